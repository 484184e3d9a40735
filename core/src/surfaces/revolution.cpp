#include "crossdiv/surfaces/revolution.h"

#include <cmath>
#include <numbers>

#include "crossdiv/error.h"

namespace crossdiv {

std::string_view to_string(RevolutionConvention c) { return c == RevolutionConvention::C3100 ? "c3100" : "cs4620"; }

int revolution_slices(const RevolutionOptions& o) {
    if (o.convention == RevolutionConvention::C3100) {
        if (o.slices < 3) throw InputError("a surface of revolution needs at least 3 slices, got " + std::to_string(o.slices));
        return o.slices;
    }
    if (!(o.max_angle > 0) || !(o.scale > 0))
        throw InputError("CS4620 revolution needs max_angle > 0 and scale > 0");
    return std::max(3, static_cast<int>(std::ceil(2 * std::numbers::pi / o.max_angle - 1e-9)));
}

double signed_area_xy(std::span<const Vec3> p) {
    double twice = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const Vec3& a = p[i];
        const Vec3& b = p[(i + 1) % p.size()];
        twice += a.x() * b.y() - b.x() * a.y();
    }
    return twice / 2;
}

bool profile_encloses(std::span<const Vec3> p, double tol) {
    if (p.size() < 3) return false;
    if ((p.front() - p.back()).norm() <= tol) return true;
    return std::abs(p.front().x()) <= tol && std::abs(p.back().x()) <= tol;
}

std::vector<Vec3> outward_profile_normals(const Polyline& profile, bool encloses) {
    const double side = encloses && signed_area_xy(profile.positions) < 0 ? -1.0 : 1.0;
    std::vector<Vec3> n(profile.size());
    for (int j = 0; j < profile.size(); ++j) {
        const Vec3& t = profile.tangents[j];
        const Vec3 right(t.y(), -t.x(), 0);
        const double len = right.norm();
        n[j] = len > 0 ? Vec3(side * right / len) : Vec3::Zero();
    }
    return n;
}

SweepGrid revolution_grid(const Polyline& profile_in, bool closed_profile, const RevolutionOptions& o) {
    const int slices = revolution_slices(o);
    if (profile_in.size() < 2) throw InputError("a profile needs at least 2 samples, got " + std::to_string(profile_in.size()));
    Polyline profile = profile_in;
    const double tol = kWeldRelative * bounding_box_diagonal(profile.positions);
    int left = -1, right = -1;
    for (int j = 0; j < profile.size(); ++j) {
        Vec3& p = profile.positions[j];
        if (std::abs(p.z()) > tol)
            throw InputError("profile sample " + std::to_string(j) + " has z = " + std::to_string(p.z()) +
                             ": a profile of revolution lies in the xy-plane");
        p.z() = 0;
        if (std::abs(p.x()) <= tol) p.x() = 0;  // on the axis: every slice's copy is the same point
        if (p.x() < 0 && left < 0) left = j;
        if (p.x() > 0 && right < 0) right = j;
    }
    if (left >= 0 && right >= 0)
        throw InputError("the profile crosses the axis of revolution (sample " + std::to_string(left) + " has x < 0, sample " +
                         std::to_string(right) + " has x > 0): the surface would intersect itself");
    const std::vector<Vec3> normals = outward_profile_normals(profile, profile_encloses(profile.positions, tol));
    SweepGrid g;
    g.rings = slices;
    g.ring_size = closed_profile ? profile.size() - 1 : profile.size();
    g.closed_profile = closed_profile;
    g.closed_sweep = true;
    g.profile_params = profile.params;
    for (int i = 0; i <= slices; ++i) g.sweep_params.push_back(2 * std::numbers::pi * i / slices);
    g.positions.reserve(static_cast<size_t>(slices) * g.ring_size);
    g.normals.reserve(g.positions.capacity());
    const bool c3100 = o.convention == RevolutionConvention::C3100;
    const double scale = c3100 ? 1.0 : o.scale;
    for (int i = 0; i < slices; ++i) {
        const double a = g.sweep_params[i], c = std::cos(a), s = std::sin(a);
        for (int j = 0; j < g.ring_size; ++j) {
            const Vec3& p = profile.positions[j];
            const Vec3& n = normals[j];
            if (c3100) {
                g.positions.emplace_back(p.x() * c, p.y(), -p.x() * s);
                g.normals.emplace_back(n.x() * c, n.y(), -n.x() * s);
            } else {
                g.positions.push_back(scale * Vec3(p.x() * c, p.x() * s, p.y()));
                g.normals.emplace_back(n.x() * c, n.x() * s, n.y());
            }
        }
    }
    return g;
}

SurfaceMesh revolve(const Polyline& profile, bool closed_profile, const RevolutionOptions& options) {
    return mesh_sweep(revolution_grid(profile, closed_profile, options));
}

}  // namespace crossdiv
