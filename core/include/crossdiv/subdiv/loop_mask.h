#pragma once
/// @file
/// Loop subdivision masks: the weights only, no traversal (as OpenSubdiv's
/// sdc/loopScheme.h). The refinement driver in loop.h walks the mesh and applies them.
///
/// C. Loop, "Smooth Subdivision Surfaces Based on Triangles", M.S. thesis, University of
/// Utah, 1987; J. Warren, "Subdivision methods for geometric design", 1995 (the simplified
/// even weights); boundary rules as in D. Zorin, P. Schroeder et al., "Subdivision for
/// Modeling and Animation", SIGGRAPH 2000 course notes, ch. 4. The two tuned families are
/// L. Barthe, L. Kobbelt, "Subdivision scheme tuning around extraordinary vertices", CAGD
/// 21(6), 2004, with the weights and the rule for applying them of the VCG library
/// (vcg/complex/algorithms/refine_loop.h, RegularLoopWeight and ContinuityLoopWeight), which
/// MeshLab's Loop filter offers as "Enhance regularity" and "Enhance continuity".

#include <array>
#include <cmath>
#include <string_view>

#include "crossdiv/named_variant.h"
#include "crossdiv/mesh/crease_tags.h"
#include "crossdiv/subdiv/nonmanifold_rule.h"

