#include "crossdiv/surfaces/sweep_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "crossdiv/curves/cubic_spline.h"
#include "crossdiv/error.h"

namespace crossdiv {

namespace {

Polyline sample(const CurveRecord& r, const SweepOptions& o) {
    TessellationOptions t;
    if (o.adaptive) {
        t.mode = TessellationMode::Distance;
        t.tol = o.tol * o.curve_share;
    }
    return tessellate_record(r, t);
}

/// The largest distance of a profile from the y axis (of its control points, which bound the
/// curve; a primitive's samples at the record's steps).
double profile_radius(const CurveRecord& r) {
    double radius = 0;
    if (r.type == CurveType::Primitive) {
        for (const Vec3& p : tessellate_record(r, {}).positions) radius = std::max(radius, std::abs(p.x()));
    } else {
        for (const Vec3& p : r.chain().points) radius = std::max(radius, std::abs(p.x()));
    }
    return radius;
}

/// Fewest slices (>= 3) whose chord sags at most `tol` below a circle of radius r.
int slices_for(double r, double tol) {
    if (r <= 0) return 3;
    if (tol >= r) return 3;
    return std::max(3, static_cast<int>(std::ceil(std::numbers::pi / std::acos(1 - tol / r))));
}

}  // namespace

ExactSurface exact_revolution(const CurveRecord& profile) {
    return [curve = record_evaluator(profile)](double t, double a) {
        const Vec3 p = curve(t).position;
        return Vec3(p.x() * std::cos(a), p.y(), -p.x() * std::sin(a));
    };
}

SweepSurface build_sweep(const CurveFile& file, int index, const SweepOptions& o) {
    if (o.adaptive && !(o.tol > 0)) throw InputError("adaptive sweeps need a positive tolerance");
    if (o.adaptive && !(o.curve_share > 0 && o.curve_share < 1)) throw InputError("curve_share must be in (0, 1)");
    const SweepRecord& rec = file.sweeps.at(index);
    SweepSurface out;
    out.record = rec;
    out.name = rec.name.empty() ? std::string("#").append(std::to_string(index)).append(rec.kind == SweepRecord::Kind::Revolution ? " srev" : " gcyl")
                                : rec.name;
    const CurveRecord& profile = file.curves.at(rec.profile_index);
    try {
        RevolutionOptions ro;
        ro.convention = RevolutionConvention::C3100;
        ro.slices = rec.steps;
        const bool adaptive_revolution = rec.kind == SweepRecord::Kind::Revolution && o.adaptive;
        if (adaptive_revolution) ro.slices = slices_for(profile_radius(profile), o.tol * (1 - o.curve_share));
        // The slices spend (1 - share) tol at the profile's widest radius, and at radius x only
        // x (1 - cos(pi / n)): a spline profile takes, wherever it is, what they leave.
        const Polyline p = adaptive_revolution && profile.type != CurveType::Primitive
                               ? tessellate_distance(profile.chain(),
                                                     DistanceBudget{o.tol, 1 - std::cos(std::numbers::pi / ro.slices)})
                               : sample(profile, o);
        const bool profile_closed = profile.closed();
        if (rec.kind == SweepRecord::Kind::Revolution) {
            require_surface_size(2LL * std::max(p.size() - 1, 0) * std::max(ro.slices, 3), o.max_triangles,
                                 "the surface of revolution");
            out.grid = revolution_grid(p, profile_closed, ro);
            out.closed = profile_encloses(p.positions, kWeldRelative * bounding_box_diagonal(p.positions));
        } else {
            const CurveRecord& sweep = file.curves.at(rec.sweep_index);
            const Polyline s = sample(sweep, o);
            require_surface_size(2LL * std::max(p.size() - 1, 0) * std::max(s.size() - 1, 0), o.max_triangles,
                                 "the generalized cylinder");
            std::vector<double> scale;
            if (rec.scale_index >= 0) {
                // The scale curve is read by the sweep's normalized parameter: sweep sample
                // at fraction f of the sweep's parameter range takes the scale curve's y at
                // the same fraction of its own range. Neither curve's control point count
                // matters, and a uniform and an adaptive sweep see the same scale function.
                const CurveRecord& sc = file.curves.at(rec.scale_index);
                const auto size = record_evaluator(sc);
                const double s_end = record_param_end(sweep), c_end = record_param_end(sc);
                for (double u : s.params) scale.push_back(size(u / s_end * c_end).position.y());
            }
            CylinderOptions co;
            co.frames = o.frames;
            co.close_frames = o.close_frames;
            const bool sweep_closed = sweep.closed();
            // A spline sweep may be only C0: its corners are mitred (sweep_corners.h).
            if (sweep.type != CurveType::Primitive) out.corners = find_corners(sweep.chain(), s, sweep_closed);
            out.grid = cylinder_grid(p, profile_closed, s, sweep_closed, co, scale, &out.closure_angle, out.corners);
            out.closed = profile_closed && sweep_closed && o.close_frames;
        }
        out.surface = mesh_sweep(out.grid);
    } catch (const ParseError&) {
        throw;
    } catch (const InputError& e) {
        throw ParseError(file.path, rec.line, out.name + ": " + e.what());
    }
    return out;
}

}  // namespace crossdiv
