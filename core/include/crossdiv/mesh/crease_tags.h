#pragma once
/// @file
/// Sharpness tags of a polygon mesh, as OpenSubdiv takes them (Far::TopologyDescriptor's
/// creaseVertexIndexPairs/creaseWeights and cornerVertexIndices/cornerWeights) and as its
/// shape files write them in OBJ (`t crease 2/1/0 a b s`, `t corner 1/1/0 v s`, vertex
/// indices from 0). Tags name vertices, not edges, so they survive any renumbering of edges
/// and a refined mesh can carry its own (decayed) tags.

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "crossdiv/named_variant.h"

namespace crossdiv {

/// How semi-sharp creases decay from one level to the next (Sdc::Options::CreasingMethod).
enum class CreaseMethod {
    /// Every sharpness drops by 1 per level (CREASE_UNIFORM, "normal" in shape files).
    Uniform,
    /// A child edge takes 3/4 of its parent's sharpness plus 1/4 of the average of the other
    /// semi-sharp edges at its end vertex, then drops by 1 (CREASE_CHAIKIN): creases whose
    /// sharpness varies along their length blend instead of stepping.
    Chaikin,
};

/// "uniform" / "chaikin".
constexpr std::string_view to_string(CreaseMethod m) { return m == CreaseMethod::Uniform ? "uniform" : "chaikin"; }
/// The creasing method named `name`. @throws InputError listing the names.
inline CreaseMethod crease_method_from_string(std::string_view name) {
    return variant_from_string<CreaseMethod>(name, std::array{CreaseMethod::Uniform, CreaseMethod::Chaikin}, "creasing method");
}

/// Sharpness of the edge between vertices a and b (either order). 0 is smooth; 10 and above
/// is infinitely sharp (Sdc::Crease::SHARPNESS_INFINITE); in between the edge is semi-sharp
/// and stays sharp for about that many levels. Stored as float, as OpenSubdiv stores it, so
/// that the decay is bit-identical with the library's.
struct SharpEdge {
    int a, b;
    float sharpness;
    friend bool operator==(const SharpEdge&, const SharpEdge&) = default;
};

/// Sharpness of a vertex: a corner that stays put while its sharpness lasts.
struct SharpVertex {
    int v;
    float sharpness;
    friend bool operator==(const SharpVertex&, const SharpVertex&) = default;
};

/// The tags of one mesh. A later tag of the same edge or vertex replaces an earlier one
/// (as repeated calls of Far's setBaseEdgeSharpness do).
struct CreaseTags {
    std::vector<SharpEdge> edges;
    std::vector<SharpVertex> vertices;
    std::vector<int> edge_line;    ///< 1-based source line of each edge tag, or empty
    std::vector<int> vertex_line;  ///< 1-based source line of each vertex tag, or empty
    /// The method a file asks for (`t creasemethod 0/0/1 normal|chaikin`), if it does.
    std::optional<CreaseMethod> method;

    bool empty() const { return edges.empty() && vertices.empty(); }
};

}  // namespace crossdiv
