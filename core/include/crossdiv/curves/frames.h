#pragma once
/// @file
/// Local coordinate frames along a sampled curve: tangent T, normal N, binormal B.
///
/// - Planar curves (CS-C3100 seed, appendix A.1): B = +z and N = B x T, so N lies to the
///   left of the direction of travel (inward on a counterclockwise circle, as the seed's
///   evalCircle). The CS4620 seed puts N on the right; that is the `Right` side, with B = -z
///   so that (T, N, B) stays right-handed.
/// - Space curves, `Recursive` (CS-C3100 seed, appendix A.2): N_i = normalize(B_{i-1} x T_i),
///   B_i = normalize(T_i x N_i), started from B_{-1} (see initial_binormal). It projects the
///   previous frame onto the new normal plane: first-order accurate as a rotation-minimizing
///   frame, and a closed curve's frame need not close.
/// - Space curves, `DoubleReflection`: the rotation-minimizing frame of W. Wang, B. Juettler,
///   D. Zheng, Y. Liu, "Computation of Rotation Minimizing Frames", ACM TOG 27(1), 2008,
///   Algorithm 1 (two reflections per step, global error O(h^4)).
///
/// A closed curve's frame generally does not close after one lap (holonomy); closure_angle
/// measures the mismatch and distribute_closure spreads it along arc length.

#include <Eigen/Geometry>  // cross products
#include <span>
#include <string_view>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// One frame: unit T, N, B with B = T x N.
struct Frame {
    Vec3 T, N, B;
};

/// How N is chosen.
enum class FrameMethod {
    Planar,            ///< B fixed to +z (or -z for NormalSide::Right); curves in the xy-plane
    Recursive,         ///< the CS-C3100 seed's recursive update
    DoubleReflection,  ///< rotation-minimizing, Wang et al. 2008
};

/// Which side of the travel direction a planar curve's normal points to.
enum class NormalSide {
    Left,   ///< N = +z x T: CS-C3100 (normals inward on a counterclockwise loop)
    Right,  ///< N = T x +z: CS4620 (normals outward on a counterclockwise loop)
};

/// "planar" / "recursive" / "rmf".
std::string_view to_string(FrameMethod m);

/// The binormal the space-curve methods start from, B_{-1}: +z, so that a planar curve in
/// the xy-plane gets the planar frame, unless T_0 is within 30 degrees of the z-axis; then
/// the coordinate axis least aligned with T_0 (the seed asks for any B not parallel to T).
Vec3 initial_binormal(const Vec3& t0);

/// Frames at the samples. `tangents` are unit (zero tangents keep the previous frame's N).
/// @param initial_b B_{-1} for the space-curve methods (ignored by Planar).
/// @throws InputError if positions and tangents differ in size.
std::vector<Frame> curve_frames(std::span<const Vec3> positions, std::span<const Vec3> tangents, FrameMethod method,
                                NormalSide side = NormalSide::Left);
std::vector<Frame> curve_frames(std::span<const Vec3> positions, std::span<const Vec3> tangents, FrameMethod method,
                                const Vec3& initial_b);

/// Signed angle (radians, in (-pi, pi]) that rotates the last frame's N about the first T
/// onto the first frame's N, after projecting it onto the first normal plane: 0 when the
/// frame closes. Meaningful for a closed curve (first and last sample coincide).
double closure_angle(std::span<const Frame> frames);

/// Rotates frame i about its T by angle * s_i / s_total (s = arc length of the polyline), so
/// that the last frame's N matches the first's after closure_angle(frames) is passed in.
void distribute_closure(std::span<const Vec3> positions, std::span<Frame> frames, double angle);

/// The largest deviation from orthonormality over all frames: max | |X| - 1 | over the
/// three vectors and | X . Y | over the three pairs, and | (T x N) - B |.
double max_orthonormality_error(std::span<const Frame> frames);

}  // namespace crossdiv
