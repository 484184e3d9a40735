#pragma once
/// @file
/// Loop subdivision masks: the weights only, no traversal (as OpenSubdiv's
/// sdc/loopScheme.h). The refinement driver in loop.h walks the mesh and applies them.
///
/// C. Loop, "Smooth Subdivision Surfaces Based on Triangles", M.S. thesis, University of
/// Utah, 1987; J. Warren, "Subdivision methods for geometric design", 1995 (the simplified
/// even weights); boundary rules as in D. Zorin, P. Schroeder et al., "Subdivision for
/// Modeling and Animation", SIGGRAPH 2000 course notes, ch. 4.

#include <array>
#include <cmath>
#include <string_view>

#include "crossdiv/named_variant.h"
#include "crossdiv/mesh/crease_tags.h"

namespace crossdiv {

/// The weight family of the even (old) vertex rule at an interior vertex of valence n.
enum class LoopWeights {
    /// Loop 1987: beta = (1/n) (5/8 - (3/8 + cos(2 pi / n) / 4)^2). OpenSubdiv, OpenMesh
    /// and CGAL use this family.
    Loop,
    /// Warren: beta = 3 / (8 n) for n > 3 and 3/16 for n = 3 (the seed assignment's rule).
    Warren,
};

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

/// beta(n), the weight of each one-ring neighbour of an interior vertex of valence n >= 3.
inline double loop_beta(LoopWeights weights, int n) {
    if (weights == LoopWeights::Warren) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
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
/// Odd mask of a boundary edge: its midpoint.
inline constexpr EdgeMask boundary_edge_mask() { return {0.5, 0.0}; }

/// "loop" / "warren".
constexpr std::string_view to_string(LoopWeights w) { return w == LoopWeights::Loop ? "loop" : "warren"; }
/// "edge-only" / "edge-and-corner".
constexpr std::string_view to_string(LoopBoundary b) {
    return b == LoopBoundary::EdgeOnly ? "edge-only" : "edge-and-corner";
}

/// The weight family named `name` ("loop", "warren"). @throws InputError listing the names.
inline LoopWeights loop_weights_from_string(std::string_view name) {
    return variant_from_string<LoopWeights>(name, std::array{LoopWeights::Loop, LoopWeights::Warren}, "Loop weight family");
}
/// The boundary rule named `name` ("edge-only", "edge-and-corner"). @throws InputError.
inline LoopBoundary loop_boundary_from_string(std::string_view name) {
    return variant_from_string<LoopBoundary>(name, std::array{LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner},
                                             "Loop boundary rule");
}

}  // namespace crossdiv
