#include "crossdiv/verification/studies/studies.h"

#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/properties/loop_rule_oracle.h"
#include "crossdiv/verification/properties/rule_oracle.h"

namespace crossdiv::verification {

using nlohmann::json;

CheckReport spectrum_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
    for (const std::string s : {"loop", "warren", "catmull-clark"})
        for (int n = 3; n <= 20; ++n) {
            const SpectrumRow r = local_spectrum(s, n);
            rows.push_back(to_json(r));
            const std::string who = s + " n=" + std::to_string(n);
            runs.push_back(measured_check("closed form", "spectrum", who, r.max_difference, tolerances::kSpectrumAgreement, "abs",
                                 "lambda_1 " + std::to_string(r.subdominant) + ", vertex eigenvalue " +
                                     std::to_string(r.vertex_rate)));
            // 0 when the characteristic map is regular (real, double, strictly dominant lambda_1).
            runs.push_back(measured_check("eigen-analysis", "regular characteristic map", who,
                                 r.regular_characteristic_map ? 0.0 : 1.0, 0.0, "",
                                 "multiplicity " + std::to_string(r.subdominant_multiplicity) + ", next " +
                                     std::to_string(r.next) + ", max |imag| " + std::to_string(r.max_imaginary)));
        }
    // The Loop rules no reference has in full (Warren's weights; the corner rule CGAL and
    // OpenMesh lack) checked against the stencils as published, not against core's masks.
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren})
        for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
            const RuleVerdict v = check_core_loop_rule({w, b}, {13, 14, 15, 16, 17, 18, 19, 20, 64, 360});
            runs.push_back(oracle_check("published stencils", "loop rule oracle",
                                        std::string(to_string(w)) + " " + std::string(to_string(b)), v));
        }
    out.tables = {{"spectrum", rows}};
    return out;
}

}  // namespace crossdiv::verification
