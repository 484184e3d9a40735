#pragma once
/// @file
/// Doo-Sabin masks: the weights only. The traversal is doo_sabin.cpp; the driver is
/// refinement.h.
///
/// D. Doo, M. Sabin, "Behaviour of recursive division surfaces near extraordinary points",
/// Computer-Aided Design 10(6), 1978. Every corner (face f, vertex v_0) of the coarse mesh
/// becomes a new vertex, an affine combination of the n vertices v_0 .. v_{n-1} of f taken
/// from v_0 around the face: alpha_0 = 1/4 + 5/(4n), alpha_k = (3 + 2 cos(2 pi k / n)) / (4n).
/// On a quad this is the tensor-product quadratic B-spline's (9, 3, 1, 3) / 16.

#include <array>
#include <cmath>
#include <numbers>
#include <string_view>

#include "crossdiv/named_variant.h"

namespace crossdiv {

/// What is made at the boundary of an open mesh. The corner points are the same in both.
enum class DooSabinBoundary {
    /// Each boundary edge (a, b) gets Chaikin's points 3/4 a + 1/4 b and 1/4 a + 3/4 b, which
    /// close the face of the edge (the quad with the face's two corner points) and the face
    /// of each boundary vertex (its corner points and its two nearest Chaikin points). The
    /// refined boundary is Chaikin's refinement of the old one, so it converges to the
    /// quadratic B-spline of the boundary polygon. This testbed's rule; no reference has it.
    ChaikinBoundary,
    /// Faces for interior edges and interior vertices only: the face of each boundary edge
    /// and of each boundary vertex is dropped, and the mesh shrinks inward at every level.
    /// CGAL's DooSabin_subdivision (its DQQ refinement removes the border faces).
    DropBorderFaces,
};

/// The weights of a corner point.
enum class DooSabinWeights {
    /// Doo and Sabin's, from their eigenanalysis: alpha_0 = 1/4 + 5/(4n),
    /// alpha_k = (3 + 2 cos(2 pi k / n)) / (4n). CGAL's and OpenMesh's.
    DooSabin,
    /// Catmull and Clark's (the same 1978 issue): the average of the vertex, the midpoints of
    /// its two edges in the face and the face's centroid, i.e. 1/2 + 1/(4n) on the vertex,
    /// 1/8 + 1/(4n) on its two neighbours in the face, 1/(4n) on the others. The same as Doo
    /// and Sabin's on quads, different on every other face.
    CatmullClark,
};

/// "doo-sabin", "catmull-clark".
constexpr std::string_view to_string(DooSabinWeights w) { return w == DooSabinWeights::DooSabin ? "doo-sabin" : "catmull-clark"; }

struct DooSabinOptions {
    DooSabinBoundary boundary;
    DooSabinWeights weights = DooSabinWeights::DooSabin;
    friend bool operator==(const DooSabinOptions&, const DooSabinOptions&) = default;
};

/// Weight of the k-th vertex of an n-gon, counted from the corner's own vertex (k = 0).
inline double doo_sabin_weight(int n, int k, DooSabinWeights weights = DooSabinWeights::DooSabin) {
    if (weights == DooSabinWeights::CatmullClark) {
        const double share = 1.0 / (4.0 * n);  // the centroid's quarter
        return k == 0 ? 0.5 + share : (k == 1 || k == n - 1) ? 0.125 + share : share;
    }
    if (k == 0) return 0.25 + 5.0 / (4.0 * n);
    return (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * k / n)) / (4.0 * n);
}

/// Chaikin's corner cutting on a boundary edge: the point near a is 3/4 a + 1/4 b.
inline constexpr double kChaikinNear = 0.75, kChaikinFar = 0.25;

/// "chaikin-boundary", "drop-border-faces".
constexpr std::string_view to_string(DooSabinBoundary b) {
    return b == DooSabinBoundary::ChaikinBoundary ? "chaikin-boundary" : "drop-border-faces";
}

/// The boundary rule named `name`. @throws InputError listing the names.
inline DooSabinBoundary doo_sabin_boundary_from_string(std::string_view name) {
    return variant_from_string<DooSabinBoundary>(
        name, std::array{DooSabinBoundary::ChaikinBoundary, DooSabinBoundary::DropBorderFaces}, "Doo-Sabin boundary rule");
}

}  // namespace crossdiv
