#include "crossdiv/curves/kappa_curve.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

namespace {

double triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

std::string point_name(size_t i, size_t n) { return "point " + std::to_string(i + 1) + " of " + std::to_string(n); }

void require_kappa_points(std::span<const Vec3> p) {
    const size_t n = p.size();
    if (n < 3) throw InputError("a closed kappa-curve needs at least 3 points, got " + std::to_string(n));
    if (n > kKappaMaxPoints)
        throw InputError("a kappa-curve of " + std::to_string(n) + " points: each of up to " +
                         std::to_string(kKappaMaxIterations) + " iterations solves a system of that size; at most " +
                         std::to_string(kKappaMaxPoints) + " points");
    for (size_t i = 0; i < n; ++i) {
        if (!p[i].allFinite()) throw InputError(point_name(i, n) + " is not finite");
        if (p[i].z() != 0.0) throw InputError(point_name(i, n) + " is off the xy-plane: a kappa-curve is planar");
    }
    for (size_t i = 0; i < n; ++i)
        if (p[i] == p[(i + 1) % n])
            throw InputError("points " + std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) + " of " +
                             std::to_string(n) + " coincide: a piece cannot have its curvature maximum at both");
}

/// The contraction rho of a linearly converging iteration, from its moves r_k: the geometric
/// mean ratio over the last kContractionWindow moves (see KappaCurve::contraction).
double contraction_of(const std::vector<double>& moves) {
    constexpr size_t kContractionWindow = 10;
    const double last = moves.back();
    if (last == 0.0) return 0.0;
    if (moves.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    const size_t w = std::min(kContractionWindow, moves.size() - 1);
    return std::pow(last / moves[moves.size() - 1 - w], 1.0 / static_cast<double>(w));
}

/// How far the middle points still are from the fixed point: the remaining moves sum to
/// r_k rho / (1 - rho). A move alone understates it where rho is near 1 (sharp turns contract
/// by 0.99 per step); infinity while the moves do not shrink (or cannot be measured yet, or
/// are rounding noise at the fixed point of an ill-conditioned case).
double distance_to_fixed_point(double last_move, double rho) {
    if (last_move == 0.0) return 0.0;
    return rho < 1.0 ? last_move * rho / (1.0 - rho) : std::numeric_limits<double>::infinity();
}

}  // namespace

double kappa_parameter(const Vec3& c0, const Vec3& p, const Vec3& c2) {
    const Vec3 u = c0 - p, w = c2 - c0;
    const double a = w.squaredNorm(), b = 3.0 * w.dot(u), c = (2.0 * u - w).dot(u), d = -u.squaredNorm();
    const auto f = [&](double t) { return ((a * t + b) * t + c) * t + d; };
    const auto df = [&](double t) { return (3.0 * a * t + 2.0 * b) * t + c; };
    // f(0) = -|c0 - p|^2 <= 0 <= |c2 - p|^2 = f(1): keep a bracket [lo, hi] with f(lo) < 0 <
    // f(hi), take Newton's step when it stays inside and bisect otherwise (the paper's
    // closed form loses digits to cancellation when the cubic is nearly degenerate).
    if (d == 0.0) return 0.0;
    if (f(1.0) <= 0.0) return 1.0;
    double lo = 0.0, hi = 1.0, t = 0.5;
    for (int step = 0; step < 200; ++step) {  // bisection alone halves [0, 1] to one ulp in < 1100
        const double v = f(t);
        if (v == 0.0) return t;
        (v < 0.0 ? lo : hi) = t;
        const double slope = df(t);
        double next = slope != 0.0 ? t - v / slope : lo;
        if (!(next > lo && next < hi) || std::abs(next - t) > 0.5 * (hi - lo)) next = 0.5 * (lo + hi);
        if (next == t || next <= lo || next >= hi) return t;  // the bracket holds no other double
        t = next;
    }
    return t;
}

double kappa_lambda(const Vec3& c0, const Vec3& c1, const Vec3& c1_next, const Vec3& c2_next) {
    const double a = std::sqrt(triangle_area(c0, c1, c1_next)), b = std::sqrt(triangle_area(c1, c1_next, c2_next));
    return a + b > 0.0 ? a / (a + b) : 0.5;
}

double quadratic_max_curvature_param(std::span<const Vec3> c) {
    // c'(t) = 2 ((c1 - c0) + t (c0 - 2 c1 + c2)): |c'| is smallest where c'(t) . c'' = 0.
    const Vec3 first = c[1] - c[0], second = c[0] - 2.0 * c[1] + c[2];
    const double s = second.squaredNorm();
    if (s == 0.0) return 0.5;  // a straight, uniformly parametrized piece: curvature 0 throughout
    return std::clamp(-first.dot(second) / s, 0.0, 1.0);
}

double quadratic_signed_curvature(std::span<const Vec3> c, double t) {
    const Vec3 d1 = 2.0 * ((1.0 - t) * (c[1] - c[0]) + t * (c[2] - c[1])), d2 = 2.0 * (c[0] - 2.0 * c[1] + c[2]);
    const double speed = d1.norm();
    return speed > 0.0 ? d1.cross(d2).z() / (speed * speed * speed) : 0.0;
}

