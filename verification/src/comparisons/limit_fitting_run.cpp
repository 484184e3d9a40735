#include "crossdiv/verification/comparisons/limit_fitting_run.h"
#include "crossdiv/verification/implementations/isolated_calls.h"

#include <fmt/format.h>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {

LimitSampling fitting_sampling(Scheme scheme, const TriMesh& control, int levels) {
    const SchemeRule rule;  // the default rules: Loop's weights, B-spline boundaries
    switch (scheme) {
        case Scheme::Loop: return loop_limit_sampling(control, rule.loop, levels);
        case Scheme::CatmullClark: return catmull_clark_limit_sampling(to_poly_mesh(control), rule.catmull_clark, levels);
        default: break;
    }
    throw InputError(std::string("fitting has the limit masks of loop and catmull-clark, not ") + to_string(scheme));
}

double recovery_error(Scheme scheme, const TriMesh& control, int levels) {
    const LimitSampling s = fitting_sampling(scheme, control, levels);
    const std::vector<Vec3> x = fit_limit_points(s, s.evaluate(control.positions));
    double worst = 0;
    for (int v = 0; v < control.num_vertices(); ++v) worst = std::max(worst, (x[v] - control.positions[v]).norm());
    return worst / bounding_box_diagonal(control.positions);
}

TopologyType topology_type(const TriMesh& mesh) {
    const MeshTopology t = mesh_topology(to_poly_mesh(mesh));
    return {t.euler, t.boundary_loops};
}

TriMesh coarse_control(const TriMesh& target, int edges, const Implementation& simplifier) {
    // Edge collapse is defined on a manifold, consistently oriented mesh; anything else is
    // refused here by its first offending element, before the library meets it.
    try {
        (void)build_tri_connectivity(target);
    } catch (const InputError& e) {
        throw InputError(std::string("the target cannot be simplified to a control mesh (--edges): ") + e.what());
    }
    IsolatedValue<TriMesh> simplified = simplify_isolated(simplifier, target, edges);
    if (!simplified.value)
        throw InputError(simplifier.name() + " could not simplify the target to " + std::to_string(edges) +
                         " edges: " + simplified.outcome.failure_explanation());
    TriMesh control = std::move(*simplified.value);
    const TopologyType want = topology_type(target), got = topology_type(control);
    if (got != want)
        throw InputError(fmt::format("{}'s simplification to {} edges changed the topology: Euler characteristic {} and {} "
                                     "boundary loops, the target's {} and {}",
                                     simplifier.name(), edges, got.euler, got.boundary_loops, want.euler, want.boundary_loops));
    return control;
}

int energy_increases(const FittingResult& result, const TriMesh& target, int samples) {
    const double ulps = tolerances::kFittingDistanceUlps * std::numeric_limits<double>::epsilon() *
                        bounding_box_diagonal(target.positions);
    const double floor = (samples + target.num_vertices()) * ulps * ulps;
    int increases = 0;
    for (size_t k = 1; k < result.steps.size(); ++k)
        if (result.steps[k].energy > result.steps[k - 1].energy * (1 + tolerances::kFittingEnergyRounding) + floor) ++increases;
    return increases;
}

FittingRun run_fitting(Scheme scheme, const TriMesh& control, const TriMesh& target, int levels, int iterations,
                       const Implementation* hausdorff_reference) {
    const TopologyType c = topology_type(control), t = topology_type(target);
    if (c != t)
        throw InputError(fmt::format("the control mesh (Euler characteristic {}, {} boundary loops) and the target ({}, {}) "
                                     "are not of the same topology type",
                                     c.euler, c.boundary_loops, t.euler, t.boundary_loops));
    FittingRun run;
    run.sampling = fitting_sampling(scheme, control, levels);
    const LimitSampling& sampling = run.sampling;
    run.result = fit_limit_surface(sampling, control.positions, target, {.iterations = iterations});
    if (hausdorff_reference) {
        run.hausdorff_by = hausdorff_reference->name();
        for (const FittingStep& step : run.result.steps) {
            const IsolatedValue<double> d = hausdorff_isolated(*hausdorff_reference, sampling.surface(step.control), target);
            if (!d.value) {
                run.hausdorff.clear();
                run.hausdorff_error = d.outcome.failure_explanation();
                break;
            }
            run.hausdorff.push_back(*d.value);
        }
    }
    return run;
}

}  // namespace crossdiv::verification
