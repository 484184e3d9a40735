#pragma once
/// @file
/// Butterfly masks: the weights only. The traversal is butterfly.cpp; the driver is
/// refinement.h. Both Butterflies are interpolating: old vertices keep their positions and
/// each edge gets one new point (the 1-to-4 split of Loop).
///
/// N. Dyn, D. Levin, J. Gregory, "A butterfly subdivision scheme for surface interpolation
/// with tension control", ACM TOG 9(2), 1990: the eight-point stencil with tension w = 1/16.
/// D. Zorin, P. Schroeder, W. Sweldens, "Interpolating subdivision for meshes with arbitrary
/// topology", SIGGRAPH 1996: the modified scheme, a K-point stencil around an extraordinary
/// endpoint, C1 at every valence.

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>
#include <vector>

#include "crossdiv/named_variant.h"

namespace crossdiv {

enum class ButterflyVariant {
    /// Dyn, Levin, Gregory: the eight-point stencil at every interior edge, whatever the
    /// valences (not C1 at valence 3 and above 7).
    Classic,
    /// Zorin, Schroeder, Sweldens, with the choices of OpenMesh's ModifiedButterflyT: the
    /// eight-point stencil when both endpoints have valence 6, when one is on the boundary and
    /// the other has valence 6, or when both are on the boundary; otherwise the K-point
    /// stencil of each endpoint that is interior and of valence K != 6, averaged when there
    /// are two. Valence counts edges (a boundary vertex's is its face count + 1).
    Modified,
};

/// Where the eight-point stencil of an interior edge takes a wing point c that is missing
/// because the wing edge (x, b) of one of its triangles (x, b, o) is on the boundary.
enum class ButterflyWings {
    /// The reflection of o across the wing edge, x + b - o: a wing as if the mesh went on
    /// flat beyond the boundary. This testbed's rule (OpenMesh's and CGAL's modified
    /// Butterfly agree with it).
    Reflected,
    /// o itself, the triangle's own third vertex: what VCG's MidPointButterfly (MeshLab's
    /// "Butterfly Subdivision") reads when its walk across the wing edge stays in the face.
    OppositeVertex,
    /// The third vertex of the edge's other triangle: VTK's vtkButterflySubdivisionFilter
    /// (GenerateButterflyStencil). Under the modified scheme this rule takes VTK's other
    /// boundary choices too, which differ from OpenMesh's only next to a boundary: valence
    /// counts faces (a boundary vertex of 6 faces is regular), and an endpoint on the
    /// boundary stands for the eight-point stencil where OpenMesh would leave it out (its
    /// K-point walk meets the boundary: GenerateLoopStencil), averaged with the other
    /// endpoint's stencil when neither is regular.
    OtherFaceVertex,
};
inline constexpr std::array<ButterflyWings, 3> kAllButterflyWings{ButterflyWings::Reflected, ButterflyWings::OppositeVertex,
                                                                   ButterflyWings::OtherFaceVertex};

/// "reflected-wings", "opposite-vertex-wings", "other-face-wings".
constexpr std::string_view to_string(ButterflyWings w) {
    return w == ButterflyWings::Reflected ? "reflected-wings" : w == ButterflyWings::OppositeVertex ? "opposite-vertex-wings" : "other-face-wings";
}

/// The wing rule named `name`. @throws InputError listing the names.
inline ButterflyWings butterfly_wings_from_string(std::string_view name) {
    return variant_from_string<ButterflyWings>(name, kAllButterflyWings, "Butterfly wing rule");
}

/// The eight-point stencil of an interior edge (a0, a1) with opposite vertices b0, b1 and the
/// four vertices c beyond the wings: a 1/2 each, b 2w, c -w, with the tension w = 1/16
/// (the value for which the scheme reproduces cubics on a regular mesh).
inline constexpr double kButterflyTension = 1.0 / 16.0;
inline constexpr double kButterflyA = 0.5, kButterflyB = 2.0 * kButterflyTension, kButterflyC = -kButterflyTension;

/// Boundary edges (and a missing wing point c across the boundary is reflected: the c across
/// edge (x, b) opposite y becomes x + b - y). The four-point rule along the boundary
/// polygon ... p, a0, a1, q ...: 9/16 on a0 and a1, -1/16 on p and q.
inline constexpr double kFourPointInner = 9.0 / 16.0, kFourPointOuter = -1.0 / 16.0;

/// Zorin's K-point stencil of an extraordinary vertex of valence K: weight s_j on its
/// j-th neighbour counted from the edge's other endpoint (j = 0), and 3/4 on itself.
/// K = 3: 5/12, -1/12, -1/12; K = 4: 3/8, 0, -1/8, 0; K >= 5:
/// s_j = (1/4 + cos(2 pi j / K) + 1/2 cos(4 pi j / K)) / K. Returns K + 1 weights, the last
/// on the vertex itself (1 minus the others, as OpenMesh computes it).
inline std::vector<double> modified_butterfly_stencil(int valence) {
    const int K = valence;
    std::vector<double> s(static_cast<size_t>(K) + 1, 0.0);
    if (K == 3) {
        s = {5.0 / 12, -1.0 / 12, -1.0 / 12, 0.75};
    } else if (K == 4) {
        s = {3.0 / 8, 0.0, -1.0 / 8, 0.0, 0.75};
    } else {
        double sum = 0;
        for (int j = 0; j < K; ++j) {
            const double t = 2.0 * std::numbers::pi * j / K;
            s[j] = (0.25 + std::cos(t) + 0.5 * std::cos(2.0 * t)) / K;
            sum += s[j];
        }
        s[K] = 1.0 - sum;
    }
    return s;
}

/// "butterfly", "modified-butterfly".
constexpr std::string_view to_string(ButterflyVariant v) {
    return v == ButterflyVariant::Classic ? "butterfly" : "modified-butterfly";
}

/// The variant named `name`. @throws InputError listing the names.
inline ButterflyVariant butterfly_variant_from_string(std::string_view name) {
    return variant_from_string<ButterflyVariant>(name, std::array{ButterflyVariant::Classic, ButterflyVariant::Modified},
                                                 "Butterfly variant");
}

}  // namespace crossdiv
