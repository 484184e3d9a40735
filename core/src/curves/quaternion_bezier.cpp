#include "crossdiv/curves/quaternion_bezier.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

namespace {

/// Below this angle sin(s theta) / sin(theta) equals s to double precision (the relative error
/// of that approximation is about theta^2 / 6 < 1e-16), so the blend is linear.
constexpr double kLinearAngle = 1e-8;

/// The largest degree evaluated in a stack buffer; higher degrees take a heap copy.
constexpr size_t kStackControl = 16;

/// b's coefficients with the sign nearer to a (the shorter arc), and the angle between them on
/// the unit sphere of R^4, 2 atan2(|a - b|, |a + b|).
struct ShorterArc {
    Eigen::Vector4d b;
    double theta;
};
ShorterArc shorter_arc(const Eigen::Vector4d& qa, const Quat& b) {
    Eigen::Vector4d qb = b.coeffs();
    if (qa.dot(qb) < 0) qb = -qb;
    return {qb, 2.0 * std::atan2((qa - qb).norm(), (qa + qb).norm())};
}

/// De Casteljau with slerp in place on `work`; returns the point.
Quat reduce(std::span<Quat> work, double t) {
    for (size_t n = work.size(); n > 1; --n)
        for (size_t i = 0; i + 1 < n; ++i) work[i] = slerp(work[i], work[i + 1], t);
    return work[0];
}

}  // namespace

Quat slerp(const Quat& a, const Quat& b, double t) {
    const Eigen::Vector4d qa = a.coeffs();
    const auto [qb, theta] = shorter_arc(qa, b);
    Eigen::Vector4d r;
    if (theta < kLinearAngle) {
        r = ((1.0 - t) * qa + t * qb).normalized();
    } else {
        const double s = std::sin(theta);
        r = (std::sin((1.0 - t) * theta) / s) * qa + (std::sin(t * theta) / s) * qb;
    }
    Quat out;
    out.coeffs() = r;
    return out;
}

std::vector<std::vector<Quat>> quaternion_casteljau_levels(std::span<const Quat> control, double t) {
    if (control.empty()) throw InputError("a quaternion Bezier curve needs at least 1 control quaternion, got 0");
    std::vector<std::vector<Quat>> levels{std::vector<Quat>(control.begin(), control.end())};
    while (levels.back().size() > 1) {
        const std::vector<Quat>& prev = levels.back();
        std::vector<Quat> next(prev.size() - 1);
        for (size_t i = 0; i + 1 < prev.size(); ++i) next[i] = slerp(prev[i], prev[i + 1], t);
        levels.push_back(std::move(next));
    }
    return levels;
}

Quat quaternion_bezier_point(std::span<const Quat> control, double t) {
    if (control.empty()) throw InputError("a quaternion Bezier curve needs at least 1 control quaternion, got 0");
    if (control.size() <= kStackControl) {
        std::array<Quat, kStackControl> work;
        std::copy(control.begin(), control.end(), work.begin());
        return reduce(std::span<Quat>(work.data(), control.size()), t);
    }
    std::vector<Quat> work(control.begin(), control.end());
    return reduce(work, t);
}

Eigen::Matrix3d rotation_matrix(const Quat& q) {
    const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
    Eigen::Matrix3d r;
    r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
        2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),    //
        2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
    return r;
}

double rotation_angle_between(const Quat& a, const Quat& b) {
    return 2.0 * shorter_arc(a.coeffs(), b).theta;  // a rotation turns by twice the arc
}

Quat QuaternionChain::at(double u) const {
    const int n = num_segments();
    if (n == 0) throw InputError("the quaternion chain has no segments");
    const int k = std::clamp(static_cast<int>(std::floor(u)), 0, n - 1);
    return quaternion_bezier_point(segment(k), std::clamp(u - k, 0.0, 1.0));
}

QuaternionChain quaternion_chain(std::span<const Quat> control) {
    const size_t n = control.size();
    if (n < 4 || (n - 1) % 3 != 0)
        throw InputError("a piecewise cubic quaternion curve needs 3n + 1 control quaternions (4, 7, 10, ...), got " +
                         std::to_string(n));
    QuaternionChain c;
    c.control.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const double len = control[i].norm();
        if (!(len > 0) || !std::isfinite(len))
            throw InputError("quaternion " + std::to_string(i + 1) + " of " + std::to_string(n) +
                             (len == 0 ? " is zero: it names no rotation" : " has a non-finite length"));
        c.control.push_back(control[i].normalized());
    }
    return c;
}

}  // namespace crossdiv
