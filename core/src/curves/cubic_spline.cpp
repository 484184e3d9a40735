#include "crossdiv/curves/cubic_spline.h"

#include <cmath>
#include <string>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/error.h"

namespace crossdiv {

std::string_view to_string(CubicBasis basis) {
    switch (basis) {
        case CubicBasis::Bezier: return "bezier";
        case CubicBasis::BSpline: return "bspline";
        case CubicBasis::CatmullRom: return "catmull-rom";
    }
    return "?";
}

Eigen::Matrix4d basis_matrix(CubicBasis basis) {
    Eigen::Matrix4d b;
    // Row i holds the power-basis coefficients (1, t, t^2, t^3) of the weight of p_i.
    switch (basis) {
        case CubicBasis::Bezier:
            b << 1, -3, 3, -1,
                 0, 3, -6, 3,
                 0, 0, 3, -3,
                 0, 0, 0, 1;
            break;
        case CubicBasis::BSpline:
            b << 1, -3, 3, -1,
                 4, 0, -6, 3,
                 1, 3, 3, -3,
                 0, 0, 0, 1;
            b /= 6.0;
            break;
        case CubicBasis::CatmullRom:
            b << 0, -1, 2, -1,
                 2, 0, -5, 3,
                 0, 1, 4, -3,
                 0, 0, -1, 1;
            b *= 0.5;
            break;
    }
    return b;
}

std::array<Vec3, 4> bspline_to_bezier(std::span<const Vec3, 4> p) {
    return {(p[0] + 4.0 * p[1] + p[2]) / 6.0, (2.0 * p[1] + p[2]) / 3.0, (p[1] + 2.0 * p[2]) / 3.0,
            (p[1] + 4.0 * p[2] + p[3]) / 6.0};
}

std::array<Vec3, 4> catmull_rom_to_bezier(std::span<const Vec3, 4> p) {
    return {p[1], p[1] + (p[2] - p[0]) / 6.0, p[2] - (p[3] - p[1]) / 6.0, p[2]};
}

std::array<Vec3, 4> to_bezier(CubicBasis basis, std::span<const Vec3, 4> p) {
    switch (basis) {
        case CubicBasis::BSpline: return bspline_to_bezier(p);
        case CubicBasis::CatmullRom: return catmull_rom_to_bezier(p);
        case CubicBasis::Bezier: break;
    }
    return {p[0], p[1], p[2], p[3]};
}

void tessellate_cubic_spline_segment(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                     const Eigen::Matrix4d& basis, int num_intervals, bool include_last_point,
                                     std::vector<Vec3>& dest) {
    if (num_intervals < 1)
        throw InputError("tessellation needs at least 1 interval per segment, got " + std::to_string(num_intervals));
    Eigen::Matrix<double, 3, 4> g;
    g << p0, p1, p2, p3;
    const Eigen::Matrix<double, 3, 4> gb = g * basis;
    const int last = include_last_point ? num_intervals : num_intervals - 1;
    for (int i = 0; i <= last; ++i) {
        const double t = static_cast<double>(i) / num_intervals;
        dest.push_back(gb * Eigen::Vector4d(1.0, t, t * t, t * t * t));
    }
}

BezierChain single_bezier(std::span<const Vec3> control) {
    if (control.empty()) throw InputError("a Bezier curve needs at least 1 control point, got 0");
    return {static_cast<int>(control.size()) - 1, std::vector<Vec3>(control.begin(), control.end()), false};
}

BezierChain bezier_chain(std::span<const Vec3> control) {
    const size_t n = control.size();
    if (n < 4 || (n - 1) % 3 != 0)
        throw InputError("a piecewise cubic Bezier curve needs 3n + 1 control points (4, 7, 10, ...), got " +
                         std::to_string(n));
    BezierChain c{3, {}, false};
    c.points.reserve((n - 1) / 3 * 4);
    for (size_t k = 0; k + 3 < n; k += 3) c.points.insert(c.points.end(), control.begin() + k, control.begin() + k + 4);
    return c;
}

namespace {

BezierChain sliding_window(std::span<const Vec3> control, CubicBasis basis, bool wrap) {
    const size_t n = control.size();
    const size_t segments = wrap ? n : n - 3;
    BezierChain c{3, {}, wrap};
    c.points.reserve(segments * 4);
    for (size_t k = 0; k < segments; ++k) {
        // Closed curves read the window cyclically, so segment k still runs from p_{k+1}.
        const std::array<Vec3, 4> window{control[k % n], control[(k + 1) % n], control[(k + 2) % n], control[(k + 3) % n]};
        // The basis change sums control points (B-spline: 1/6, 4/6, 1/6; Catmull-Rom: with
        // negative weights).
        append_segment(c, static_cast<int>(k), to_bezier(basis, window));
    }
    return c;
}

}  // namespace

std::array<Vec3, 4> hermite_to_bezier(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1) {
    return {p0, p0 + m0 / 3.0, p1 - m1 / 3.0, p1};
}

void require_window_count(size_t n, bool closed, const char* curve, const char* points) {
    const size_t need = closed ? 3 : 4;
    if (n < need)
        throw InputError(std::string("a") + (closed ? " closed " : "n open ") + curve + " needs at least " +
                         std::to_string(need) + " " + points + ", got " + std::to_string(n));
}

void append_segment(BezierChain& chain, int k, const std::array<Vec3, 4>& segment) {
    for (int i = 0; i < 4; ++i)
        if (!segment[i].allFinite())
            throw InputError("segment " + std::to_string(k) + ": Bezier control point " + std::to_string(i) +
                             " is not finite; the control points overflow double in the sums that make it, so "
                             "scale the curve down");
    chain.points.insert(chain.points.end(), segment.begin(), segment.end());
}

BezierChain bspline_chain(std::span<const Vec3> control) {
    if (control.size() < 4)
        throw InputError("a cubic B-spline needs at least 4 control points, got " + std::to_string(control.size()));
    return sliding_window(control, CubicBasis::BSpline, false);
}

BezierChain catmull_rom_chain(std::span<const Vec3> control, bool closed) {
    require_window_count(control.size(), closed, "Catmull-Rom curve", "control points");
    return sliding_window(control, CubicBasis::CatmullRom, closed);
}

ChainJet chain_jet(const BezierChain& chain, double u) {
    const int n = chain.num_segments();
    if (n == 0) throw InputError("the curve has no segments");
    const int k = std::clamp(static_cast<int>(std::floor(u)), 0, n - 1);
    const BezierJet j = bezier_jet(chain.segment(k), u - k);
    return {j.position, j.d1, j.d2};
}

}  // namespace crossdiv
