#include "crossdiv/adapters/eigen_splines.h"

#include <unsupported/Eigen/Splines>

#include "crossdiv/error.h"

namespace crossdiv::adapters::eigen_splines {

namespace {

using Spline3 = Eigen::Spline<double, 3>;  // dynamic degree, read from the knots

SplineSamples evaluate(std::span<const Vec3> control, const Eigen::ArrayXd& knots, std::span<const double> params,
                       double shift) {
    Spline3::ControlPointVectorType ctrls(3, static_cast<Eigen::Index>(control.size()));
    for (size_t i = 0; i < control.size(); ++i) ctrls.col(static_cast<Eigen::Index>(i)) = control[i];
    const Spline3 spline(knots.transpose(), ctrls);
    SplineSamples out;
    out.position.reserve(params.size());
    out.d1.reserve(params.size());
    out.d2.reserve(params.size());
    // derivatives() has no orders above the degree; those derivatives are zero.
    const Eigen::Index order = std::min<Eigen::Index>(2, spline.degree());
    for (double u : params) {
        const auto der = spline.derivatives(u + shift, order);
        out.position.push_back(der.col(0));
        out.d1.push_back(order >= 1 ? Vec3(der.col(1)) : Vec3::Zero());
        out.d2.push_back(order >= 2 ? Vec3(der.col(2)) : Vec3::Zero());
    }
    return out;
}

}  // namespace

SplineSamples uniform_cubic_bspline(std::span<const Vec3> control, std::span<const double> u) {
    const Eigen::Index n = static_cast<Eigen::Index>(control.size());
    if (n < 4) throw InputError("a cubic B-spline needs at least 4 control points, got " + std::to_string(n));
    const Eigen::ArrayXd knots = Eigen::ArrayXd::LinSpaced(n + 4, 0.0, static_cast<double>(n + 3));
    return evaluate(control, knots, u, 3.0);
}

SplineSamples clamped_bezier(std::span<const Vec3> control, std::span<const double> t) {
    if (control.empty()) throw InputError("a Bezier curve needs at least 1 control point, got 0");
    const Eigen::Index d = static_cast<Eigen::Index>(control.size()) - 1;
    Eigen::ArrayXd knots(2 * d + 2);
    knots.head(d + 1).setZero();
    knots.tail(d + 1).setOnes();
    return evaluate(control, knots, t, 0.0);
}

std::string version() {
    return "Eigen " + std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
           std::to_string(EIGEN_MINOR_VERSION);
}

}  // namespace crossdiv::adapters::eigen_splines
