#include "crossdiv/subdiv/least_squares.h"

#include "crossdiv/error.h"
#include "normal_equations.h"

namespace crossdiv {

std::vector<Vec3> least_squares(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const std::vector<Vec3>& points,
                                const char* what) {
    if (static_cast<Eigen::Index>(points.size()) != a.rows())
        throw InputError(std::string(what) + ": " + std::to_string(points.size()) + " points for " + std::to_string(a.rows()) +
                         " rows");
    detail::check_finite(points, std::string(what) + ": point");
    const Eigen::SparseMatrix<double> at = a.transpose();
    const detail::Points p = detail::to_matrix(points);
    const Eigen::SparseMatrix<double> normal = at * a;
    return detail::to_points(detail::solve_normal_equations(
        normal, at * p, [&](const detail::Points& x) -> detail::Points { return at * (p - a * x); }, what));
}

}  // namespace crossdiv
