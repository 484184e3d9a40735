#pragma once
/// @file
/// Surfaces of revolution of a profile curve in the xy-plane, in the two course conventions.
///
/// Outside: when the profile encloses a region, either as a closed curve or with both ends
/// on the axis (the wineglass: the axis closes it), the surface bounds the solid swept by
/// that region and the normals point out of it; the region's side is read from the sign of
/// its area (shoelace, closed along the axis). Otherwise (a profile that encloses nothing,
/// such as srev/norm.swp) the CS-C3100 convention holds: the curve's normals point to the
/// left of travel, and the surface takes them reversed (to the right of travel), which is
/// outward for a profile at x <= 0 travelling downward.

#include <span>

#include "crossdiv/curves/tessellation.h"
#include "crossdiv/surfaces/sweep_mesh.h"

namespace crossdiv {

/// Which course's construction.
enum class RevolutionConvention {
    C3100,   ///< CS-C3100: profile at x <= 0, swept counterclockwise about +y (seen from +y):
             ///< (x, y) -> (x cos a, y, -x sin a), a = 2 pi i / slices
    CS4620,  ///< Cornell CS4620: about +z: (x, y) -> scale (x cos a, x sin a, y), with as many
             ///< equal slices as keep the angle between slices at most max_angle
};
std::string_view to_string(RevolutionConvention c);

struct RevolutionOptions {
    RevolutionConvention convention = RevolutionConvention::C3100;
    int slices = 0;         ///< C3100: slices around the axis (the srev record's STEPS)
    double max_angle = 0;   ///< CS4620: radians, > 0
    double scale = 1;       ///< CS4620: uniform scale, > 0
};

/// The slices a set of options asks for. @throws InputError on a non-positive value.
int revolution_slices(const RevolutionOptions& options);

/// Whether the profile encloses a region (closed, or both ends within `tol` of the axis):
/// then the revolved surface is closed.
bool profile_encloses(std::span<const Vec3> profile, double tol);

/// The grid of a surface of revolution: ring i is the profile rotated by 2 pi i / slices
/// (closed_sweep, so the seam is shared, not duplicated). A profile point within
/// kWeldRelative of the axis is put exactly on it, so that its copies coincide (a pole).
/// Vertex normals are the profile's normals rotated: a rotation is its own inverse
/// transpose, and a uniform scale changes no direction. `closed_profile` says the profile's
/// last sample repeats its first (it is then dropped).
/// @throws InputError if the profile is not in the xy-plane, has fewer than 2 samples, or
///         crosses the axis (samples on both sides: the surface would intersect itself),
///         naming the sample.
SweepGrid revolution_grid(const Polyline& profile, bool closed_profile, const RevolutionOptions& options);

/// revolution_grid meshed with mesh_sweep.
SurfaceMesh revolve(const Polyline& profile, bool closed_profile, const RevolutionOptions& options);

/// The outward normals of a planar profile in its plane (unit, z = 0), by the rule in this
/// file's header: right of travel, or left when `encloses` and the enclosed region's area
/// is negative. The shoelace closes the polygon from the last sample to the first: along
/// the axis when both ends are on it, a zero-length step for a closed profile.
std::vector<Vec3> outward_profile_normals(const Polyline& profile, bool encloses);

/// Signed area of the closed polygon through the points' x and y (positive counterclockwise).
double signed_area_xy(std::span<const Vec3> points);

}  // namespace crossdiv
