// A user's Loop subdivision, linked into their own program, put under test with crossdiv's
// comparison through a C++ function instead of a command. Here the "user's Loop" is core's
// with Warren's weights, so the answer is known: crossdiv must name that rule.
#include <cstdio>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/implementations/callback_implementation.h"

using namespace crossdiv;
using namespace crossdiv::verification;

int main() {
    const auto mine = make_callback_implementation("mine", {Scheme::Loop}, [](const PolyMesh& mesh, const RefineRequest& r) {
        return to_poly_mesh(loop_subdivide(to_tri_mesh(mesh, "mine"), {LoopWeights::Warren, LoopBoundary::EdgeOnly}, r.levels));
    });
    RefinementRequest request;  // Loop, core's default rule
    request.levels = 2;
    request.subject = mine.get();
    const RefinementComparison c = compare_refinement(datasets::bundled_mesh("icosahedron"), "icosahedron", request);
    if (c.subject_failed() || !c.rules || !c.rules->rule) {
        std::printf("mine: no named rule found (%s)\n", c.subject_outcome.summary().c_str());
        return 1;
    }
    std::printf("mine follows weights=%s boundary=%s\n", std::string(to_string(c.rules->rule->loop.weights)).c_str(),
                std::string(to_string(c.rules->rule->loop.boundary)).c_str());
    for (const RefinementRun& run : c.runs) std::printf("  %s: %s %s\n", run.reference.c_str(), to_string(run.verdict), to_string(run.divergence_class));
    return c.rules->rule->loop.weights == LoopWeights::Warren ? 0 : 1;
}
