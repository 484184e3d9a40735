#pragma once
/// @file
/// The shape-file tags of a polygon mesh, as OpenSubdiv takes them: sharpness
/// (Far::TopologyDescriptor's creaseVertexIndexPairs/creaseWeights and
/// cornerVertexIndices/cornerWeights), holes (holeIndices), and the scheme options a shape
/// file may state (creasemethod, interpolateboundary, smoothtriangles). In OBJ they are
/// OpenSubdiv's regression-suite lines `t crease 2/1/0 a b s`, `t corner 1/1/0 v s`,
/// `t hole n/0/0 f...` (vertex and face indices from 0). Sharpness tags name vertices, not
/// edges, so they survive any renumbering of edges and a refined mesh can carry its own
/// (decayed) tags.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "crossdiv/mesh/face_varying_rule.h"
#include "crossdiv/mesh/hierarchical_edit.h"
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

/// Whose rules for semi-sharp creases: the two implementations OpenSubdiv ships differ in three.
enum class CreaseRules {
    /// Far (Sdc::Crease): a vertex whose features decay takes its next rule from the decayed
    /// sharpness (1 becomes 0, smooth) and weighs the parent rule by the average of every
    /// sharpness that decays to zero, 1 included (transition_weight, subdiv/crease_mask.h);
    /// Chaikin's decay averages the other semi-sharp edges at the end vertex, and a lone
    /// edge drops by 1 (child_edge_sharpness); an edge point is the crease's midpoint when
    /// both halves stay sharp in the next level.
    OpenSubdiv,
    /// Hbr (HbrVertex::GetMask, GetFractionalMask, HbrSubdivision::SubdivideCreaseWeight): a
    /// feature of sharpness at least 1 is still sharp in the next rule (IsSharp(false) is
    /// `sharpness >= 1`), and the parent rule is weighed by the average of the sharpnesses
    /// strictly between 0 and 1 -- a corner of 1 with four edges of 0.5 stays a corner, where
    /// Far keeps 3/5 of it; Chaikin's decay averages every other sharp edge at the end vertex,
    /// infinitely sharp ones included, and takes 3/4 of a lone edge's sharpness before the
    /// drop by 1 (hbr_child_edge_sharpness); an edge point is the midpoint when the edge's
    /// sharpness is at least 1, else blended by it, whatever Chaikin's decay gives its halves.
    /// Face-varying data is then refined by Hbr's face-varying rules too
    /// (FaceVaryingOptions::rules).
    Hbr,
};

/// "opensubdiv" / "hbr".
constexpr std::string_view to_string(CreaseRules t) { return t == CreaseRules::OpenSubdiv ? "opensubdiv" : "hbr"; }

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

/// The boundary rule a shape file asks for (`t interpolateboundary 1/0/0 k`, the integer of
/// OpenSubdiv's regression reader, far_utils.h GetSdcOptions).
enum class BoundaryTag {
    /// k = 0, Sdc VTX_BOUNDARY_NONE: Far sharpens boundary edges as always (positions as
    /// EdgeOnly) and makes every face at a boundary vertex a hole
    /// (TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness), so no surface is
    /// emitted over the boundary faces.
    None,
    EdgeAndCorner,  ///< k = 1, VTX_BOUNDARY_EDGE_AND_CORNER
    EdgeOnly,       ///< k = 2, VTX_BOUNDARY_EDGE_ONLY
};

/// "none" / "edge-and-corner" / "edge-only".
constexpr std::string_view to_string(BoundaryTag b) {
    return b == BoundaryTag::None ? "none" : b == BoundaryTag::EdgeAndCorner ? "edge-and-corner" : "edge-only";
}

/// The tags of one mesh. A later tag of the same edge or vertex replaces an earlier one
/// (as repeated calls of Far's setBaseEdgeSharpness do).
struct CreaseTags {
    std::vector<SharpEdge> edges;
    std::vector<SharpVertex> vertices;
    std::vector<int> edge_line;    ///< 1-based source line of each edge tag, or empty
    std::vector<int> vertex_line;  ///< 1-based source line of each vertex tag, or empty
    /// Faces that are holes (Far's setBaseFaceHole): refined around like any face, their
    /// children are holes too, and they are not emitted (without_hole_faces). Sorted, each once.
    std::vector<int> holes;
    /// The method a file asks for (`t creasemethod 0/0/1 normal|chaikin`), if it does.
    std::optional<CreaseMethod> method;
    /// The boundary rule a file asks for (`t interpolateboundary`), if it does.
    std::optional<BoundaryTag> boundary;
    /// `t smoothtriangles 0/0/1 smooth|catmark`: Catmull-Clark's edge points next to
    /// triangles use OpenSubdiv's TRI_SUB_SMOOTH weights (true) or the plain ones.
    std::optional<bool> smooth_triangles;
    /// The face-varying rule a file asks for (`t facevaryinginterpolateboundary 1/0/0 k`).
    std::optional<FaceVaryingRule> face_varying;
    /// Hierarchical edits (`t vertexedit`, `t edgeedit`, `t faceedit`), in file order: changes
    /// to refined levels, which only a refinement that applies them may take (core's
    /// Catmull-Clark, Hbr); every other refinement refuses a mesh that has them.
    std::vector<HierarchicalEdit> edits;

    /// No sharpness, no holes and no hierarchical edits: nothing that needs the rules of a
    /// tagged mesh. (The options above change a rule, which the commands resolve, not the
    /// mesh's refinement.)
    bool empty() const { return edges.empty() && vertices.empty() && holes.empty() && edits.empty(); }
    /// "2 crease and 1 corner tag(s)", with holes "2 crease, 1 corner and 3 hole tag(s)", and
    /// with edits "..., and 4 hierarchical edit(s)".
    std::string describe() const {
        const std::string sharp = std::to_string(edges.size()) + " crease";
        const std::string corner = std::to_string(vertices.size()) + " corner";
        const std::string tags = holes.empty() ? sharp + " and " + corner + " tag(s)"
                                               : sharp + ", " + corner + " and " + std::to_string(holes.size()) + " hole tag(s)";
        return edits.empty() ? tags : tags + ", and " + std::to_string(edits.size()) + " hierarchical edit(s)";
    }
};

}  // namespace crossdiv
