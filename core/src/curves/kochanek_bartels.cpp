#include "crossdiv/curves/kochanek_bartels.h"

#include <cmath>
#include <string>
#include <utility>

#include "crossdiv/error.h"

namespace crossdiv {

namespace {

/// w_in (p - previous) + w_out (next - p). Where the two weights are equal (c = b = 0, the
/// cardinal splines, or c = -b) it is w (next - previous), one rounding fewer: with w = 1/2
/// that is Catmull-Rom's tangent to the bit.
Vec3 blend(double w_in, double w_out, const Vec3& previous, const Vec3& key, const Vec3& next) {
    if (w_in == w_out) return w_in * (next - previous);
    return w_in * (key - previous) + w_out * (next - key);
}

}  // namespace

void check_tcb_parameters(const TcbParameters& p) {
    for (const auto& [value, name] : {std::pair{p.tension, "tension"}, {p.continuity, "continuity"}, {p.bias, "bias"}})
        if (!(value >= -1.0 && value <= 1.0))
            throw InputError(std::string(name) + " " + std::to_string(value) + " is outside [-1, 1]");
}

KeyTangents kochanek_bartels_tangents(const Vec3& previous, const Vec3& key, const Vec3& next, const TcbParameters& p) {
    const double s = (1.0 - p.tension) / 2.0;
    const double c = p.continuity, b = p.bias;
    return {blend(s * (1.0 - c) * (1.0 + b), s * (1.0 + c) * (1.0 - b), previous, key, next),
            blend(s * (1.0 + c) * (1.0 + b), s * (1.0 - c) * (1.0 - b), previous, key, next)};
}

Vec3 kochanek_bartels_jump(const Vec3& previous, const Vec3& key, const Vec3& next, const TcbParameters& p) {
    return (1.0 - p.tension) * p.continuity * ((1.0 + p.bias) * (key - previous) - (1.0 - p.bias) * (next - key));
}

BezierChain kochanek_bartels_chain(std::span<const Vec3> keys, std::span<const TcbParameters> parameters, bool closed) {
    const size_t n = keys.size();
    require_window_count(n, closed, "TCB spline", "keys");
    if (!parameters.empty() && parameters.size() != n)
        throw InputError("a TCB spline needs one parameter set per key: " + std::to_string(n) + " keys, " +
                         std::to_string(parameters.size()) + " parameter sets");
    for (size_t i = 0; i < parameters.size(); ++i) {
        try {
            check_tcb_parameters(parameters[i]);
        } catch (const InputError& e) {
            throw InputError("key " + std::to_string(i + 1) + " of " + std::to_string(n) + ": " + e.what());
        }
    }
    const auto at = [&](size_t i) { return parameters.empty() ? TcbParameters{} : parameters[i % n]; };
    // Segment k runs from key k + 1 to key k + 2 (mod n when closed), as Catmull-Rom's.
    const size_t segments = closed ? n : n - 3;
    BezierChain chain{3, {}, closed};
    chain.points.reserve(segments * 4);
    for (size_t k = 0; k < segments; ++k) {
        const size_t i = k + 1;
        const Vec3 &p0 = keys[k % n], &p1 = keys[i % n], &p2 = keys[(i + 1) % n], &p3 = keys[(i + 2) % n];
        const Vec3 leaving = kochanek_bartels_tangents(p0, p1, p2, at(i)).leaving;
        const Vec3 arriving = kochanek_bartels_tangents(p1, p2, p3, at(i + 1)).arriving;
        append_segment(chain, static_cast<int>(k), hermite_to_bezier(p1, leaving, p2, arriving));
    }
    return chain;
}

}  // namespace crossdiv
