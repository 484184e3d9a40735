#pragma once
/// @file
/// The surfaces an SWP file's srev and gcyl records describe, built from its curve records.

#include <string>

#include "crossdiv/curves/curve_record.h"
#include "crossdiv/surfaces/generalized_cylinder.h"
#include "crossdiv/surfaces/revolution.h"

namespace crossdiv {

/// How to sample the curves of a sweep.
struct SweepOptions {
    FrameMethod frames = FrameMethod::Recursive;  ///< gcyl: recursive (the seed's) or DoubleReflection
    bool close_frames = true;                     ///< gcyl: distribute the closure angle of closed sweeps
    /// Uniform (false): every curve with its record's STEPS, srev with the record's slices.
    /// Adaptive (true): gcyl's curves by the distance mode at curve_share * tol. srev takes the
    /// fewest slices n whose chord stays within (1 - curve_share) * tol of the widest circle
    /// (radius r: r (1 - cos(pi / n))), and a spline profile the distance mode under the budget
    /// the slices leave at each radius x, tol - x (1 - cos(pi / n)) (DistanceBudget): at the
    /// rim curve_share * tol, near the axis almost all of it; the two parts add up to at most
    /// about tol everywhere. A primitive profile (circ) takes curve_share * tol.
    bool adaptive = false;
    double tol = 0;            ///< absolute, for adaptive
    double curve_share = 0.5;  ///< adaptive: the part of tol left to the curves at the widest radius, in (0, 1)
    long long max_triangles = kDefaultMaxSurfaceTriangles;  ///< refuse a larger surface before building it
};

/// One built surface.
struct SweepSurface {
    std::string name;        ///< the record's name, or "#k srev" for an anonymous one
    SweepRecord record;
    SweepGrid grid;
    SurfaceMesh surface;
    bool closed = false;     ///< whether the construction is closed (must then be watertight)
    double closure_angle = 0;  ///< gcyl over a closed sweep: the frames' mismatch before distribution (rad)
    std::vector<SweepCorner> corners;  ///< gcyl: the sweep's mitred corners
};

/// Builds record `index` of file.sweeps.
/// @throws ParseError naming the file and the record's line when its curves cannot make the
///         surface (a profile that is not planar, crosses the axis, or a scale curve that is
///         not positive), InputError for bad options.
SweepSurface build_sweep(const CurveFile& file, int index, const SweepOptions& options);

/// The exact surface of revolution a C3100 srev grid samples, for grid_deviation.
ExactSurface exact_revolution(const CurveRecord& profile);

}  // namespace crossdiv
