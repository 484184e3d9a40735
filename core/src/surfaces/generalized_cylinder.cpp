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

SweepFrames sweep_frames(const Polyline& sweep, bool closed_sweep, const CylinderOptions& o) {
    if (o.frames == FrameMethod::Planar)
        throw InputError("a generalized cylinder needs space-curve frames (recursive or rmf), not planar ones");
    SweepFrames f;
    f.frames = curve_frames(sweep.positions, sweep.tangents, o.frames);
    if (closed_sweep && f.frames.size() > 1) {
        f.closure_angle = closure_angle(f.frames);
        if (o.close_frames) {
            distribute_closure(sweep.positions, f.frames, f.closure_angle);
            // The last sample is the first; after distribution its frame equals the first's
            // up to rounding, so take the first's exactly and the seam closes by index.
            f.frames.back() = f.frames.front();
        }
    }
    return f;
}

SweepGrid cylinder_grid(const Polyline& profile, bool closed_profile, const Polyline& sweep, bool closed_sweep,
                        const CylinderOptions& o, std::span<const double> scale, double* closure_angle) {
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
    const SweepFrames sf = sweep_frames(sweep, closed_sweep, o);
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
        const double s = scale.empty() ? 1.0 : scale[i];
        for (int j = 0; j < g.ring_size; ++j) {
            const Vec3& p = profile.positions[j];
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
            const Vec3 d = g.at(ring(i + 1), j) - g.at(ring(i - 1), j);
            const double along = f.T.dot(d);
            const Vec3 n = std::abs(along) > kMinStepAlongT * d.norm() ? Vec3(m - (m.dot(d) / along) * f.T) : m;
            g.normals.push_back(n.normalized());
        }
    }
    return g;
}

}  // namespace crossdiv
