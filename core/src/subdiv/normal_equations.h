#pragma once
// The normal equations of sparse linear least squares, shared by least_squares.cpp and
// limit_fitting.cpp (internal to core's sources).
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::detail {

using Points = Eigen::Matrix<double, Eigen::Dynamic, 3>;

inline void check_finite(const std::vector<Vec3>& points, const std::string& what) {
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite()) throw InputError(what + " " + std::to_string(i) + " is not finite");
}

inline Points to_matrix(const std::vector<Vec3>& points) {
    Points m(static_cast<Eigen::Index>(points.size()), 3);
    for (size_t i = 0; i < points.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
    return m;
}

inline std::vector<Vec3> to_points(const Points& m) {
    std::vector<Vec3> out(static_cast<size_t>(m.rows()));
    for (Eigen::Index i = 0; i < m.rows(); ++i) out[static_cast<size_t>(i)] = m.row(i).transpose();
    return out;
}

/// Solves the normal equations M X = rhs (M = Q^T Q for the system's matrix Q) by sparse
/// Cholesky, then one step of iterative refinement against `residual`, which returns
/// rhs - M X evaluated without forming M's rounding twice.
/// `what` starts the error message ("fitting", "multiresolution analysis").
template <class Residual>
Points solve_normal_equations(const Eigen::SparseMatrix<double>& normal, const Points& rhs, Residual residual,
                              const std::string& what) {
    const std::string singular = what + ": the least-squares system is singular (the samples do not determine every "
                                        "control point: the stencils are linearly dependent, or a point reaches no sample)";
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (ldlt.info() != Eigen::Success) throw InputError(singular);
    const Eigen::VectorXd d = ldlt.vectorD();
    // LDL^T of a positive semi-definite matrix succeeds with a zero (or, by rounding, a tiny
    // negative) pivot; the matrix is then numerically singular and the solution meaningless.
    const double largest = d.cwiseAbs().maxCoeff();
    if (!(d.minCoeff() > largest * 1e-13)) throw InputError(singular);
    Points x = ldlt.solve(rhs);
    x += ldlt.solve(residual(x));
    return x;
}

}  // namespace crossdiv::detail
