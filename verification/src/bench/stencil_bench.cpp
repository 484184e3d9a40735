#include "crossdiv/verification/bench/stencil_bench.h"

#include <cmath>

#include "crossdiv/adapters/opensubdiv.h"
#include "crossdiv/subdiv/composed_stencils.h"
#include "crossdiv/subdiv/level_stencils.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/mesh_comparison.h"

namespace crossdiv::verification {
namespace {

/// A frame: the base vertices moved by a smooth field, as an animation would move them.
std::vector<Vec3> moved(const std::vector<Vec3>& p) {
    std::vector<Vec3> out(p.size());
    for (size_t i = 0; i < p.size(); ++i)
        out[i] = p[i] + 0.05 * Vec3(std::sin(3 * p[i].y()), std::cos(2 * p[i].z()), std::sin(p[i].x() + p[i].z()));
    return out;
}

}  // namespace

std::vector<StencilRow> run_stencil_bench(const std::vector<BenchInput>& inputs, int repeats) {
    std::vector<StencilRow> rows;
    const WarmAllocator warm;
    const LoopOptions options{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    for (const BenchInput& in : inputs) {
        const ComposedStencils core = ComposedStencils::loop(in.mesh, options, in.levels);
        const LevelStencils core_levels = LevelStencils::loop(in.mesh, options, in.levels);
        const adapters::opensubdiv::LoopFrames far(in.mesh, options, in.levels);
        const std::vector<Vec3> frame = moved(in.mesh.positions);
        std::vector<Vec3> ours, ours_by_levels, scratch, theirs, by_levels;
        StencilRow r{in.name, in.levels, core.num_rows(), core.num_terms(), far.num_stencil_terms(),
                     core_levels.num_terms(), core_levels.num_patterns()};
        const std::vector<double> ms = interleaved_median_ms(
            repeats, {[&] { core.apply(frame, ours); }, [&] { core_levels.apply(frame, ours_by_levels, scratch); },
                      [&] { far.by_stencils(frame, theirs); }, [&] { far.by_levels(frame, by_levels); }});
        r.core_ms = ms[0];
        r.core_levels_ms = ms[1];
        r.opensubdiv_stencils_ms = ms[2];
        r.opensubdiv_levels_ms = ms[3];
        TriMesh moved_mesh = in.mesh;
        moved_mesh.positions = frame;
        const std::vector<Vec3> refined = loop_subdivide(moved_mesh, options, in.levels).positions;
        r.core_vs_levels = max_relative_distance(ours, refined, identity_map(ours.size()));
        r.level_stencils_vs_levels = max_relative_distance(ours_by_levels, refined, identity_map(refined.size()));
        const Correspondence c = match_nearest(ours, theirs);
        r.core_vs_opensubdiv = c.method == MatchMethod::None ? INFINITY : max_relative_distance(ours, theirs, c.ref_to_ours);
        rows.push_back(r);
    }
    return rows;
}

nlohmann::json to_json(const StencilRow& r) {
    return {{"input", r.input},
            {"levels", r.levels},
            {"output_vertices", r.output_vertices},
            {"core_terms", r.core_terms},
            {"opensubdiv_terms", r.opensubdiv_terms},
            {"level_terms", r.level_terms},
            {"level_patterns", r.level_patterns},
            {"core_ms", r.core_ms},
            {"core_levels_ms", r.core_levels_ms},
            {"opensubdiv_stencils_ms", r.opensubdiv_stencils_ms},
            {"opensubdiv_levels_ms", r.opensubdiv_levels_ms},
            {"core_vs_levels", r.core_vs_levels},
            {"level_stencils_vs_levels", r.level_stencils_vs_levels},
            {"core_vs_opensubdiv", r.core_vs_opensubdiv},
            {"ratio", r.ratio()},
            {"level_ratio", r.level_ratio()}};
}

}  // namespace crossdiv::verification
