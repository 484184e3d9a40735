#pragma once
/// @file
/// Bezier curves of any degree d (d + 1 control points, in 2D or 3D; 2D curves have z = 0).
///
/// Evaluation is de Casteljau's algorithm (G. Farin, "Curves and Surfaces for CAGD", 5th ed.,
/// ch. 4): level k holds d + 1 - k points, p_{k,i} = (1 - t) p_{k-1,i} + t p_{k-1,i+1}, and
/// the single point of level d lies on the curve. Every level is available (the meshedit
/// seed's `evaluateStep`), because the levels are also the control points of the two halves
/// split at t and, through their last edge, the tangent. The Bernstein sum is offered as an
/// independent second algorithm for verification, not for speed.

#include <span>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// The highest degree a curve file may give one Bezier segment (BZC's control point count
/// less one). De Casteljau's subdivision costs d^2 / 2 interpolations, and the adaptive
/// tessellations split a segment up to 1024 times, so the work grows as the square of the
/// degree: at 256 a segment's tessellation is about 1e8 interpolations (0.1 s), at degree
/// 1000 it took 6.5 s and a 50 KB file would take hours. Any degree up to this is exact.
inline constexpr int kMaxBezierDegree = 256;

/// One de Casteljau step: n points in, n - 1 points out (the seed's `evaluateStep`).
/// @pre points.size() >= 1; a single point returns an empty vector.
std::vector<Vec3> casteljau_step(std::span<const Vec3> points, double t);

/// Every de Casteljau level at t: levels[0] is the control polygon, levels[d] the point on
/// the curve. @throws InputError if `control` is empty.
std::vector<std::vector<Vec3>> casteljau_levels(std::span<const Vec3> control, double t);

/// The point at t by de Casteljau (in place on a small copy; no allocation for d <= 15).
/// @throws InputError if `control` is empty.
Vec3 bezier_point(std::span<const Vec3> control, double t);

/// The point at t as the Bernstein sum  sum_i C(d,i) t^i (1-t)^(d-i) p_i, a different
/// algorithm from de Casteljau (binomials and powers, no repeated interpolation). For
/// cross-checks: it loses accuracy faster with the degree.
Vec3 bernstein_point(std::span<const Vec3> control, double t);

/// Control points of the derivative (the hodograph): d (p_{i+1} - p_i), degree d - 1.
/// A degree-0 curve has the zero derivative (one zero control point).
std::vector<Vec3> bezier_derivative(std::span<const Vec3> control);

/// Position and first and second derivatives at t.
struct BezierJet {
    Vec3 position, d1, d2;
};
/// Position, first and second derivative at t, all read off one de Casteljau pass: the last
/// three levels give d1 = d (b_1 - b_0) and d2 = d (d - 1) (c_2 - 2 c_1 + c_0).
BezierJet bezier_jet(std::span<const Vec3> control, double t);

/// Position and unit tangent at t from one de Casteljau pass (the tangent is the direction
/// of the last level's edge, b_1 - b_0; where that vanishes, bezier_unit_tangent's limit).
struct BezierPointTangent {
    Vec3 position, tangent;
};
BezierPointTangent bezier_point_tangent(std::span<const Vec3> control, double t);

/// The two halves of a split at t: `left` reproduces the curve on [0, t] and `right` on
/// [t, 1], each reparametrized to [0, 1]. left.back() == right.front() bitwise.
struct BezierSplit {
    std::vector<Vec3> left, right;
};
BezierSplit bezier_split(std::span<const Vec3> control, double t);

/// Degree elevation by one: the same curve with d + 2 control points,
/// q_i = (i / (d+1)) p_{i-1} + (1 - i / (d+1)) p_i (Farin, sec. 6.1).
std::vector<Vec3> bezier_elevate(std::span<const Vec3> control);

/// Unit tangent at t in the direction of increasing t. Where the derivative vanishes (a
/// control point repeated at an end, a cusp) the direction is the limit of the tangent:
/// the first non-vanishing derivative of order k, negated at t = 1 when k is even (the
/// curve arrives there along -p^(k)). Zero only for a curve that is a single point.
Vec3 bezier_unit_tangent(std::span<const Vec3> control, double t);

}  // namespace crossdiv
