#pragma once
/// @file thread_bench.h
/// Refinement on every core: core's streaming Loop and Catmull-Clark (loop_streaming.h,
/// catmull_clark_streaming.h) on one thread and on N, against OpenSubdiv's way of using N
/// cores, Osd::OmpEvaluator evaluating Far's float stencil table with OpenMP, on one thread and
/// on N. Each timing in a child process of its own, in
/// rounds (time_in_rounds). Core's time includes its topology; OpenSubdiv's stencil table is
/// built in the warm-up call, so its time is the evaluation alone: the comparison favours
/// OpenSubdiv.

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "crossdiv/verification/bench/bench.h"

namespace crossdiv::verification {

struct ThreadRow {
    std::string scheme;
    std::string input;
    int levels = 0;
    long long output_faces = 0;
    int threads = 1;
    /// Medians: core on one thread and on `threads`; OmpEvaluator likewise (NaN without the
    /// OpenSubdiv adapter, or when it failed).
    double core_one_ms = 0, core_many_ms = 0, omp_one_ms = 0, omp_many_ms = 0;
    /// The ratios, each the median of the ratios of runs taken side by side (paired_ratio):
    /// core's one-thread time over its N-thread time, and OmpEvaluator's N-thread time over
    /// core's (above 1, core is ahead).
    double speedup = NAN, over_omp = NAN;
    std::string status = "ok";  ///< or the first failure, "core: crashed: signal 11"
};

/// Goal: on N threads, at least 0.85 N times core's one-thread speed (1.7x on 2 cores).
inline constexpr double kThreadSpeedupGoalPerThread = 0.85;
/// Goal: core on N threads ahead of OmpEvaluator on N threads.
inline constexpr double kThreadOmpGoal = 1.0;
/// Catmull-Clark's thread rows: the benchmark quads (default_catmull_clark_bench_inputs) of
/// about 19,500 faces at 2 levels (312k output faces) and, unless `quick`, at 3 (1.25M).
std::vector<BenchInput> catmull_clark_thread_inputs(bool quick);

/// The goals hold at inputs of at least this many output faces (below, the passes are short
/// enough that waking the threads weighs).
inline constexpr long long kThreadGoalMinFaces = 1000000;

/// Each input (Loop: weights loop, boundary edge-only; Catmull-Clark: boundary edge-only) on 1
/// and `threads` threads.
std::vector<ThreadRow> run_thread_bench(const std::vector<BenchInput>& inputs, int threads, int repeats);

nlohmann::json to_json(const ThreadRow& r);

}  // namespace crossdiv::verification
