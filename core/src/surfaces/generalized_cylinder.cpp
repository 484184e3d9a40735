#include "crossdiv/surfaces/generalized_cylinder.h"

#include <algorithm>
#include <cmath>

#include "crossdiv/error.h"
#include "crossdiv/surfaces/revolution.h"

namespace crossdiv {

namespace {
/// The tilt divides by the step's component along T; a step that barely moves along T (the
/// sweep stops, or turns back) says nothing about the tilt, and m is kept as it is.
constexpr double kMinStepAlongT = 1e-3;
}  // namespace

namespace {

Frame rotated(const Eigen::Matrix3d& r, const Frame& f) { return {r * f.T, r * f.N, r * f.B}; }

/// The method's frames run by run between corners: each run's tangents are the polyline's,
/// except that it leaves a corner along the corner's `out` and arrives at the next along its
/// `in`; each run starts from the previous run's last frame turned by the corner's rotation.
/// A closed sweep's seam corner is sample 0: the last sample keeps the frame arriving there.
std::vector<Frame> frames_with_corners(const Polyline& sweep, FrameMethod method, std::span<const SweepCorner> corners) {
    const int n = sweep.size();
    std::vector<int> at(n, -1);  // corner index at each sample
    for (size_t c = 0; c < corners.size(); ++c) at[corners[c].sample] = static_cast<int>(c);
    std::vector<Frame> frames(n);
    int start = 0;
    Vec3 initial_b = initial_binormal(at[0] >= 0 ? corners[at[0]].out : sweep.tangents[0]);
    while (start < n - 1) {
        int end = start + 1;
        while (end < n - 1 && at[end] < 0) ++end;
        std::vector<Vec3> t(sweep.tangents.begin() + start, sweep.tangents.begin() + end + 1);
        if (at[start] >= 0) t.front() = corners[at[start]].out;
        if (at[end] >= 0) t.back() = corners[at[end]].in;
        if (end == n - 1 && at[0] >= 0) t.back() = corners[at[0]].in;  // arriving at the seam
        const std::vector<Frame> run = curve_frames(std::span<const Vec3>(sweep.positions).subspan(start, end - start + 1), t,
                                                    method, initial_b);
        std::copy(run.begin(), run.end(), frames.begin() + start);
        if (at[end] >= 0) {
            const SweepCorner& c = corners[at[end]];
            frames[end] = rotated(corner_rotation(c.in, c.out), run.back());
            initial_b = frames[end].B;
        }
        start = end;
    }
    return frames;
}

}  // namespace

SweepFrames sweep_frames(const Polyline& sweep, bool closed_sweep, const CylinderOptions& o,
                         std::span<const SweepCorner> corners) {
    if (o.frames == FrameMethod::Planar)
        throw InputError("a generalized cylinder needs space-curve frames (recursive or rmf), not planar ones");
    SweepFrames f;
    f.frames = corners.empty() ? curve_frames(sweep.positions, sweep.tangents, o.frames)
                               : frames_with_corners(sweep, o.frames, corners);
    // A seam corner: the frame arriving at the last sample, turned by the corner's rotation, is
    // what must meet the first frame.
    const SweepCorner* seam = !corners.empty() && corners.front().sample == 0 ? &corners.front() : nullptr;
    if (seam && f.frames.size() > 1) f.frames.back() = rotated(corner_rotation(seam->in, seam->out), f.frames.back());
    if (closed_sweep && f.frames.size() > 1) {
        f.closure_angle = closure_angle(f.frames);
        if (o.close_frames) {
            distribute_closure(sweep.positions, f.frames, f.closure_angle);
            // The last sample is the first; after distribution its frame equals the first's
            // up to rounding, so take the first's exactly and the seam closes by index.
            f.frames.back() = f.frames.front();
        }
    }
    // The frames arriving: the leaving ones but at corners, where R^T turns them back (after the
    // distribution, so that they follow it).
    f.arriving = f.frames;
    for (const SweepCorner& c : corners)
        f.arriving[c.sample] = rotated(corner_rotation(c.in, c.out).transpose(), f.frames[c.sample]);
    if (seam && f.frames.size() > 1)
        f.arriving.back() = rotated(corner_rotation(seam->in, seam->out).transpose(), f.frames.back());
    return f;
}

SweepGrid cylinder_grid(const Polyline& profile, bool closed_profile, const Polyline& sweep, bool closed_sweep,
                        const CylinderOptions& o, std::span<const double> scale, double* closure_angle,
                        std::span<const SweepCorner> corners) {
    if (profile.size() < 2 || sweep.size() < 2)
        throw InputError("a generalized cylinder needs at least 2 profile and 2 sweep samples");
    if (!scale.empty() && scale.size() != static_cast<size_t>(sweep.size()))
        throw InputError(std::to_string(scale.size()) + " scale values for " + std::to_string(sweep.size()) + " sweep samples");
    const double tol = kWeldRelative * bounding_box_diagonal(profile.positions);
    for (int j = 0; j < profile.size(); ++j)
        if (std::abs(profile.positions[j].z()) > tol)
            throw InputError("profile sample " + std::to_string(j) + " has z = " + std::to_string(profile.positions[j].z()) +
                             ": a generalized cylinder's profile lies in the xy-plane");
    for (size_t i = 0; i < scale.size(); ++i)
        if (!(scale[i] > 0))
            throw InputError("the scale at sweep sample " + std::to_string(i) + " is " + std::to_string(scale[i]) +
                             "; scales must be positive (zero pinches the tube, negative turns it inside out)");
    const SweepFrames sf = sweep_frames(sweep, closed_sweep, o, corners);
    std::vector<char> corner(static_cast<size_t>(sweep.size()), 0);
    for (const SweepCorner& c : corners) corner[c.sample] = 1;
    if (closure_angle) *closure_angle = sf.closure_angle;
    // Without closing the frames, a closed sweep's last ring is kept as its own ring.
    const bool wrap = closed_sweep && o.close_frames;
    const std::vector<Vec3> normals2 = outward_profile_normals(profile, closed_profile);
    SweepGrid g;
    g.rings = wrap ? sweep.size() - 1 : sweep.size();
    g.ring_size = closed_profile ? profile.size() - 1 : profile.size();
    g.closed_profile = closed_profile;
    g.closed_sweep = wrap;
    g.profile_params = profile.params;
    g.sweep_params = sweep.params;
    g.positions.reserve(static_cast<size_t>(g.rings) * g.ring_size);
    g.normals.reserve(g.positions.capacity());
    for (int i = 0; i < g.rings; ++i) {
        const Frame& f = sf.frames[i];
        const Frame& in = sf.arriving[i];
        const double s = scale.empty() ? 1.0 : scale[i];
        for (int j = 0; j < g.ring_size; ++j) {
            const Vec3& p = profile.positions[j];
            if (corner[i])  // in the arriving frame, moved into the mitre plane
                g.positions.push_back(sweep.positions[i] + s * mitre_offset(p.x() * in.N + p.y() * in.B, in.T, f.T));
            else
                g.positions.push_back(sweep.positions[i] + s * (p.x() * f.N + p.y() * f.B));
        }
    }
    // The profile's normal placed in the frame, m = nx N + ny B, is perpendicular to the
    // surface along the profile, but along the sweep the surface also moves within the
    // normal plane where the scale changes or the frame twists (the recursive frames do).
    // The normal is m tilted along T until it is perpendicular to the surface's step along
    // the sweep too (central differences of the rings; one-sided at open ends).
    auto ring = [&](int i) { return wrap ? (i + g.rings) % g.rings : std::clamp(i, 0, g.rings - 1); };
    for (int i = 0; i < g.rings; ++i) {
        const Frame& f = sf.frames[i];
        for (int j = 0; j < g.ring_size; ++j) {
            const Vec3& n2 = normals2[j];
            const Vec3 m = n2.x() * f.N + n2.y() * f.B;
            if (corner[i]) {  // a crease: between the two tubes' normals
                const Frame& in = sf.arriving[i];
                g.normals.push_back((m + n2.x() * in.N + n2.y() * in.B).normalized());
                continue;
            }
            const Vec3 d = g.at(ring(i + 1), j) - g.at(ring(i - 1), j);
            const double along = f.T.dot(d);
            const Vec3 n = std::abs(along) > kMinStepAlongT * d.norm() ? Vec3(m - (m.dot(d) / along) * f.T) : m;
            g.normals.push_back(n.normalized());
        }
    }
    return g;
}

}  // namespace crossdiv
