#pragma once
/// @file
/// Corners of a sweep curve that is only C0 (a Bezier chain whose pieces meet at an angle), and
/// the mitre a generalized cylinder makes there. At a corner the tube turns by the corner's
/// rotation R, the smallest rotation taking the arriving tangent T_in to the leaving tangent
/// T_out (about T_in x T_out): the frames after the corner are R times the frames before it, so
/// no twist is added. The profile ring at the corner lies in the bisecting (mitre) plane,
/// normal to T_in + T_out: profile offset o (in the arriving frame) goes to where the arriving
/// tube's line V + o + s T_in meets that plane, o - (o . m) / (T_in . m) T_in, m the plane's
/// normal. The leaving tube's line from R o meets the plane at the same point (the plane is R's
/// mirror), so the two tubes share the ring, and each keeps its thickness up to the corner.

#include <Eigen/Core>
#include <span>
#include <vector>

#include "crossdiv/curves/cubic_spline.h"
#include "crossdiv/curves/tessellation.h"

namespace crossdiv {

/// A turn of the unit tangent below this (radians) at a joint is rounding, not a corner: the
/// tangents of a G1 joint computed from either side differ by a few ulps.
inline constexpr double kCornerAngle = 1e-9;

/// A turn above this (radians) is refused: the mitre plane is then almost the tube's own
/// direction, the mitre stretches the ring without bound, and the tube folds onto itself.
inline constexpr double kMaxCornerTurn = 170.0 * 3.14159265358979323846 / 180.0;

/// A sample of a sweep polyline where the tangent jumps.
struct SweepCorner {
    int sample = 0;  ///< index into the polyline (a closed sweep's seam corner is sample 0)
    Vec3 in, out;    ///< unit tangents arriving and leaving
};

/// The corners of a sweep: the joints of `chain` where the end tangent of one piece and the
/// start tangent of the next turn by more than kCornerAngle, at the samples of `sweep` whose
/// parameter is the joint's (the tessellations emit every piece's ends). A closed sweep's seam
/// (the last piece's end to the first's start) counts as a joint at sample 0.
/// @throws InputError for a turn beyond kMaxCornerTurn, naming the joint and its angle.
std::vector<SweepCorner> find_corners(const BezierChain& chain, const Polyline& sweep, bool closed);

/// The smallest rotation taking unit `from` to unit `to` (about from x to; the identity when
/// they coincide). @pre from and to are not opposite.
Eigen::Matrix3d corner_rotation(const Vec3& from, const Vec3& to);

/// Profile offset `o` (perpendicular to `in`) moved along `in` into the mitre plane of the
/// corner from `in` to `out`.
Vec3 mitre_offset(const Vec3& o, const Vec3& in, const Vec3& out);

}  // namespace crossdiv
