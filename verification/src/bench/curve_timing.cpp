#include "crossdiv/verification/bench/curve_timing.h"

#include <vector>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/verification/bench/bench.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {

std::optional<CurveTiming> time_curve_evaluation(const CurveRecord& r, const std::string& label, int repeats) {
    const std::vector<const Implementation*> refs = references_with(&Capabilities::spline_evaluation);
    if (refs.empty() || (r.type != CurveType::BSpline && r.type != CurveType::Bezier)) return std::nullopt;
    const Implementation& reference = *refs.front();
    const BezierChain c = r.chain();
    constexpr int kPerSegment = 1000;
    std::vector<double> u;
    for (int k = 0; k < c.num_segments(); ++k)
        for (int j = 0; j < kPerSegment; ++j) u.push_back(k + (j + 0.5) / kPerSegment);
    CurveTiming t{label, reference.name(), c.degree, u.size(), 0, 0, 0};
    t.core_ms = median_ms(repeats, [&] {
        for (double x : u) t.checksum += chain_jet(c, x).d2.x();
    });
    const SplineKind kind = r.type == CurveType::BSpline ? SplineKind::UniformCubicBSpline : SplineKind::ClampedBezier;
    t.reference_ms = median_ms(repeats, [&] { t.checksum += reference.evaluate_spline(kind, r.control, u).d2.back().x(); });
    return t;
}

nlohmann::json to_json(const CurveTiming& t) {
    return {{"curve", t.curve}, {"degree", t.degree}, {"evaluations", t.evaluations}, {"core_ms", t.core_ms},
            {"eigen_ms", t.reference_ms}, {"eigen_over_core", t.reference_ms / t.core_ms}, {"checksum", t.checksum}};
}

}  // namespace crossdiv::verification
