#include "crossdiv/curves/bessel_overhauser.h"

#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

namespace {

/// |p_{j+1} - p_j| for every chord j the chain uses (j < n - 1 open, all n closed).
std::vector<double> chord_lengths(std::span<const Vec3> p, bool closed) {
    const size_t n = p.size();
    std::vector<double> h(closed ? n : n - 1);
    for (size_t j = 0; j < h.size(); ++j) {
        h[j] = (p[(j + 1) % n] - p[j]).norm();
        if (!(h[j] > 0))
            throw InputError("points " + std::to_string(j + 1) + " and " + std::to_string((j + 1) % n + 1) + " of " +
                             std::to_string(n) +
                             (h[j] == 0 ? " coincide: a chord of length 0 has no knot interval"
                                        : ": the chord length is not finite (the points overflow double)"));
    }
    return h;
}

}  // namespace

BezierChain bessel_overhauser_chain(std::span<const Vec3> points, bool closed) {
    const size_t n = points.size();
    require_window_count(n, closed, "Bessel-Overhauser spline", "points");
    const std::vector<double> h = chord_lengths(points, closed);
    const size_t chords = h.size();
    // Bessel's tangent at point i times a chord length `scale`: the chord velocities around
    // it, each weighted by the other's knot interval.
    const auto tangent = [&](size_t i, double scale) {
        const size_t before = (i + chords - 1) % chords, after = i % chords;
        const Vec3 m_before = (points[i % n] - points[before]) / h[before];
        const Vec3 m_after = (points[(i + 1) % n] - points[i % n]) / h[after];
        return Vec3(scale * (h[after] * m_before + h[before] * m_after) / (h[before] + h[after]));
    };
    // Segment k runs from point k + 1 to point k + 2 (mod n when closed), as Catmull-Rom's.
    const size_t segments = closed ? n : n - 3;
    BezierChain chain{3, {}, closed};
    chain.points.reserve(segments * 4);
    for (size_t k = 0; k < segments; ++k) {
        const size_t i = k + 1;
        const double span = h[i % chords];
        append_segment(chain, static_cast<int>(k),
                       hermite_to_bezier(points[i % n], tangent(i, span), points[(i + 1) % n], tangent(i + 1, span)));
    }
    return chain;
}

std::vector<double> bessel_overhauser_chords(std::span<const Vec3> points, bool closed) {
    const size_t n = points.size();
    require_window_count(n, closed, "Bessel-Overhauser spline", "points");
    const std::vector<double> h = chord_lengths(points, closed);
    std::vector<double> out(closed ? n : n - 3);
    for (size_t k = 0; k < out.size(); ++k) out[k] = h[(k + 1) % h.size()];
    return out;
}

}  // namespace crossdiv
