#pragma once
/// @file
/// Kochanek-Bartels (TCB) splines: cubic Hermite segments through keys whose tangents are
/// set by a tension, a continuity and a bias per key (D. Kochanek, R. Bartels, "Interpolating
/// splines with local tension, continuity, and bias control", SIGGRAPH 1984, eq. 8-9).
///
/// At key p_i with neighbours p_{i-1}, p_{i+1} and parameters (t, c, b), the tangent of the
/// segment arriving at p_i and of the segment leaving it are
///
///     arriving = (1-t)(1-c)(1+b)/2 (p_i - p_{i-1}) + (1-t)(1+c)(1-b)/2 (p_{i+1} - p_i)
///     leaving  = (1-t)(1+c)(1+b)/2 (p_i - p_{i-1}) + (1-t)(1-c)(1-b)/2 (p_{i+1} - p_i)
///
/// per unit of the segment parameter (every segment spans one unit; the paper's adjustment
/// for keys unevenly spaced in time is not applied). Their difference, the jump of the first
/// derivative at the key, is (1-t) c ((1+b)(p_i - p_{i-1}) - (1-b)(p_{i+1} - p_i)): the curve is
/// C1 where c = 0. With t = c = b = 0 both are (p_{i+1} - p_{i-1}) / 2, Catmull-Rom's tangent,
/// and the chain is core's Catmull-Rom chain bit for bit. A segment with end tangents m0, m1
/// is the cubic Bezier p_i, p_i + m0/3, p_{i+1} - m1/3, p_{i+1}.

#include <span>

#include "crossdiv/curves/cubic_spline.h"

namespace crossdiv {

/// Tension, continuity and bias of one key, each in [-1, 1]; all 0 is Catmull-Rom.
struct TcbParameters {
    double tension = 0, continuity = 0, bias = 0;
    friend bool operator==(const TcbParameters&, const TcbParameters&) = default;
};

/// @throws InputError naming the parameter outside [-1, 1] (or not finite), e.g.
/// "tension 2.000000 is outside [-1, 1]".
void check_tcb_parameters(const TcbParameters& p);

/// The tangents at a key: of the segment arriving there and of the segment leaving it.
struct KeyTangents {
    Vec3 arriving, leaving;
};

/// The TCB tangents at `key` between `previous` and `next`.
KeyTangents kochanek_bartels_tangents(const Vec3& previous, const Vec3& key, const Vec3& next, const TcbParameters& p);

/// The first-derivative jump at a key that the formula gives: leaving - arriving,
/// (1-t) c ((1+b)(p_i - p_{i-1}) - (1-b)(p_{i+1} - p_i)).
Vec3 kochanek_bartels_jump(const Vec3& previous, const Vec3& key, const Vec3& next, const TcbParameters& p);

/// A TCB chain through `keys` with one parameter set per key (`parameters` empty: all 0).
/// Open, as Catmull-Rom: n >= 4 keys give n - 3 segments from key 1 to key n - 2, the first
/// and last keys only shaping the end tangents. Closed: n >= 3 keys, n segments, through
/// every key. @throws InputError for too few keys, a parameter count other than the key
/// count, a parameter outside [-1, 1] (naming the key), or a control point that overflows.
BezierChain kochanek_bartels_chain(std::span<const Vec3> keys, std::span<const TcbParameters> parameters, bool closed);

}  // namespace crossdiv
