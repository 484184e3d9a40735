#include "crossdiv/curves/primitives.h"

#include <cmath>
#include <string>

#include "crossdiv/curves/tessellation.h"
#include "crossdiv/error.h"

namespace crossdiv {

std::string_view to_string(PrimitiveKind k) {
    switch (k) {
        case PrimitiveKind::Circle: return "circle";
        case PrimitiveKind::Helix: return "helix";
        case PrimitiveKind::Trefoil: return "trefoil";
    }
    return "?";
}

double Primitive::param_end() const { return kind == PrimitiveKind::Helix ? 2.0 * M_PI * turns : 2.0 * M_PI; }

ChainJet Primitive::jet(double s) const {
    const double c = std::cos(s), n = std::sin(s);
    switch (kind) {
        case PrimitiveKind::Circle:
            return {radius * Vec3(c, n, 0), radius * Vec3(-n, c, 0), radius * Vec3(-c, -n, 0)};
        case PrimitiveKind::Helix: {
            const double rise = pitch / (2.0 * M_PI);
            return {Vec3(radius * c, radius * n, rise * s), Vec3(-radius * n, radius * c, rise), Vec3(-radius * c, -radius * n, 0)};
        }
        case PrimitiveKind::Trefoil: {
            const double c2 = std::cos(2 * s), n2 = std::sin(2 * s), c3 = std::cos(3 * s), n3 = std::sin(3 * s);
            return {scale * Vec3(n + 2 * n2, c - 2 * c2, -n3), scale * Vec3(c + 4 * c2, -n + 4 * n2, -3 * c3),
                    scale * Vec3(-n - 8 * n2, -c + 8 * c2, 9 * n3)};
        }
    }
    return {};
}

Polyline sample_primitive(const Primitive& p, int steps) {
    if (steps < 1) throw InputError(std::string(to_string(p.kind)) + ": at least 1 step needed, got " + std::to_string(steps));
    if (steps >= kMaxCurveSamples)
        throw InputError(std::string(to_string(p.kind)) + ": " + std::to_string(steps) + " steps, more samples than the limit of " +
                         std::to_string(kMaxCurveSamples));
    Polyline out;
    const double end = p.param_end();
    for (int i = 0; i <= steps; ++i) {
        // The last sample of a closed primitive is the first one again, bitwise, so that
        // closure checks see a closed curve (cos(2 pi) is not exactly 1 in doubles).
        const double s = (i == steps && p.closed()) ? 0.0 : end * i / steps;
        const ChainJet j = p.jet(s);
        out.positions.push_back(j.position);
        out.tangents.push_back(j.d1.normalized());
        out.params.push_back(end * i / steps);
    }
    out.normals = curve_normals(out.positions, out.tangents);
    return out;
}

}  // namespace crossdiv
