#pragma once
/// @file stencil_bench.h
/// Re-evaluation at fixed topology, core against OpenSubdiv: the topology of a torus refined
/// once, then a moved frame of its base vertices evaluated through core's ComposedStencils and
/// LevelStencils, through Far's stencil table (double) and through Far's PrimvarRefiner level
/// by level.
/// Only in a build with the OpenSubdiv adapter.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "crossdiv/verification/bench/bench.h"

namespace crossdiv::verification {

struct StencilRow {
    std::string input;
    int levels = 0;
    int output_vertices = 0;
    size_t core_terms = 0, opensubdiv_terms = 0;  ///< stored weights of each stencil table
    size_t level_terms = 0, level_patterns = 0;   ///< LevelStencils: source indices, weight sequences
    /// Median per frame: core's composed and level stencils, Far's stencil table and levels.
    double core_ms = 0, core_levels_ms = 0, opensubdiv_stencils_ms = 0, opensubdiv_levels_ms = 0;
    /// Largest distance, over the bounding-box diagonal, between core's composed stencils and
    /// core's level-by-level refinement of the same frame, the same for core's level stencils,
    /// and between core's composed stencils and Far's (matched by position: Far numbers the
    /// edges its own way).
    double core_vs_levels = 0, level_stencils_vs_levels = 0, core_vs_opensubdiv = 0;
    /// Far's stencil time over core's composed stencils'.
    double ratio() const { return opensubdiv_stencils_ms / core_ms; }
    /// Far's stencil time over core's level stencils': at least kStencilRatioGoal is the goal
    /// (the faster of core's two forms, the one a user re-evaluating frames would take).
    double level_ratio() const { return opensubdiv_stencils_ms / core_levels_ms; }
};

/// Goal: core's level stencils at least on par with Far's stencil table.
inline constexpr double kStencilRatioGoal = 1.0;

/// The tori of the Loop rows of at least 5000 faces, at their levels.
std::vector<StencilRow> run_stencil_bench(const std::vector<BenchInput>& inputs, int repeats);

nlohmann::json to_json(const StencilRow& r);

}  // namespace crossdiv::verification
