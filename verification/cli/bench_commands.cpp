// The bench subcommand of the crossdiv CLI: core Loop against the references side by side,
// the curve tessellation and evaluation tables, the adaptive sweep.
#include "bench_commands.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "command.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/bench/bench.h"
#include "curve_commands.h"
#include "suite_commands.h"
#include "surface_commands.h"

namespace crossdiv::cli {
namespace {

using namespace crossdiv::verification;

int run_bench_command(const std::string& json_path, const std::string& out_dir, int repeats, bool quick, bool cold) {
    const LoopOptions options{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    const std::vector<BenchInput> inputs = default_bench_inputs(quick);
    fmt::print("Loop (weights=loop boundary=edge-only), single thread, median of {} runs after one warm-up{}\n", repeats,
               cold ? ", freed memory returned to the kernel (cold)" : ", freed memory kept (warm)");
    fmt::print("{:<12} {:>6} {:<11} {:>11} {:>12} {:>10} {:>9} {:>8}\n", "input", "levels", "impl", "input faces",
               "output faces", "median ms", "x core", "RSS MB");
    std::vector<BenchRecord> records;
    for (const BenchInput& in : inputs) {
        std::vector<BenchRecord> r = run_bench({in}, options, repeats, cold);
        const double core_ms = r.front().median_ms;
        for (const BenchRecord& b : r) {
            if (b.status != "ok")
                fmt::print("{:<12} {:>6} {:<11} {}\n", b.input, b.levels, b.impl, b.status);
            else
                fmt::print("{:<12} {:>6} {:<11} {:>11} {:>12} {:>10.2f} {:>9.2f} {:>8.0f}\n", b.input, b.levels, b.impl,
                           b.input_faces, b.output_faces, b.median_ms, b.median_ms / core_ms, b.peak_rss_mb);
        }
        std::fflush(stdout);
        records.insert(records.end(), r.begin(), r.end());
    }
    const std::optional<BenchGoal> goal = bench_goal(records);
    if (goal)
        fmt::print("\ngoal: core {:.2f}x faster than the fastest reference ({}) on {} at 2 levels ({} output faces, "
                   "core peak RSS {:.0f} MB): {} (target {}x)\n",
                   goal->ratio, goal->fastest_reference, goal->input, goal->output_faces, goal->core_peak_rss_mb,
                   goal->met() ? "met" : "NOT met", kBenchGoalRatio);
    const nlohmann::json curves = run_curve_bench(repeats);
    const nlohmann::json surfaces = run_surface_bench();
    nlohmann::json recs = nlohmann::json::array();
    for (const BenchRecord& r : records) recs.push_back(to_json(r));
    const nlohmann::json doc = {{"tool", "crossdiv bench"}, {"repeats", repeats}, {"memory", cold ? "cold" : "warm"},
                                {"goal", goal ? to_json(*goal) : nlohmann::json(nullptr)}, {"records", recs}, {"curves", curves["tessellation"]},
                                {"curve_timing", curves["timing"]}, {"adaptive_sweep", surfaces},
                                {"note", "references timed through their native refinement (loop_native), output kept "
                                         "in the library's own structures"}};
    std::vector<std::string> paths;
    if (!json_path.empty()) paths.push_back(json_path);
    if (!out_dir.empty()) paths.push_back((std::filesystem::path(out_dir) / "bench.json").string());
    for (const std::string& path : paths) {
        const std::filesystem::path p(path);
        if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
        std::ofstream(path) << verification::json_text(doc, 1) << "\n";
        fmt::print("bench results: {}\n", path);
    }
    if (!out_dir.empty() && std::filesystem::exists(std::filesystem::path(out_dir) / "results.json"))
        return finish_outputs(out_dir, true);
    return 0;
}

struct BenchArgs {
    std::string json, out;
    int repeats = 5;
    bool quick = false, cold = false;
    void add_to(CLI::App& app) {
        app.add_option("--json", json, "Write the records to this JSON file");
        app.add_option("--out", out, "Suite output folder: write bench.json there and re-render its report");
        app.add_option("--repeats", repeats, "Timed runs per measurement")->check(CLI::Range(1, 64))->capture_default_str();
        app.add_flag("--quick", quick, "Two mesh sizes only (320 and 20000 faces)");
        app.add_flag("--cold", cold, "Return freed memory to the kernel between repeats (page faults counted)");
    }
};
int bench_command(const BenchArgs& a) { return run_bench_command(a.json, a.out, a.repeats, a.quick, a.cold); }

}  // namespace

void add_bench_command(CLI::App& app, int& status) {
    add_command<BenchArgs>(app, "bench", "Time core Loop against the references side by side (ratios, memory)", status,
                           bench_command);
}

}  // namespace crossdiv::cli
