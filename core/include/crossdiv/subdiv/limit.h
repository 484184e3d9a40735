#pragma once
/// @file
/// Limit positions and limit normals of the vertices of a control mesh: where the vertex
/// lands after infinitely many levels, from one mask per vertex (the left eigenvectors of
/// the local subdivision matrix).
///
/// Loop, interior vertex of valence n with even weight beta(n) (either family): the left
/// eigenvector of eigenvalue 1 of the 1-ring matrix gives the limit mask
///     (1 - n chi) v + chi sum p_i,   chi = 1 / (n + 3 / (8 beta)),
/// (Loop 1987, sec. 3.3; Hoppe et al., "Piecewise smooth surface reconstruction", SIGGRAPH 94,
/// appendix); the test derives it from the eigenvectors numerically and compares. Tangents:
/// sum cos(2 pi i / n) p_i and sum sin(2 pi i / n) p_i (the subdominant left eigenvectors).
/// Catmull-Clark, interior vertex of valence n with all incident faces quads, e_i the ring
/// vertices and f_i the vertices opposite v in face i:
///     (n^2 v + 4 sum e_i + sum f_i) / (n (n + 5))        (Halstead et al. 1993, sec. 4)
/// with tangents sum [A_n cos(2 pi i/n) e_i + (cos(2 pi i/n) + cos(2 pi (i+1)/n)) f_i] (f_i between e_i and e_{i+1}),
/// A_n = 1 + cos(2 pi/n) + cos(pi/n) sqrt(2 (9 + cos(2 pi/n))), and the same with sines.
/// Boundary (both schemes, every rule whose boundary is the cubic B-spline): 2/3 v + 1/6 on each
/// boundary neighbour; a corner of EdgeAndCorner stays. The limit normal of a boundary vertex
/// is not computed here (NaN): its cross-boundary tangent mask is a further formula.

#include <Eigen/SparseCore>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {

struct LimitResult {
    std::vector<Vec3> position;
    /// Unit limit normal, oriented like the faces (counter-clockwise = outward); NaN where not
    /// computed (boundary vertices) and zero where the tangents are parallel.
    std::vector<Vec3> normal;
};

/// Loop limit positions of every vertex of `mesh` (an isolated vertex stays).
/// @throws InputError as LoopRefiner.
LimitResult loop_limit(const TriMesh& mesh, const LoopOptions& options);

/// Catmull-Clark limit positions of every vertex of `mesh`.
/// @throws InputError as catmull_clark_subdivide, and naming the vertex when an interior
///         vertex has a non-quad face around it (refine once first: every face is then a quad).
///         The midpoint-average rule has no cubic B-spline boundary: refused too.
LimitResult catmull_clark_limit(const PolyMesh& mesh, const CatmullClarkOptions& options);

/// The same limit masks as a matrix L (row v: the mask of vertex v, columns: the vertices), so
/// that L V is the limit position of every vertex; what makes the limit surface a linear
/// function of the control points, for fitting it (limit_fitting.h). Agrees with the limit
/// positions above to rounding (they sum each mask in another order). @throws as loop_limit.
Eigen::SparseMatrix<double, Eigen::RowMajor> loop_limit_matrix(const TriMesh& mesh, const LoopOptions& options);
/// @throws as catmull_clark_limit.
Eigen::SparseMatrix<double, Eigen::RowMajor> catmull_clark_limit_matrix(const PolyMesh& mesh, const CatmullClarkOptions& options);

/// Loop's limit weight chi(n) on each ring vertex (the centre gets 1 - n chi).
inline double loop_limit_ring_weight(LoopWeights weights, int n) { return 1.0 / (n + 3.0 / (8.0 * loop_beta(weights, n))); }

}  // namespace crossdiv
