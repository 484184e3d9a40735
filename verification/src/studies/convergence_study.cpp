#include "crossdiv/verification/studies/studies.h"

#include <cmath>

#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {

using nlohmann::json;

CheckReport convergence_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
    for (const std::string s : {"loop", "warren", "catmull-clark"})
        for (int n = 3; n <= 12; ++n) {
            const ConvergenceRow r = convergence(s, n, 8);
            rows.push_back(to_json(r));
            runs.push_back(measured_check("eigen-analysis", "convergence rate", s + " n=" + std::to_string(n),
                                 std::abs(r.fitted_rate - r.vertex_rate) / r.vertex_rate,
                                 tolerances::kConvergenceRateRelative, "rel",
                                 "fitted " + std::to_string(r.fitted_rate) + " vs vertex eigenvalue " +
                                     std::to_string(r.vertex_rate) + " (subdominant " + std::to_string(r.subdominant) + ")"));
        }
    out.tables = {{"convergence", rows}};
    return out;
}

}  // namespace crossdiv::verification
