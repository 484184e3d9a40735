#include "crossdiv/surfaces/sweep_corners.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/error.h"

namespace crossdiv {

namespace {

double turn(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

}  // namespace

std::vector<SweepCorner> find_corners(const BezierChain& chain, const Polyline& sweep, bool closed) {
    std::vector<SweepCorner> corners;
    const int n = chain.num_segments();
    if (n == 0 || sweep.size() == 0) return corners;
    // Joint k is between piece k - 1 and piece k; joint 0 is a closed sweep's seam.
    for (int k = closed ? 0 : 1; k < n; ++k) {
        const Vec3 in = bezier_unit_tangent(chain.segment((k + n - 1) % n), 1.0);
        const Vec3 out = bezier_unit_tangent(chain.segment(k), 0.0);
        const double angle = turn(in, out);
        if (!(angle > kCornerAngle)) continue;
        if (angle > kMaxCornerTurn)
            throw InputError("the sweep turns by " + std::to_string(angle * 180 / 3.14159265358979323846) +
                             " degrees at joint " + std::to_string(k) + " (parameter " + std::to_string(k) +
                             "); a mitred corner needs a turn below 170 degrees");
        // The parameters increase along the polyline, and each piece's ends are emitted exactly.
        const auto it = std::lower_bound(sweep.params.begin(), sweep.params.end(), static_cast<double>(k));
        if (it == sweep.params.end() || *it != static_cast<double>(k))
            throw InputError("the sweep's tessellation has no sample at joint " + std::to_string(k));
        corners.push_back({static_cast<int>(it - sweep.params.begin()), in, out});
    }
    return corners;
}

Eigen::Matrix3d corner_rotation(const Vec3& from, const Vec3& to) {
    const Vec3 axis = from.cross(to);
    const double s = axis.norm(), c = from.dot(to);
    if (s == 0) return Eigen::Matrix3d::Identity();
    // Rodrigues with the unnormalized axis: R = I + [a]x + [a]x^2 (1 - c) / s^2.
    Eigen::Matrix3d k;
    k << 0, -axis.z(), axis.y(), axis.z(), 0, -axis.x(), -axis.y(), axis.x(), 0;
    return Eigen::Matrix3d::Identity() + k + k * k * ((1 - c) / (s * s));
}

Vec3 mitre_offset(const Vec3& o, const Vec3& in, const Vec3& out) {
    const Vec3 m = (in + out).normalized();
    return o - (o.dot(m) / in.dot(m)) * in;
}

}  // namespace crossdiv
