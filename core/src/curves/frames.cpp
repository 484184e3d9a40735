#include "crossdiv/curves/frames.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

std::string_view to_string(FrameMethod m) {
    switch (m) {
        case FrameMethod::Planar: return "planar";
        case FrameMethod::Recursive: return "recursive";
        case FrameMethod::DoubleReflection: return "rmf";
    }
    return "?";
}

Vec3 initial_binormal(const Vec3& t0) {
    // cos(30 deg): closer than that to the axis, B x T gets short and the first normal would
    // be dominated by rounding in T.
    constexpr double kParallelCos = 0.8660254037844386;
    const Vec3 z = Vec3::UnitZ();
    if (std::abs(t0.dot(z)) <= kParallelCos * t0.norm()) return z;
    int axis = 0;
    t0.cwiseAbs().minCoeff(&axis);
    return Vec3::Unit(axis);
}

namespace {

void check_sizes(std::span<const Vec3> positions, std::span<const Vec3> tangents) {
    if (positions.size() != tangents.size())
        throw InputError("frames need one tangent per point: " + std::to_string(positions.size()) + " points, " +
                         std::to_string(tangents.size()) + " tangents");
}

/// A unit vector orthogonal to t, as close as possible to `hint`; falls back to any
/// orthogonal direction when hint is parallel to t.
Vec3 orthogonal_towards(const Vec3& t, const Vec3& hint) {
    Vec3 n = hint - hint.dot(t) * t;
    if (n.squaredNorm() > 1e-24) return n.normalized();
    return t.unitOrthogonal();
}

}  // namespace

std::vector<Frame> curve_frames(std::span<const Vec3> positions, std::span<const Vec3> tangents, FrameMethod method,
                                NormalSide side) {
    check_sizes(positions, tangents);
    if (method != FrameMethod::Planar) return curve_frames(positions, tangents, method, initial_binormal(tangents.empty() ? Vec3::UnitX() : tangents[0]));
    std::vector<Frame> frames(positions.size());
    const Vec3 b = side == NormalSide::Left ? Vec3::UnitZ() : Vec3(-Vec3::UnitZ());
    for (size_t i = 0; i < frames.size(); ++i) {
        const Vec3& t = tangents[i];
        frames[i] = {t, b.cross(t), b};
    }
    return frames;
}

std::vector<Frame> curve_frames(std::span<const Vec3> positions, std::span<const Vec3> tangents, FrameMethod method,
                                const Vec3& initial_b) {
    check_sizes(positions, tangents);
    std::vector<Frame> frames(positions.size());
    if (frames.empty()) return frames;
    if (method == FrameMethod::Planar) {
        for (size_t i = 0; i < frames.size(); ++i) frames[i] = {tangents[i], initial_b.cross(tangents[i]), initial_b};
        return frames;
    }
    {
        const Vec3& t = tangents[0];
        const Vec3 n = orthogonal_towards(t, initial_b.cross(t));
        frames[0] = {t, n, t.cross(n)};
    }
    for (size_t i = 1; i < frames.size(); ++i) {
        const Frame& prev = frames[i - 1];
        const Vec3& t = tangents[i];
        if (t.squaredNorm() == 0.0) {  // no direction here: carry the frame
            frames[i] = prev;
            continue;
        }
        Vec3 n;
        if (method == FrameMethod::Recursive) {
            n = orthogonal_towards(t, prev.B.cross(t));
        } else {
            // Double reflection: reflect (r_i, t_i) in the bisector plane of x_i x_{i+1}, then
            // in the plane that maps the reflected tangent onto t_{i+1}.
            Vec3 v1 = positions[i] - positions[i - 1];
            // The reflection depends on v1's direction only: a step so short that its
            // square underflows (a curve at the scale of 1e-300) is scaled up first.
            if (v1.squaredNorm() < std::numeric_limits<double>::min() && (v1.array() != 0.0).any())
                v1 /= v1.cwiseAbs().maxCoeff();
            const double c1 = v1.squaredNorm();
            Vec3 r = prev.N, tl = prev.T;
            if (c1 > 0.0) {
                r -= (2.0 / c1) * v1.dot(r) * v1;
                tl -= (2.0 / c1) * v1.dot(tl) * v1;
            }
            const Vec3 v2 = t - tl;
            const double c2 = v2.squaredNorm();
            if (c2 > 0.0) r -= (2.0 / c2) * v2.dot(r) * v2;
            // r is orthogonal to t up to rounding; re-orthogonalizing keeps the error from
            // accumulating over long curves without changing the method's order.
            n = orthogonal_towards(t, r);
        }
        frames[i] = {t, n, t.cross(n)};
    }
    return frames;
}

double closure_angle(std::span<const Frame> frames) {
    if (frames.size() < 2) return 0.0;
    const Frame& first = frames.front();
    const Vec3 last_n = orthogonal_towards(first.T, frames.back().N);
    return std::atan2(last_n.cross(first.N).dot(first.T), last_n.dot(first.N));
}

void distribute_closure(std::span<const Vec3> positions, std::span<Frame> frames, double angle) {
    if (positions.size() != frames.size())
        throw InputError("closure needs one frame per point: " + std::to_string(positions.size()) + " points, " +
                         std::to_string(frames.size()) + " frames");
    double total = 0;
    for (size_t i = 1; i < positions.size(); ++i) total += (positions[i] - positions[i - 1]).norm();
    if (total == 0.0) return;
    double s = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        if (i > 0) s += (positions[i] - positions[i - 1]).norm();
        const double a = angle * s / total;
        Frame& f = frames[i];
        const Vec3 n = std::cos(a) * f.N + std::sin(a) * f.B;
        f.N = n;
        f.B = f.T.cross(n);
    }
}

double max_orthonormality_error(std::span<const Frame> frames) {
    double e = 0;
    for (const Frame& f : frames) {
        e = std::max({e, std::abs(f.T.norm() - 1), std::abs(f.N.norm() - 1), std::abs(f.B.norm() - 1),
                      std::abs(f.T.dot(f.N)), std::abs(f.T.dot(f.B)), std::abs(f.N.dot(f.B)),
                      (f.T.cross(f.N) - f.B).norm()});
    }
    return e;
}

}  // namespace crossdiv