namespace {

/// kappa_curve of points whose largest extent is in [1/2, 1).
KappaCurve kappa_curve_of_unit_size(std::span<const Vec3> p, const KappaOptions& options) {
    const size_t n = p.size();
    const auto next = [n](size_t i) { return (i + 1) % n; };
    const auto prev = [n](size_t i) { return (i + n - 1) % n; };
    const double diagonal = bounding_box_diagonal({p.begin(), p.end()});

    // The paper's start: middle points at the points, joints at the chords' midpoints.
    std::vector<Vec3> mid(p.begin(), p.end()), start(n), end(n);
    for (size_t i = 0; i < n; ++i) {
        start[i] = 0.5 * (p[prev(i)] + p[i]);
        end[i] = 0.5 * (p[i] + p[next(i)]);
    }
    KappaCurve out;
    out.params.assign(n, 0.5);
    out.lambdas.assign(n, 0.5);

    // Row i of the system: p_i = (1-t)^2 c_{i,0} + 2t(1-t) c_{i,1} + t^2 c_{i,2} with the joints
    // written in the middle points; three entries per row, one pattern for every iteration.
    Eigen::SparseMatrix<double> a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    {
        std::vector<Eigen::Triplet<double>> pattern;
        pattern.reserve(3 * n);
        for (size_t i = 0; i < n; ++i)
            for (size_t j : {prev(i), i, next(i)}) pattern.emplace_back(int(i), int(j), 1.0);
        a.setFromTriplets(pattern.begin(), pattern.end());
        a.makeCompressed();
    }
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.analyzePattern(a);
    Eigen::MatrixX3d rhs(static_cast<Eigen::Index>(n), 3);
    for (size_t i = 0; i < n; ++i) rhs.row(static_cast<Eigen::Index>(i)) = p[i].transpose();

    std::vector<double>& t = out.params;
    std::vector<double>& lambda = out.lambdas;
    for (int iteration = 1; iteration <= options.max_iterations; ++iteration) {
        for (size_t i = 0; i < n; ++i) {
            t[i] = kappa_parameter(start[i], p[i], end[i]);
            lambda[i] = kappa_lambda(start[i], mid[i], mid[next(i)], end[next(i)]);
        }
        for (size_t i = 0; i < n; ++i) {
            const double s = 1.0 - t[i], before = lambda[prev(i)], after = lambda[i];
            const auto row = static_cast<Eigen::Index>(i);
            a.coeffRef(row, static_cast<Eigen::Index>(prev(i))) = (1.0 - before) * s * s;
            a.coeffRef(row, row) = before * s * s + 2.0 * t[i] * s + (1.0 - after) * t[i] * t[i];
            a.coeffRef(row, static_cast<Eigen::Index>(next(i))) = after * t[i] * t[i];
        }
        lu.factorize(a);
        if (lu.info() != Eigen::Success)
            throw InputError("the kappa-curve system is singular at iteration " + std::to_string(iteration) + ": " +
                             lu.lastErrorMessage());
        const Eigen::MatrixX3d solved = lu.solve(rhs);
        double move = 0;
        for (size_t i = 0; i < n; ++i) {
            const Vec3 m = solved.row(static_cast<Eigen::Index>(i)).transpose();
            move = std::max(move, (m - mid[i]).norm());
            mid[i] = m;
        }
        for (size_t i = 0; i < n; ++i) end[i] = start[next(i)] = (1.0 - lambda[i]) * mid[i] + lambda[i] * mid[next(i)];
        if (!std::isfinite(move))
            throw InputError("the kappa-curve iteration left the finite range at iteration " + std::to_string(iteration));
        out.residuals.push_back(move / diagonal);
        out.contraction = contraction_of(out.residuals);
        out.error_estimate = distance_to_fixed_point(out.residuals.back(), out.contraction);
        if (out.error_estimate <= options.tolerance) {
            out.converged = true;
            break;
        }
    }
    out.chain = BezierChain{2, {}, true};
    out.chain.points.reserve(3 * n);
    for (size_t i = 0; i < n; ++i) out.chain.points.insert(out.chain.points.end(), {start[i], mid[i], end[i]});
    return out;
}

}  // namespace

KappaCurve kappa_curve(std::span<const Vec3> p, const KappaOptions& options) {
    require_kappa_points(p);
    // The construction commutes with scaling (its parameters and weights are ratios of
    // areas). It runs on the points scaled by the power of two that brings their largest
    // extent into [1/2, 1), which is exact in floating point, so that a curve at the scale of
    // 1e-300 (whose areas would underflow to 0) or of 1e300 (overflow) is the same curve as
    // at 1, to the last bit.
    Vec3 lo = p[0], hi = p[0];
    for (const Vec3& q : p) {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    int exponent = 0;  // of the largest extent: the diagonal itself may underflow
    (void)std::frexp((hi - lo).maxCoeff(), &exponent);
    std::vector<Vec3> unit(p.begin(), p.end());
    for (Vec3& q : unit) q = Vec3(std::ldexp(q.x(), -exponent), std::ldexp(q.y(), -exponent), std::ldexp(q.z(), -exponent));
    KappaCurve out = kappa_curve_of_unit_size(unit, options);
    for (Vec3& q : out.chain.points) q = Vec3(std::ldexp(q.x(), exponent), std::ldexp(q.y(), exponent), std::ldexp(q.z(), exponent));
    return out;
}

KappaCurve converged_kappa_curve(std::span<const Vec3> points) {
    KappaCurve k = kappa_curve(points);
    if (!k.converged) {
        char message[256];
        std::snprintf(message, sizeof message,
                      "the kappa-curve iteration did not converge: after %d iterations the middle points still move "
                      "by %.3g of the diagonal, an estimated %.3g from the fixed point (tolerance %.0e)",
                      k.iterations(), k.residual(), k.error_estimate, kKappaConvergence);
        throw InputError(message);
    }
    return k;
}

}  // namespace crossdiv
