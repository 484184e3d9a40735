#pragma once
/// @file
/// Cubic spline segments by basis matrix, and piecewise curves as chains of Bezier segments.
///
/// A cubic segment with geometry G = [p0 p1 p2 p3] (points as columns) and basis matrix B is
/// q(t) = G B T(t), T(t) = (1, t, t^2, t^3)^T (the CS-C3100 seed's convention). Changing
/// basis to Bezier is G' = G B B_bez^-1; the conversions below are those products written out
/// as exact weights, so converted control points are reproducible to the last bit.
///
/// Piecewise curves (CS-C3100 seed):
/// - Bezier chains of 3n + 1 points: segment k uses points 3k..3k+3 (ends shared);
/// - uniform cubic B-splines with the sliding window: segment k uses points k..k+3;
/// - Catmull-Rom (CS4620 seed): segment k of an open curve uses points k..k+3 and runs from
///   p_{k+1} to p_{k+2}; a closed curve wraps around and has one segment per point.

#include <Eigen/Core>
#include <span>
#include <string_view>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// The three cubic bases of the seeds.
enum class CubicBasis {
    Bezier,      ///< Bernstein: interpolates p0 and p3
    BSpline,     ///< uniform cubic B-spline: C2, interpolates nothing
    CatmullRom,  ///< tension 1/2: interpolates p1 and p2, C1
};

/// "bezier" / "bspline" / "catmull-rom".
std::string_view to_string(CubicBasis basis);

/// The 4x4 basis matrix B of q(t) = G B (1, t, t^2, t^3)^T.
Eigen::Matrix4d basis_matrix(CubicBasis basis);

/// The Bezier control points of the segment with geometry p[0..3] in `basis` (the seed's
/// `toBezier`). Bezier returns its input.
std::array<Vec3, 4> to_bezier(CubicBasis basis, std::span<const Vec3, 4> p);

/// B-spline segment -> Bezier: (p0 + 4p1 + p2)/6, (2p1 + p2)/3, (p1 + 2p2)/3, (p1 + 4p2 + p3)/6.
std::array<Vec3, 4> bspline_to_bezier(std::span<const Vec3, 4> p);
/// Catmull-Rom segment -> Bezier: p1, p1 + (p2 - p0)/6, p2 - (p3 - p1)/6, p2.
std::array<Vec3, 4> catmull_rom_to_bezier(std::span<const Vec3, 4> p);

/// Appends points of one cubic segment to `dest` at t = i / num_intervals for
/// i = 0 .. num_intervals - 1, and t = 1 too when `include_last_point` (the CS-C3100 seed's
/// `tessellateCubicSplineSegment`). num_intervals = 1 gives t = {0, 1}. The seed's text
/// also says num_intervals = 5 gives t = {0, .25, .5, .75, 1}, which contradicts its own
/// rule (that is 4 intervals); we follow the rule: 5 gives t = {0, .2, .4, .6, .8, 1}.
/// include_last_point only decides whether t = 1 is emitted, never the spacing. Points are
/// evaluated as G B T(t), the seed's matrix form.
/// @throws InputError if num_intervals < 1.
void tessellate_cubic_spline_segment(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                     const Eigen::Matrix4d& basis, int num_intervals, bool include_last_point,
                                     std::vector<Vec3>& dest);

/// A piecewise curve as Bezier segments of one degree, stored flat and unshared: segment k
/// is points[k (degree + 1) .. k (degree + 1) + degree]. Keeping each segment's ends lets the
/// checks measure continuity at the joints instead of assuming it. The global parameter
/// u in [0, num_segments()] runs over segment floor(u) at t = u - floor(u).
struct BezierChain {
    int degree = 3;
    std::vector<Vec3> points;
    bool closed = false;  ///< built as a closed curve (a closed Catmull-Rom), for frames

    int num_segments() const { return degree < 0 || points.empty() ? 0 : static_cast<int>(points.size()) / (degree + 1); }
    std::span<const Vec3> segment(int k) const {
        return std::span<const Vec3>(points).subspan(static_cast<size_t>(k) * (degree + 1), degree + 1);
    }
};

/// The cubic Bezier of the Hermite segment from p0 to p1 with end derivatives m0, m1:
/// p0, p0 + m0/3, p1 - m1/3, p1.
std::array<Vec3, 4> hermite_to_bezier(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1);

/// The count rule of the splines that run through their points by Catmull-Rom's windows: at
/// least 4 points open, 3 closed. @throws InputError "a[n] open|closed CURVE needs at least N
/// POINTS, got n".
void require_window_count(size_t n, bool closed, const char* curve, const char* points);

/// Appends `segment` to `chain`, refusing a control point that is not finite (a basis change
/// or tangent sums control points, which overflows for points near DBL_MAX).
/// @throws InputError naming segment `k`.
void append_segment(BezierChain& chain, int k, const std::array<Vec3, 4>& segment);

/// A single Bezier curve of any degree (the BZC file's curve) as a one-segment chain.
/// @throws InputError if `control` is empty.
BezierChain single_bezier(std::span<const Vec3> control);
/// Cubic Bezier chain from 3n + 1 points. @throws InputError naming the count otherwise.
BezierChain bezier_chain(std::span<const Vec3> control);
/// Uniform cubic B-spline from n >= 4 points: n - 3 segments. @throws InputError otherwise.
BezierChain bspline_chain(std::span<const Vec3> control);
/// Catmull-Rom: open from n >= 4 points (n - 3 segments, from p1 to p_{n-2}); closed from
/// n >= 3 points (n segments, through every point). @throws InputError otherwise.
BezierChain catmull_rom_chain(std::span<const Vec3> control, bool closed);

/// The point, first and second derivative with respect to the global parameter u.
struct ChainJet {
    Vec3 position, d1, d2;
};
ChainJet chain_jet(const BezierChain& chain, double u);

}  // namespace crossdiv
