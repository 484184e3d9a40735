#pragma once
/// @file
/// Bessel-Overhauser splines: cubic Hermite segments through points, on chord-length knots,
/// whose tangent at each point is the knot-weighted average of the velocities of the two
/// chords around it (Bessel's tangent; the Overhauser curve blends the parabolas through
/// three consecutive points, which gives the same tangent). With knots u_i, chord lengths
/// h_i = u_{i+1} - u_i = |p_{i+1} - p_i| and chord velocities m_i = (p_{i+1} - p_i) / h_i,
///
///     v_i = (h_i m_{i-1} + h_{i-1} m_i) / (h_{i-1} + h_i).
///
/// The segment from p_i to p_{i+1}, reparametrized to [0, 1], is the cubic Bezier p_i,
/// p_i + h_i v_i / 3, p_{i+1} - h_i v_{i+1} / 3, p_{i+1}. The curve is C1 in the chord-length
/// parameter (G1 in the chain's unit-per-segment parameter, whose derivative scales by h_i).
/// With equal chords every v_i is (p_{i+1} - p_{i-1}) / (2h) and the curve is Catmull-Rom's.

#include <span>
#include <vector>

#include "crossdiv/curves/cubic_spline.h"

namespace crossdiv {

/// The Bessel-Overhauser chain through `points`: open from n >= 4 points (n - 3 segments
/// from point 1 to point n - 2, the first and last shaping the end tangents, as Catmull-Rom),
/// closed from n >= 3 (n segments through every point).
/// @throws InputError for too few points, two consecutive points that coincide (a chord of
/// length 0 has no knot interval; naming them), or a control point that overflows.
BezierChain bessel_overhauser_chain(std::span<const Vec3> points, bool closed);

/// The chord length of each segment of that chain: segment k runs from p_{k+1} to p_{k+2}
/// (indices mod n when closed, as Catmull-Rom's), and its derivatives are h = |p_{k+2} - p_{k+1}|
/// times those in the chord-length parameter. @throws InputError as the chain.
std::vector<double> bessel_overhauser_chords(std::span<const Vec3> points, bool closed);

}  // namespace crossdiv
