#include "crossdiv/curves/bezier.h"

#include <array>
#include <cmath>

#include "crossdiv/error.h"

namespace crossdiv {

namespace {

void require_points(std::span<const Vec3> control, const char* what) {
    if (control.empty()) throw InputError(std::string(what) + ": a Bezier curve needs at least one control point");
}

/// In-place de Casteljau on `work` (size d + 1) down to `stop_size` points.
void reduce(std::span<Vec3> work, double t, size_t stop_size) {
    const double s = 1.0 - t;
    for (size_t n = work.size(); n > stop_size; --n)
        for (size_t i = 0; i + 1 < n; ++i) work[i] = s * work[i] + t * work[i + 1];
}

/// Small curves (the common cubic) run on the stack; larger degrees on the heap.
template <class F>
auto with_work_copy(std::span<const Vec3> control, F&& f) {
    constexpr size_t kStack = 16;
    if (control.size() <= kStack) {
        std::array<Vec3, kStack> buf;
        std::copy(control.begin(), control.end(), buf.begin());
        return f(std::span<Vec3>(buf.data(), control.size()));
    }
    std::vector<Vec3> buf(control.begin(), control.end());
    return f(std::span<Vec3>(buf));
}

}  // namespace

std::vector<Vec3> casteljau_step(std::span<const Vec3> points, double t) {
    std::vector<Vec3> out;
    if (points.size() < 2) return out;
    out.reserve(points.size() - 1);
    for (size_t i = 0; i + 1 < points.size(); ++i) out.push_back((1.0 - t) * points[i] + t * points[i + 1]);
    return out;
}

std::vector<std::vector<Vec3>> casteljau_levels(std::span<const Vec3> control, double t) {
    require_points(control, "de Casteljau");
    std::vector<std::vector<Vec3>> levels;
    levels.reserve(control.size());
    levels.emplace_back(control.begin(), control.end());
    while (levels.back().size() > 1) {
        levels.push_back(casteljau_step(levels.back(), t));
        for (size_t i = 0; i < levels.back().size(); ++i)
            if (!levels.back()[i].allFinite())
                throw InputError("de Casteljau level " + std::to_string(levels.size() - 1) + ", point " + std::to_string(i) +
                                 " is not finite at t = " + std::to_string(t) +
                                 ": the control points overflow double in (1 - t) a + t b, so scale the curve down");
    }
    return levels;
}

Vec3 bezier_point(std::span<const Vec3> control, double t) {
    require_points(control, "Bezier evaluation");
    return with_work_copy(control, [t](std::span<Vec3> w) {
        reduce(w, t, 1);
        return w[0];
    });
}

Vec3 bernstein_point(std::span<const Vec3> control, double t) {
    require_points(control, "Bernstein evaluation");
    const int d = static_cast<int>(control.size()) - 1;
    Vec3 sum = Vec3::Zero();
    double binomial = 1.0;  // C(d, i), updated exactly for d <= 50 (below 2^53)
    for (int i = 0; i <= d; ++i) {
        sum += binomial * std::pow(t, i) * std::pow(1.0 - t, d - i) * control[i];
        binomial = binomial * (d - i) / (i + 1);
    }
    return sum;
}

std::vector<Vec3> bezier_derivative(std::span<const Vec3> control) {
    require_points(control, "Bezier derivative");
    const size_t d = control.size() - 1;
    if (d == 0) return {Vec3::Zero()};
    std::vector<Vec3> out(d);
    for (size_t i = 0; i < d; ++i) out[i] = static_cast<double>(d) * (control[i + 1] - control[i]);
    return out;
}

BezierJet bezier_jet(std::span<const Vec3> control, double t) {
    require_points(control, "Bezier evaluation");
    const double d = static_cast<double>(control.size() - 1);
    return with_work_copy(control, [&](std::span<Vec3> w) {
        BezierJet jet{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
        // Stop at three points (level d - 2): they give the second difference, then the
        // first, then the point, each by one more step.
        reduce(w, t, 3);
        if (w.size() >= 3) jet.d2 = d * (d - 1) * (w[2] - 2.0 * w[1] + w[0]);
        reduce(w.first(std::min<size_t>(w.size(), 3)), t, 2);
        if (w.size() >= 2) jet.d1 = d * (w[1] - w[0]);
        reduce(w.first(std::min<size_t>(w.size(), 2)), t, 1);
        jet.position = w[0];
        return jet;
    });
}

BezierPointTangent bezier_point_tangent(std::span<const Vec3> control, double t) {
    require_points(control, "Bezier evaluation");
    BezierPointTangent r = with_work_copy(control, [t](std::span<Vec3> w) {
        reduce(w, t, 2);
        if (w.size() == 1) return BezierPointTangent{w[0], Vec3::Zero()};
        return BezierPointTangent{(1.0 - t) * w[0] + t * w[1], w[1] - w[0]};
    });
    // stableNorm: the derivative of a curve at the scale of 1e-300 has a norm whose square
    // underflows to 0; the direction is still well defined.
    const double len = r.tangent.stableNorm();
    r.tangent = len > 0.0 ? Vec3(r.tangent / len) : bezier_unit_tangent(control, t);
    return r;
}

BezierSplit bezier_split(std::span<const Vec3> control, double t) {
    require_points(control, "Bezier split");
    const size_t n = control.size();
    BezierSplit s;
    s.left.resize(n);
    s.right.resize(n);
    std::vector<Vec3> w(control.begin(), control.end());
    // After step k the first point is p_{k,0} (left's k-th) and the last is p_{k,n-1-k}
    // (right's (n-1-k)-th).
    for (size_t k = 0; k < n; ++k) {
        s.left[k] = w[0];
        s.right[n - 1 - k] = w[n - 1 - k];
        for (size_t i = 0; i + 1 < n - k; ++i) w[i] = (1.0 - t) * w[i] + t * w[i + 1];
    }
    return s;
}

std::vector<Vec3> bezier_elevate(std::span<const Vec3> control) {
    require_points(control, "Bezier degree elevation");
    const size_t n = control.size();  // d + 1
    std::vector<Vec3> out(n + 1);
    out[0] = control[0];
    out[n] = control[n - 1];
    for (size_t i = 1; i < n; ++i) {
        const double a = static_cast<double>(i) / static_cast<double>(n);
        out[i] = a * control[i - 1] + (1.0 - a) * control[i];
    }
    return out;
}

Vec3 bezier_unit_tangent(std::span<const Vec3> control, double t) {
    require_points(control, "Bezier tangent");
    std::vector<Vec3> derivative(control.begin(), control.end());
    for (int order = 1; derivative.size() > 1; ++order) {
        derivative = bezier_derivative(derivative);
        const Vec3 v = bezier_point(derivative, t);
        // Exactly zero only: any nonzero derivative has a well-defined direction, and a
        // threshold would pick a higher order where the first is merely small.
        if ((v.array() != 0.0).any()) return ((t == 1.0 && order % 2 == 0) ? -v : v).stableNormalized();
    }
    return Vec3::Zero();
}

}  // namespace crossdiv
