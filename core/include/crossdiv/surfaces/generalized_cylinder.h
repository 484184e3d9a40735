#pragma once
/// @file
/// Generalized cylinders (CS-C3100 seed, appendix B.2): a planar profile placed along a 3D
/// sweep curve in the sweep's frames, profile point (x, y) at sweep sample i going to
/// V_i + s_i (x N_i + y B_i). Outside as for revolution: a closed profile's outward side
/// (from its area's sign), otherwise the right of travel.

#include <span>

#include "crossdiv/curves/frames.h"
#include "crossdiv/curves/tessellation.h"
#include "crossdiv/surfaces/sweep_corners.h"
#include "crossdiv/surfaces/sweep_mesh.h"

namespace crossdiv {

struct CylinderOptions {
    FrameMethod frames = FrameMethod::Recursive;  ///< the seed's recursive update, or DoubleReflection (RMF)
    /// For a closed sweep: rotate the frames about T by the closure angle spread over arc
    /// length (distribute_closure), so that the last frame is the first and the tube closes
    /// without a seam. Without it a closed sweep's last ring is kept apart (an open seam).
    bool close_frames = true;
};

/// A sweep's samples and the frames the cylinder uses, after closure.
struct SweepFrames {
    std::vector<Frame> frames;    ///< leaving each sample
    std::vector<Frame> arriving;  ///< arriving at each sample: the same but at corners, R^T times the leaving one
    double closure_angle = 0;     ///< radians, before distribution (0 for an open sweep)
};

/// Frames along the sweep (FrameMethod::Planar is refused: a sweep is a space curve). Between
/// corners each run of samples has the method's frames; at a corner the next run starts from
/// the corner's rotation of the frame arriving there (sweep_corners.h), so no twist is added.
/// A closed sweep's closure angle is measured after its seam corner's rotation, if it has one.
/// @throws InputError for Planar or when sizes differ.
SweepFrames sweep_frames(const Polyline& sweep, bool closed_sweep, const CylinderOptions& options,
                         std::span<const SweepCorner> corners = {});

/// The grid of a generalized cylinder. `closed_*` say the last sample repeats the first.
/// `scale`, when not empty, holds one profile scale per sweep sample (> 0). When
/// `closure_angle` is given it receives the frames' mismatch before distribution
/// (SweepFrames::closure_angle).
/// @throws InputError if the profile is not planar in xy, a scale is not positive, or the
///         sizes disagree, naming the sample.
/// At a corner of the sweep the ring is mitred (mitre_offset) and its normals are the
/// normalized sum of the arriving and leaving tubes' normals.
SweepGrid cylinder_grid(const Polyline& profile, bool closed_profile, const Polyline& sweep, bool closed_sweep,
                        const CylinderOptions& options, std::span<const double> scale = {}, double* closure_angle = nullptr,
                        std::span<const SweepCorner> corners = {});

}  // namespace crossdiv
