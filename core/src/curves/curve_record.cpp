#include "crossdiv/curves/curve_record.h"

#include <cmath>

#include "crossdiv/curves/bessel_overhauser.h"
#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/primitive_tessellation.h"
#include "crossdiv/error.h"

namespace crossdiv {

std::string_view to_string(CurveType t) {
    switch (t) {
        case CurveType::BezierChain: return "bezier-chain";
        case CurveType::BSpline: return "bspline";
        case CurveType::CatmullRom: return "catmull-rom";
        case CurveType::CatmullRomClosed: return "catmull-rom-closed";
        case CurveType::Tcb: return "tcb";
        case CurveType::TcbClosed: return "tcb-closed";
        case CurveType::BesselOverhauser: return "bessel-overhauser";
        case CurveType::BesselOverhauserClosed: return "bessel-overhauser-closed";
        case CurveType::KappaClosed: return "kappa-closed";
        case CurveType::CameraPath: return "camera-path";
        case CurveType::Bezier: return "bezier";
        case CurveType::Primitive: return "primitive";
    }
    return "?";
}

std::string CurveRecord::label(int index) const {
    return name.empty() ? std::string("#").append(std::to_string(index)).append(" ").append(keyword) : name;
}

BezierChain CurveRecord::chain() const {
    switch (type) {
        case CurveType::BezierChain: return bezier_chain(control);
        case CurveType::BSpline: return bspline_chain(control);
        case CurveType::CatmullRom: return catmull_rom_chain(control, false);
        case CurveType::CatmullRomClosed: return catmull_rom_chain(control, true);
        case CurveType::Tcb: return kochanek_bartels_chain(control, tcb, false);
        case CurveType::TcbClosed: return kochanek_bartels_chain(control, tcb, true);
        case CurveType::BesselOverhauser: return bessel_overhauser_chain(control, false);
        case CurveType::BesselOverhauserClosed: return bessel_overhauser_chain(control, true);
        case CurveType::KappaClosed: return kappa ? kappa->chain : converged_kappa_curve(control).chain;
        case CurveType::CameraPath: return bezier_chain(control);
        case CurveType::Bezier: return single_bezier(control);
        case CurveType::Primitive: break;
    }
    throw InputError(keyword + " is a primitive, not a spline: it has no control points");
}

bool CurveRecord::wraps() const {
    return type == CurveType::CatmullRomClosed || type == CurveType::TcbClosed || type == CurveType::BesselOverhauserClosed ||
           type == CurveType::KappaClosed;
}

bool CurveRecord::closed() const {
    if (type == CurveType::Primitive) return primitive.closed();
    if (wraps()) return true;
    const BezierChain c = chain();
    return c.points.front() == c.points.back();
}

namespace {

/// Largest turn of the tangent between consecutive samples.
double max_turn(const Polyline& p) {
    double worst = 0;
    for (int i = 0; i + 1 < p.size(); ++i)
        worst = std::max(worst, std::atan2(p.tangents[i].cross(p.tangents[i + 1]).norm(), p.tangents[i].dot(p.tangents[i + 1])));
    return worst;
}

/// A primitive by angle: uniform steps, doubled from the record's until no edge turns the
/// tangent by more than the tolerance (the turn of a uniform step is the same all along a
/// circle or helix). 2^20 steps of any primitive here is far below any tolerance the readers
/// accept, so the cap only guards against a bug.
Polyline sample_primitive_by_angle(const CurveRecord& r, double angle_tol) {
    constexpr int kMaxSteps = 1 << 20;
    if (!std::isfinite(angle_tol) || angle_tol <= 0.0) throw InputError(r.keyword + ": the angle tolerance must be positive");
    for (int steps = std::max(1, r.steps);; steps *= 2) {
        Polyline p = sample_primitive(r.primitive, steps);
        if (max_turn(p) <= angle_tol || steps >= kMaxSteps) return p;
    }
}

}  // namespace

Polyline tessellate_record(const CurveRecord& r, const TessellationOptions& o) {
    if (r.type == CurveType::Primitive) {
        if (o.mode == TessellationMode::Uniform) return sample_primitive(r.primitive, o.intervals.value_or(r.steps));
        if (o.mode == TessellationMode::Angle) return sample_primitive_by_angle(r, o.angle_tol);
        return tessellate_primitive_distance(r.primitive, o.tol);
    }
    const BezierChain c = r.chain();
    switch (o.mode) {
        case TessellationMode::Uniform: return tessellate_uniform(c, o.intervals.value_or(r.steps));
        case TessellationMode::Angle: return tessellate_angle(c, o.angle_tol);
        case TessellationMode::Distance: return tessellate_distance(c, o.tol);
    }
    throw std::logic_error("unknown tessellation mode");
}

std::function<ChainJet(double)> record_evaluator(const CurveRecord& r) {
    if (r.type == CurveType::Primitive) return [prim = r.primitive](double s) { return prim.jet(s); };
    return [chain = r.chain()](double u) { return chain_jet(chain, u); };
}

double record_param_end(const CurveRecord& r) {
    return r.type == CurveType::Primitive ? r.primitive.param_end() : static_cast<double>(r.chain().num_segments());
}

Deviation primitive_deviation(const Primitive& prim, const Polyline& p) {
    Deviation dev;
    for (int i = 0; i + 1 < p.size(); ++i) {
        const Vec3 &a = p.positions[i], &b = p.positions[i + 1];
        const Deviation d = sampled_maximum(
            [&](double s) { return point_segment_distance(prim.jet(s).position, a, b); }, p.params[i], p.params[i + 1]);
        if (d.max > dev.max) dev = d;
    }
    return dev;
}

}  // namespace crossdiv
