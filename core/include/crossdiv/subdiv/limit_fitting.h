#pragma once
/// @file
/// Fitting a subdivision surface to a target mesh: control positions X of a coarse mesh whose
/// limit surface approximates a dense target (Hoppe et al., "Piecewise smooth surface
/// reconstruction", SIGGRAPH 1994, sec. 4; Litke, Levin and Schroeder, "Fitting subdivision
/// surfaces", IEEE Visualization 2001).
///
/// The limit surface is sampled at the vertices of the control mesh's L-th level: their limit
/// positions are A X with A = Lim_L S_L ... S_1 (the levels' subdivision matrices, then the
/// limit masks of the last level, limit.h), so every sample, and every point of the triangles
/// between samples, is a fixed linear combination of the control points.
///
/// fit_limit_points() solves the linear least-squares problem min |A X - P|^2 for given
/// samples P, one per row; a P that is itself A X* gives back X* (exact recovery).
/// fit_limit_surface() alternates, as Hoppe et al. do for the vertex positions, between
///  - correspondences at fixed X: each sample's closest point on the target, and each target
///    vertex's closest point on the sampled surface (a triangle of rows and its barycentric
///    coordinates), and
///  - the least-squares X for fixed correspondences of the two-sided energy
///      E(X) = sum_i |A_i X - c_i|^2 + sum_j |t_j - sum_k b_jk A_(r_jk) X|^2 ,
/// each step minimizing E over one of the two, so that the distance energy D(X_k) -- E at the
/// closest points of X_k -- never increases (asserted by the tests). The normal equations are
/// solved by a sparse Cholesky factorization (Eigen's SimplicialLDLT) followed by one step of
/// iterative refinement, which brings the residual of a well-conditioned system to rounding.

#include <Eigen/SparseCore>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {

/// The limit surface of a control mesh as a linear function of its control points.
struct LimitSampling {
    /// A: one row per vertex of level `levels`, one column per control vertex.
    Eigen::SparseMatrix<double, Eigen::RowMajor> stencils;
    /// The faces of level `levels` over the rows; a quad is cut along the diagonal from its
    /// first corner.
    std::vector<Triangle> triangles;
    int levels = 0;

    int num_control() const { return static_cast<int>(stencils.cols()); }
    int num_samples() const { return static_cast<int>(stencils.rows()); }
    /// A X.
    std::vector<Vec3> evaluate(const std::vector<Vec3>& control) const;
    /// The sampled surface A X as a triangle mesh.
    TriMesh surface(const std::vector<Vec3>& control) const;
};

/// @throws InputError as loop_subdivide and loop_limit_matrix, or for a negative level count.
LimitSampling loop_limit_sampling(const TriMesh& control, const LoopOptions& options, int levels);
/// @throws InputError as catmull_clark_subdivide and catmull_clark_limit_matrix (a level count
///         of 0 needs quads around every interior vertex), for a negative level count, or for
///         crease tags (fitting takes smooth meshes).
LimitSampling catmull_clark_limit_sampling(const PolyMesh& control, const CatmullClarkOptions& options, int levels);

/// The control points minimizing sum_i |A_i X - points_i|^2.
/// @throws InputError when `points` has not one point per sample or a point is not finite, or
///         when A has not full column rank (the factorization finds a zero pivot).
std::vector<Vec3> fit_limit_points(const LimitSampling& sampling, const std::vector<Vec3>& points);

struct FittingOptions {
    int iterations = 8;  ///< correspondence-and-solve rounds after the start
};

/// One state of the iteration: control points and their distance to the target.
struct FittingStep {
    std::vector<Vec3> control;
    /// D(X): the two-sided energy at the closest points, the sum of the squared distances below.
    double energy = 0;
    double rms_sample_to_target = 0, max_sample_to_target = 0;    ///< samples A X to the target
    double rms_target_to_surface = 0, max_target_to_surface = 0;  ///< target vertices to the sampled surface
};

struct FittingResult {
    std::vector<FittingStep> steps;  ///< steps[0]: the start; then one per iteration
};

/// Fits the limit surface of `sampling`'s control mesh, from `start`, to `target`.
/// @throws InputError when `start` has not num_control() points, a position is not finite,
///         the target has no triangles or names a vertex it lacks, or the system is singular.
FittingResult fit_limit_surface(const LimitSampling& sampling, const std::vector<Vec3>& start, const TriMesh& target,
                                const FittingOptions& options);

}  // namespace crossdiv
