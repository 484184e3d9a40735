#include "crossdiv/curves/primitive_tessellation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {
namespace {

/// Samples per edge of the bound's maxima (widened by the next derivative's bound between them).
constexpr int kBoundSamples = 64;
/// Trapezoids per turn of the flattening integral.
constexpr int kFlatteningSamplesPerTurn = 4096;

/// The bound of the arc's distance to its chord over [s0, s1] (the file comment of the header).
double chord_bound(const Primitive& p, const PrimitiveDerivativeBounds& b, double s0, double s1) {
    const double h = s1 - s0;
    const Vec3 chord = p.jet(s1).position - p.jet(s0).position;
    const double length = chord.norm();
    const double widen = 0.5 * h / kBoundSamples;  // the farthest any s lies from a sample
    double largest = 0, offset = 0, along = INFINITY;
    const Vec3 u = length > 0 ? Vec3(chord / length) : Vec3::Zero();
    for (int i = 0; i <= kBoundSamples; ++i) {
        const ChainJet j = p.jet(s0 + h * i / kBoundSamples);
        largest = std::max(largest, j.d2.norm());
        offset = std::max(offset, (j.d2 - j.d2.dot(u) * u).norm());
        along = std::min(along, j.d1.dot(u));
    }
    const bool monotone = length > 0 && along - widen * b.second > 0;
    const double second = monotone ? offset : largest;
    return h * h / 8.0 * (second + widen * b.third);
}

}  // namespace

PrimitiveDerivativeBounds derivative_bounds(const Primitive& p) {
    switch (p.kind) {
        case PrimitiveKind::Circle:
        case PrimitiveKind::Helix: return {std::abs(p.radius), std::abs(p.radius)};
        case PrimitiveKind::Trefoil: {
            // P'' = scale (-sin s - 8 sin 2s, -cos s + 8 cos 2s, 9 sin 3s): each component at
            // most 9, 9, 9; P''' = scale (-cos s - 16 cos 2s, sin s - 16 sin 2s, 27 cos 3s): 17, 17, 27.
            const double k = std::abs(p.scale);
            return {k * std::sqrt(3.0 * 81.0), k * std::sqrt(17.0 * 17.0 * 2.0 + 27.0 * 27.0)};
        }
    }
    return {};
}

Polyline tessellate_primitive_distance(const Primitive& p, double tol) {
    const std::string name(to_string(p.kind));
    const double size = bounding_box_diagonal(sample_primitive(p, 256).positions);
    if (!std::isfinite(tol) || tol <= 0.0 || tol < kMinDistanceTolRelative * size)
        throw InputError(name + ": the distance tolerance must be finite and at least " +
                         std::to_string(kMinDistanceTolRelative) + " x the curve's size (" + std::to_string(size) +
                         "), got " + std::to_string(tol));
    const PrimitiveDerivativeBounds b = derivative_bounds(p);
    const double end = p.param_end();
    // Certified with a margin of 1e-9 of tol, as for the splines: the vertices and any
    // measurement of the distance round differently from the bound (by ulps).
    const double certified = tol * (1.0 - 1e-9);
    const auto fits = [&](double s0, double s1) { return chord_bound(p, b, s0, s1) <= certified; };
    Polyline out;
    const auto emit = [&](double s, double at) {
        const ChainJet j = p.jet(s);
        out.positions.push_back(j.position);
        out.tangents.push_back(j.d1.normalized());
        out.params.push_back(at);
        if (out.positions.size() >= static_cast<size_t>(kMaxCurveSamples))
            throw InputError(name + ": more samples than the limit of " + std::to_string(kMaxCurveSamples) +
                             " within a distance of " + std::to_string(tol));
    };
    for (double s = 0.0; s < end;) {
        emit(s, s);
        // The farthest end within tol, bracketed from where the local second derivative says
        // an edge within tol ends.
        const double second = std::max(p.jet(s).d2.norm(), 1e-300);
        const double lo = farthest_reach(s, end, s + std::sqrt(8.0 * tol / second), fits);
        // The bound is positive on any edge of positive length, and tol is at least 1e-12 of
        // the size: some end always fits; the guard keeps a rounding corner from stalling.
        s = lo > s ? lo : std::nextafter(s, end);
    }
    // The end: a closed primitive's first sample again, bitwise (cos(2 pi) is not exactly 1).
    emit(p.closed() ? 0.0 : end, end);
    out.normals = curve_normals(out.positions, out.tangents);
    return out;
}

double primitive_flattening_estimate(const Primitive& p, double tol) {
    if (!std::isfinite(tol) || tol <= 0.0)
        throw InputError("the flattening estimate needs a positive tolerance, got " + std::to_string(tol));
    const double end = p.param_end();
    const int n = std::max(1, static_cast<int>(std::ceil(kFlatteningSamplesPerTurn * end / (2.0 * M_PI))));
    // sqrt(kappa) |P'| = sqrt(|P' x P''| / |P'|), 0 where P' vanishes.
    const auto f = [&](double s) {
        const ChainJet j = p.jet(s);
        const double speed = j.d1.norm();
        return speed > 0 ? std::sqrt(j.d1.cross(j.d2).norm() / speed) : 0.0;
    };
    double sum = 0.5 * (f(0.0) + f(end));
    for (int i = 1; i < n; ++i) sum += f(end * i / n);
    return sum * (end / n) / std::sqrt(8.0 * tol);
}

}  // namespace crossdiv