namespace crossdiv {

/// The weight family of the even (old) vertex rule at an interior vertex of valence n.
enum class LoopWeights {
    /// Loop 1987: beta = (1/n) (5/8 - (3/8 + cos(2 pi / n) / 4)^2). OpenSubdiv, OpenMesh
    /// and CGAL use this family.
    Loop,
    /// Warren: beta = 3 / (8 n) for n > 3 and 3/16 for n = 3 (the seed assignment's rule).
    Warren,
    /// Barthe-Kobbelt weights tuned for the regularity of the limit surface at valences
    /// 3..12 (Loop's outside that range); the edge mask changes too, next to an
    /// extraordinary vertex (tuned_edge_mask). MeshLab's "Enhance regularity".
    Regularity,
    /// Barthe-Kobbelt weights tuned for the continuity of the limit surface, as Regularity.
    /// MeshLab's "Enhance continuity".
    Continuity,
};

/// Whether the family tunes the edge mask next to extraordinary vertices (the
/// Barthe-Kobbelt families); Loop's and Warren's edge mask is always 3/8, 3/8, 1/8, 1/8.
constexpr bool has_tuned_edges(LoopWeights w) { return w == LoopWeights::Regularity || w == LoopWeights::Continuity; }

/// How the boundary is refined.
enum class LoopBoundary {
    /// Boundary edges are sharp: edge point 1/2, 1/2; boundary vertex 3/4, 1/8, 1/8 (its two
    /// boundary neighbours). OpenSubdiv's VTX_BOUNDARY_EDGE_ONLY; OpenMesh's and CGAL's rule.
    EdgeOnly,
    /// As EdgeOnly, and a boundary vertex with exactly one incident face is a corner that
    /// stays fixed. OpenSubdiv's VTX_BOUNDARY_EDGE_AND_CORNER.
    EdgeAndCorner,
};

/// Both rules named; there is no default for them, callers say which variant they mean. The
/// crease decay defaults to OpenSubdiv's (uniform); it only acts on a crease-tagged mesh.
struct LoopOptions {
    LoopWeights weights;
    LoopBoundary boundary;
    /// How semi-sharp crease tags decay (crease_mask.h); without tags it changes nothing.
    CreaseMethod creasing = CreaseMethod::Uniform;
    /// A mesh that is not a manifold: OpenSubdiv's rules (nonmanifold.h) or refused.
    NonManifoldRule nonmanifold = NonManifoldRule::OpenSubdiv;
    /// Whose semi-sharp crease rules (crease_tags.h): Far's, or Hbr's where they differ.
    CreaseRules crease_rules = CreaseRules::OpenSubdiv;
    friend bool operator==(const LoopOptions&, const LoopOptions&) = default;
};

/// Weights of a vertex-point mask: `self` on the old vertex, `neighbor` on each neighbour
/// that takes part (all n one-ring neighbours inside, the two boundary neighbours on a
/// boundary, none at a corner).
struct VertexMask {
    double self;
    double neighbor;
};

/// Weights of an edge-point mask: `end` on each endpoint, `opposite` on each of the two
/// vertices opposite the edge (0 on a boundary edge, which has one).
struct EdgeMask {
    double end;
    double opposite;
};

/// cos(2 pi / n) with the values that are exact in closed form returned exactly
/// (n = 1, 2, 3, 4, 6), so that the common regular valences get bit-exact weights
/// (std::cos(pi / 3) is 0.5000000000000001).
inline double cos_two_pi_over(int n) {
    switch (n) {
        case 1: return 1.0;
        case 2: return -1.0;
        case 3: return -0.5;
        case 4: return 0.0;
        case 6: return 0.5;
        default: return std::cos(2.0 * M_PI / n);
    }
}

/// The Barthe-Kobbelt tables for valences 3..12 (index n - 3), as the VCG library holds them
/// (five decimals): the weight of the extraordinary vertex on itself (1 - n beta), and the
/// edge mask of an edge from it to a regular vertex: `irregular` on the extraordinary end,
/// `opposite` on each vertex opposite the edge; the regular end takes the rest,
/// 1 - irregular - 2 opposite. At n = 6 every table gives Loop's weights.
struct TunedLoopTable {
    std::array<double, 10> self, irregular, opposite;
};
inline const TunedLoopTable& tuned_loop_table(LoopWeights weights) {
    static const TunedLoopTable regularity{
        {.32517, .49954, .59549, .625, .63873, .64643, .65127, .67358, .68678, .69908},
        {.15658, .25029, .34547, .375, .38877, .39644, .40132, .42198, .43423, .44579},
        {.14427, .12524, .11182, .125, .14771, .1768, .21092, .20354, .20505, .19828}};
    static const TunedLoopTable continuity{
        {.32517, .50033, .59464, .625, .63903, .67821, .6866, .69248, .69678, .70014},
        {.15658, .26721, .33539, .375, .36909, .25579, .2521, .24926, .24706, .2452},
        {.14427, .12495, .11252, .125, .14673, .16074, .18939, .2222, .25894, .29934}};
    return weights == LoopWeights::Continuity ? continuity : regularity;
}
/// Whether the tuned tables hold valence n.
constexpr bool in_tuned_table(int n) { return n >= 3 && n <= 12; }

/// beta(n), the weight of each one-ring neighbour of an interior vertex of valence n >= 3.
inline double loop_beta(LoopWeights weights, int n) {
    if (weights == LoopWeights::Warren) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
    if (has_tuned_edges(weights) && in_tuned_table(n)) return (1.0 - tuned_loop_table(weights).self[n - 3]) / n;
    const double t = 0.375 + 0.25 * cos_two_pi_over(n);
    return (0.625 - t * t) / n;
}

/// Even mask of an interior vertex of valence n: 1 - n beta on itself, beta on each neighbour.
inline VertexMask interior_vertex_mask(LoopWeights weights, int valence) {
    const double beta = loop_beta(weights, valence);
    return {1.0 - valence * beta, beta};
}

/// Even mask of a boundary vertex with `incident_faces` faces around it.
inline VertexMask boundary_vertex_mask(LoopBoundary boundary, int incident_faces) {
    if (boundary == LoopBoundary::EdgeAndCorner && incident_faces == 1) return {1.0, 0.0};
    return {0.75, 0.125};
}

/// Odd mask of an interior edge (3/8, 3/8, 1/8, 1/8; the seed's p11 example).
inline constexpr EdgeMask interior_edge_mask() { return {0.375, 0.125}; }

/// The valence the tuned edge mask reads at an edge's endpoint with `faces` faces around it:
/// the face count inside; on the boundary VCG's max(2 (faces - 1), 3), meant as "twice the
/// half-disc", which counts faces where the half-disc has faces + 1 edges (so a regular
/// boundary vertex of 3 faces reads 4, not 6). Reproduced as VCG computes it.
constexpr int tuned_edge_valence(int faces, bool boundary) {
    return boundary ? (2 * (faces - 1) > 3 ? 2 * (faces - 1) : 3) : faces;
}

/// An edge mask whose two ends may weigh differently.
struct TunedEdgeMask {
    double end_a, end_b, opposite;
};

/// Odd mask of an interior edge (a, b) whose endpoints read valences `va`, `vb`
/// (tuned_edge_valence). For Loop's and Warren's families, and for the tuned ones unless
/// exactly one end reads 6 or both do, interior_edge_mask(). When one end reads 6 and the
/// other n (in the table: 3..12), the tuned row of n: `irregular` on the n end, the rest on
/// the regular end. As VCG, the row of n = 6 when both ends read 6 (Loop's weights).
inline TunedEdgeMask tuned_edge_mask(LoopWeights weights, int va, int vb) {
    const EdgeMask plain = interior_edge_mask();
    if (!has_tuned_edges(weights) || (va != 6 && vb != 6)) return {plain.end, plain.end, plain.opposite};
    const int n = va == 6 ? vb : va;
    if (!in_tuned_table(n)) return {plain.end, plain.end, plain.opposite};
    const TunedLoopTable& t = tuned_loop_table(weights);
    const double irregular = t.irregular[n - 3], opposite = t.opposite[n - 3];
    const double regular = 1.0 - irregular - 2.0 * opposite;
    return {va == 6 ? regular : irregular, vb == 6 ? regular : irregular, opposite};
}
/// Odd mask of a boundary edge: its midpoint.
inline constexpr EdgeMask boundary_edge_mask() { return {0.5, 0.0}; }

/// "loop", "warren", "regularity", "continuity".
constexpr std::string_view to_string(LoopWeights w) {
    switch (w) {
        case LoopWeights::Loop: return "loop";
        case LoopWeights::Warren: return "warren";
        case LoopWeights::Regularity: return "regularity";
        case LoopWeights::Continuity: return "continuity";
    }
    return "unknown";
}
/// Every weight family, in the order of the enum.
inline constexpr std::array<LoopWeights, 4> kAllLoopWeights{LoopWeights::Loop, LoopWeights::Warren, LoopWeights::Regularity,
                                                           LoopWeights::Continuity};
/// "edge-only" / "edge-and-corner".
constexpr std::string_view to_string(LoopBoundary b) {
    return b == LoopBoundary::EdgeOnly ? "edge-only" : "edge-and-corner";
}

/// The weight family named `name` (to_string's names). @throws InputError listing the names.
inline LoopWeights loop_weights_from_string(std::string_view name) {
    return variant_from_string<LoopWeights>(name, kAllLoopWeights, "Loop weight family");
}
/// The boundary rule named `name` ("edge-only", "edge-and-corner"). @throws InputError.
inline LoopBoundary loop_boundary_from_string(std::string_view name) {
    return variant_from_string<LoopBoundary>(name, std::array{LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner},
                                             "Loop boundary rule");
}

}  // namespace crossdiv
