#pragma once
/// @file
/// Linear least squares min |A X - P|^2 for a sparse A of full column rank and three
/// right-hand sides (points): the normal equations A^T A X = A^T P by sparse Cholesky
/// (Eigen's SimplicialLDLT), then one step of iterative refinement, which brings the residual
/// of a well-conditioned system back to rounding. Fitting (limit_fitting.h) and multiresolution
/// analysis (multiresolution.h) both solve it.

#include <Eigen/SparseCore>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// The X minimizing sum_i |A_i X - points_i|^2. `what` starts the error messages.
/// @throws InputError when `points` has not one point per row of A or one is not finite, or when
///         A has not full column rank (a zero pivot, relative to the largest, below 1e-13).
std::vector<Vec3> least_squares(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const std::vector<Vec3>& points,
                                const char* what);

}  // namespace crossdiv
