#pragma once
/// @file
/// Bezier curves of unit quaternions (orientations): de Casteljau's algorithm with spherical
/// linear interpolation in place of the affine one at every level (K. Shoemake, "Animating
/// rotation with quaternion curves", SIGGRAPH 1985), any degree, and piecewise cubic chains of
/// them for a camera path whose positions are a Bezier chain.
///
/// slerp(a, b, t) = sin((1-t) theta) / sin(theta) a + sin(t theta) / sin(theta) b, theta the
/// angle between a and b on the unit sphere of R^4. q and -q are the same rotation: slerp takes
/// the shorter arc, so where a . b < 0 it interpolates towards -b (the result at t = 1 is then
/// -b, the same rotation as b). The curve stays on the unit sphere, interpolates its first and
/// last control quaternion (as rotations), and with two control points turns at a constant
/// angular velocity.

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

using Quat = Eigen::Quaterniond;

/// Spherical linear interpolation along the shorter arc. The angle is 2 atan2(|a - b|, |a + b|)
/// (accurate for nearby quaternions, where acos of the dot product loses half the digits);
/// below an angle of 1e-8 radians it is the linear blend, normalized (sin theta / theta is 1 to
/// double precision there). @pre a and b are unit quaternions.
Quat slerp(const Quat& a, const Quat& b, double t);

/// Every de Casteljau level at t with slerp: levels[0] is the control polygon, levels[d] the
/// point on the curve. @throws InputError if `control` is empty.
std::vector<std::vector<Quat>> quaternion_casteljau_levels(std::span<const Quat> control, double t);

/// The point at t of the quaternion Bezier curve. @throws InputError if `control` is empty.
Quat quaternion_bezier_point(std::span<const Quat> control, double t);

/// The rotation matrix of a unit quaternion (w, x, y, z):
///     [1 - 2(y^2 + z^2)   2(xy - wz)        2(xz + wy)     ]
///     [2(xy + wz)         1 - 2(x^2 + z^2)  2(yz - wx)     ]
///     [2(xz - wy)         2(yz + wx)        1 - 2(x^2 + y^2)].
Eigen::Matrix3d rotation_matrix(const Quat& q);

/// The angle of the rotation that takes a to b, in [0, pi]: 2 atan2(|a - b|, |a + b|) with b's
/// sign chosen nearer to a.
double rotation_angle_between(const Quat& a, const Quat& b);

/// Cubic Bezier pieces of unit quaternions, 3n + 1 control quaternions with shared ends as a
/// Bezier chain of points; the global parameter u in [0, n] runs over piece floor(u).
struct QuaternionChain {
    std::vector<Quat> control;

    int num_segments() const { return control.size() < 4 ? 0 : static_cast<int>(control.size() - 1) / 3; }
    std::span<const Quat> segment(int k) const { return std::span<const Quat>(control).subspan(3 * static_cast<size_t>(k), 4); }
    /// The orientation at global parameter u (clamped to [0, n]).
    Quat at(double u) const;
};

/// A quaternion chain from 3n + 1 quaternions, each normalized.
/// @throws InputError for another count or a quaternion of zero or non-finite length (naming it).
QuaternionChain quaternion_chain(std::span<const Quat> control);

}  // namespace crossdiv
