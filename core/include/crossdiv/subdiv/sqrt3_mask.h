#pragma once
/// @file
/// sqrt3 masks: the weights only. The traversal is sqrt3.cpp; the driver is refinement.h.
///
/// L. Kobbelt, "sqrt(3)-Subdivision", SIGGRAPH 2000. Every step inserts the centroid of each
/// triangle and flips the old edges, which rotates the lattice by 30 degrees; two steps make
/// a 1-to-9 refinement. The boundary polygon is refined by the univariate ternary rule, and
/// only on every second step, so that two steps trisect each boundary edge once.

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

#include "crossdiv/named_variant.h"

namespace crossdiv {

/// How a multi-level run counts the steps that refine the boundary (odd generations).
enum class Sqrt3Parity {
    /// Generations counted from the input: step 0 keeps the boundary, step 1 trisects it,
    /// step 2 keeps it, ... (Kobbelt's scheme; OpenMesh's Sqrt3T and CGAL's
    /// Sqrt3_subdivision when all levels are asked of one call).
    CountFromInput,
    /// Every level is generation 0, so the boundary is never refined: what OpenMesh and
    /// CGAL do when called once per level, since both count generations within a call.
    RestartEachLevel,
};

struct Sqrt3Options {
    Sqrt3Parity parity;
    friend bool operator==(const Sqrt3Options&, const Sqrt3Options&) = default;
};

/// Interior vertex: (1 - alpha) v + (alpha / n) sum of its n neighbours, with Kobbelt's
/// alpha_n = (4 - 2 cos(2 pi / n)) / 9, chosen so that the two-step scheme is C1 at
/// valence n (the eigenvalue analysis of the paper, section 3).
struct Sqrt3VertexMask {
    double self, ring;
};

inline Sqrt3VertexMask sqrt3_interior_vertex_mask(int valence) {
    const double n = valence;
    const double alpha = (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / n)) / 9.0;
    return {1.0 - alpha, alpha / n};
}

/// The new face point: the centroid.
inline constexpr double kSqrt3FacePoint = 1.0 / 3.0;

/// Boundary, on a boundary step, along the boundary polygon ... p_prev, p, q, q_next ...:
/// the old vertex p becomes (4 p_prev + 19 p + 4 q) / 27, and edge (p, q) gets the two
/// points (p_prev + 16 p + 10 q) / 27 and (10 p + 16 q + q_next) / 27 (Kobbelt, section 4).
inline constexpr double kSqrt3BoundaryVertexSelf = 19.0 / 27.0, kSqrt3BoundaryVertexNeighbor = 4.0 / 27.0;
inline constexpr double kSqrt3BoundaryEdgeFar = 1.0 / 27.0, kSqrt3BoundaryEdgeNear = 16.0 / 27.0,
                        kSqrt3BoundaryEdgeOther = 10.0 / 27.0;

/// "count-from-input", "restart-each-level".
constexpr std::string_view to_string(Sqrt3Parity p) {
    return p == Sqrt3Parity::CountFromInput ? "count-from-input" : "restart-each-level";
}

/// The parity named `name`. @throws InputError listing the names.
inline Sqrt3Parity sqrt3_parity_from_string(std::string_view name) {
    return variant_from_string<Sqrt3Parity>(name, std::array{Sqrt3Parity::CountFromInput, Sqrt3Parity::RestartEachLevel},
                                            "sqrt3 boundary parity");
}

}  // namespace crossdiv
