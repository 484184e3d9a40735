// The bench subcommand of the crossdiv CLI: core Loop and Catmull-Clark against the references side by side,
// the curve tessellation and evaluation tables, the adaptive sweep.
#include "bench_commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "command.h"
#include "crossdiv/io/output_file.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/bench/bench.h"
#include "crossdiv/verification/bench/thread_bench.h"
#include "crossdiv/verification/bench/valence_bench.h"
#ifdef CROSSDIV_HAS_OPENSUBDIV
#include "crossdiv/verification/bench/stencil_bench.h"
#endif
#include "curve_commands.h"
#include "suite_commands.h"
#include "surface_commands.h"

namespace crossdiv::cli {
namespace {

using namespace crossdiv::verification;

/// The valence rows: each command on a pole, a fan and a big polygon against a regular mesh.
nlohmann::json print_valence_bench(const std::vector<int>& valences, int repeats) {
    fmt::print("\nValence: each command on a vertex of valence k (or a polygon of k sides) against a regular mesh of "
               "as many corners, median of {} runs; ratio of the times per unit of size (check: input corners, a "
               "scheme: output vertices + faces)\n",
               repeats);
    fmt::print("{:<9} {:>7} {:<19} {:>9} {:>10} {:>9} {:>11} {:>7}\n", "shape", "k", "command", "size", "ms",
               "reg. size", "regular ms", "ratio");
    const std::vector<ValenceRow> rows = run_valence_bench(valences, repeats);
    nlohmann::json out = nlohmann::json::array();
    double worst = 0;
    std::string worst_row;
    for (const ValenceRow& r : rows) {
        fmt::print("{:<9} {:>7} {:<19} {:>9} {:>10.2f} {:>9} {:>11.2f} {:>7.2f}\n", datasets::to_string(r.shape),
                   r.valence, r.command, r.size, r.ms, r.regular_size, r.regular_ms, r.ratio());
        out.push_back(to_json(r));
        if (!(r.ratio() <= worst)) {
            worst = r.ratio();
            worst_row = fmt::format("{} on the {} of k = {}", r.command, datasets::to_string(r.shape), r.valence);
        }
    }
    fmt::print("goal: every ratio <= {}: {} (largest {:.2f}, {})\n", kValenceRatioGoal,
               worst <= kValenceRatioGoal ? "met" : "NOT met", worst, worst_row);
    std::fflush(stdout);
    return {{"goal_ratio", kValenceRatioGoal}, {"rows", out}};
}

/// The sections `crossdiv bench` runs, each by name.
inline constexpr const char* kBenchSections[] = {"loop", "catmull-clark", "threads", "valence", "stencils", "curves", "sweep"};

/// The machine's cores, at least 2: the thread rows compare one thread with several.
int default_threads() { return std::max(2, static_cast<int>(std::thread::hardware_concurrency())); }

struct BenchArgs {
    std::string json, out;
    int repeats = 5;
    int threads = default_threads();
    bool quick = false, cold = false, warm = false;
    std::vector<std::string> only;  ///< sections to run; every one when empty
    std::vector<int> valences;      ///< the valence rows' k; kBenchValences when empty
    void add_to(CLI::App& app) {
        app.add_option("--json", json, "Write the records to this JSON file");
        app.add_option("--out", out, "Suite output folder: write bench.json there and re-render its report");
        app.add_option("--repeats", repeats, "Timed runs per measurement")->check(CLI::Range(1, 64))->capture_default_str();
        app.add_flag("--quick", quick, "Two mesh sizes only (320 and 20000 faces), valence 1000 only");
        CLI::Option* c = app.add_flag(
            "--cold", cold, "Loop and Catmull-Clark rows cold only: freed memory returned to the kernel between repeats (page faults counted)");
        app.add_flag("--warm", warm, "Loop and Catmull-Clark rows warm only: freed memory kept between repeats (by default both, in turn)")
            ->excludes(c);
        app.add_option("--threads", threads, "The thread rows' thread count (default: the cores, at least 2)")
            ->check(CLI::Range(2, 256))
            ->capture_default_str();
        app.add_option("--only", only, "Run only these sections (loop, catmull-clark, threads, valence, stencils, curves, sweep)")
            ->check(CLI::IsMember(std::vector<std::string>(std::begin(kBenchSections), std::end(kBenchSections))));
        app.add_option("--valences", valences, "The valence rows' valences (default 1000 10000 100000)")
            ->check(CLI::Range(3, 10000000));
    }
    bool runs(const std::string& section) const {
        return only.empty() || std::find(only.begin(), only.end(), section) != only.end();
    }
};

/// The stencil rows: re-evaluation at fixed topology, core against OpenSubdiv.
nlohmann::json print_stencil_bench(bool quick, int repeats) {
#ifdef CROSSDIV_HAS_OPENSUBDIV
    std::vector<BenchInput> inputs;
    for (BenchInput& in : default_bench_inputs(quick))
        if (in.mesh.num_faces() >= 5000 && in.levels >= 2) inputs.push_back(std::move(in));
    fmt::print("\nFixed topology: a moved frame of the base vertices re-evaluated, median of {} runs; core's composed "
               "stencils (comp.) and level stencils (lev.) against OpenSubdiv's stencil table (double) and "
               "PrimvarRefiner per level\n",
               repeats);
    fmt::print("{:<12} {:>6} {:>9} {:>10} {:>10} {:>10} {:>9} {:>9} {:>10} {:>10} {:>7} {:>7} {:>9} {:>9} {:>9}\n", "input",
               "levels", "vertices", "comp.terms", "lev.terms", "osd terms", "comp. ms", "lev. ms", "osd st. ms",
               "osd lv. ms", "r comp", "r lev", "comp.err", "lev.err", "vs osd");
    const std::vector<StencilRow> rows = run_stencil_bench(inputs, repeats);
    nlohmann::json out = nlohmann::json::array();
    bool met = !rows.empty();
    for (const StencilRow& r : rows) {
        fmt::print("{:<12} {:>6} {:>9} {:>10} {:>10} {:>10} {:>9.2f} {:>9.2f} {:>10.2f} {:>10.2f} {:>7.2f} {:>7.2f} {:>9.1e} "
                   "{:>9.1e} {:>9.1e}\n",
                   r.input, r.levels, r.output_vertices, r.core_terms, r.level_terms, r.opensubdiv_terms, r.core_ms,
                   r.core_levels_ms, r.opensubdiv_stencils_ms, r.opensubdiv_levels_ms, r.ratio(), r.level_ratio(),
                   r.core_vs_levels, r.level_stencils_vs_levels, r.core_vs_opensubdiv);
        out.push_back(to_json(r));
        met = met && r.level_ratio() >= kStencilRatioGoal;
    }
    fmt::print("r: OpenSubdiv's stencil time / core's; err: distance to core's level-by-level refinement over the "
               "diagonal\ngoal: core's level stencils at least {}x OpenSubdiv's stencil table's speed on every torus: {}\n",
               kStencilRatioGoal, met ? "met" : "NOT met");
    std::fflush(stdout);
    return {{"goal_ratio", kStencilRatioGoal}, {"rows", out}};
#else
    (void)quick;
    (void)repeats;
    fmt::print("\nFixed topology: this build has no OpenSubdiv adapter to time against\n");
    return nullptr;
#endif
}

/// The thread rows: core's streaming Loop and OpenSubdiv's OmpEvaluator on one thread and on
/// N, with the two goals at every input of at least kThreadGoalMinFaces output faces.
nlohmann::json print_thread_bench(const BenchArgs& a) {
    // The schemes asked for beside the section (--only threads loop), both when neither is.
    const bool loop = a.runs("loop") || !a.runs("catmull-clark"), catmull_clark = a.runs("catmull-clark") || !a.runs("loop");
    std::vector<BenchInput> inputs;
    if (loop)
        for (BenchInput& in : default_bench_inputs(a.quick))
            if (static_cast<long long>(in.mesh.num_faces()) << (2 * in.levels) >= kBenchGoalMinFaces) inputs.push_back(std::move(in));
    if (catmull_clark)
        for (BenchInput& in : catmull_clark_thread_inputs(a.quick)) inputs.push_back(std::move(in));
    fmt::print("\nThreads: Loop (weights=loop boundary=edge-only) and Catmull-Clark (boundary=edge-only) on 1 and {} "
               "threads, median of {} runs; core refines (topology included), OpenSubdiv's Osd::OmpEvaluator evaluates "
               "Far's float stencil table built before (evaluation only)\n",
               a.threads, a.repeats);
    fmt::print("{:<13} {:<12} {:>6} {:>12} {:>11} {:>11} {:>8} {:>11} {:>11} {:>8} {:>9}\n", "scheme", "input", "levels",
               "output faces", "core 1 ms", "core N ms", "speedup", "omp 1 ms", "omp N ms", "speedup", "omp/core");
    const std::vector<ThreadRow> rows = run_thread_bench(inputs, a.threads, a.repeats);
    nlohmann::json out = nlohmann::json::array(), goals = nlohmann::json::array();
    const double speedup_goal = kThreadSpeedupGoalPerThread * a.threads;
    for (const ThreadRow& r : rows) {
        if (r.status != "ok") fmt::print("{:<13} {:<12} {:>6} {}\n", r.scheme, r.input, r.levels, r.status);
        fmt::print("{:<13} {:<12} {:>6} {:>12} {:>11.2f} {:>11.2f} {:>8.2f} {:>11.2f} {:>11.2f} {:>8.2f} {:>9.2f}\n",
                   r.scheme, r.input, r.levels, r.output_faces, r.core_one_ms, r.core_many_ms, r.speedup, r.omp_one_ms,
                   r.omp_many_ms, r.omp_one_ms / r.omp_many_ms, r.over_omp);
        out.push_back(to_json(r));
        if (r.output_faces < kThreadGoalMinFaces) continue;
        const bool fast = r.speedup >= speedup_goal, ahead = r.over_omp >= kThreadOmpGoal;
        // Without OmpEvaluator's times (no OpenSubdiv adapter, or it failed) the second goal
        // has nothing to be measured against: said so, not counted as met.
        const std::string against = std::isfinite(r.over_omp) ? (ahead ? "met" : "NOT met") : "not measured";
        fmt::print("goal ({} threads): core {:.2f}x its one-thread speed on {} threads, {} at {} levels ({} output faces): "
                   "{} (target {:.2f}x)\n",
                   r.scheme, r.speedup, r.threads, r.input, r.levels, r.output_faces, fast ? "met" : "NOT met", speedup_goal);
        fmt::print("goal ({} threads): core on {} threads {:.2f}x OmpEvaluator's speed on as many: {} (target {}x)\n", r.scheme,
                   r.threads, r.over_omp, against, kThreadOmpGoal);
        goals.push_back({{"goal", "speedup"}, {"scheme", r.scheme}, {"input", r.input}, {"levels", r.levels}, {"threads", r.threads},
                         {"ratio", r.speedup}, {"target_ratio", speedup_goal}, {"met", fast}});
        goals.push_back({{"goal", "ahead of OmpEvaluator"}, {"scheme", r.scheme}, {"input", r.input}, {"levels", r.levels}, {"threads", r.threads},
                         {"ratio", finite_or_null(r.over_omp)},
                         {"target_ratio", kThreadOmpGoal}, {"met", ahead}});
    }
    if (goals.empty()) fmt::print("goal (threads): no input of at least {} output faces in this run\n", kThreadGoalMinFaces);
    std::fflush(stdout);
    return {{"threads", a.threads}, {"rows", out}, {"goals", goals}};
}

/// One scheme's rows: core against each reference on meshes of growing size, warm and cold, an
/// input's two regimes timed in the same rounds (so that core's cold-over-warm ratio pairs runs
/// taken side by side).
std::vector<BenchRecord> print_scheme_rows(const BenchArgs& a, Scheme scheme) {
    const bool loop = scheme == Scheme::Loop;
    const std::vector<BenchInput> inputs = loop ? default_bench_inputs(a.quick) : default_catmull_clark_bench_inputs(a.quick);
    std::vector<bool> regimes;  // cold?
    if (!a.cold) regimes.push_back(false);
    if (!a.warm) regimes.push_back(true);
    fmt::print("{}, single thread, median of {} runs after one warm-up; warm: freed memory kept between runs, cold: "
               "returned to the kernel after each\n",
               loop ? "Loop (weights=loop boundary=edge-only)" : "Catmull-Clark (boundary=edge-only)", a.repeats);
    fmt::print("{:<12} {:>6} {:<11} {:>11} {:>12} {:>10} {:>9} {:>8} {:<6}\n", "input", "levels", "impl", "input faces",
               "output faces", "median ms", "x core", "RSS MB", "memory");
    std::vector<BenchRecord> records;
    for (const BenchInput& in : inputs) {
        const std::vector<BenchRecord> r = run_bench({in}, SchemeRule{}, a.repeats, regimes);
        for (const BenchRecord& b : r) {
            const auto core = std::find_if(r.begin(), r.end(), [&](const BenchRecord& c) { return c.impl == "core" && c.memory == b.memory; });
            if (b.status != "ok")
                fmt::print("{:<12} {:>6} {:<11} {} ({})\n", b.input, b.levels, b.impl, b.status, b.memory);
            else
                fmt::print("{:<12} {:>6} {:<11} {:>11} {:>12} {:>10.2f} {:>9.2f} {:>8.0f} {:<6}\n", b.input, b.levels, b.impl,
                           b.input_faces, b.output_faces, b.median_ms, b.median_ms / core->median_ms, b.peak_rss_mb, b.memory);
        }
        std::fflush(stdout);
        records.insert(records.end(), r.begin(), r.end());
    }
    fmt::print("\n");
    return records;
}

/// The refinement rows of Loop and Catmull-Clark (the sections asked for), the goals against the
/// references at every size of at least kBenchGoalMinFaces output faces, the floor that memory
/// bandwidth sets (the output's bytes written at the write bandwidth measured in this run), and
/// core Loop's goals on its own figures (the floor; cold over warm).
nlohmann::json print_refinement_bench(const BenchArgs& a, nlohmann::json& goals_json, nlohmann::json& core_goals_json,
                                      nlohmann::json& bandwidth_json) {
    std::vector<BenchRecord> records;
    for (Scheme scheme : {Scheme::Loop, Scheme::CatmullClark}) {
        if (!a.runs(to_string(scheme))) continue;
        const std::vector<BenchRecord> r = print_scheme_rows(a, scheme);
        records.insert(records.end(), r.begin(), r.end());
    }
    const Bandwidth bw = measure_bandwidth(a.repeats);
    bandwidth_json = {{"write_gbs", bw.write_gbs}, {"copy_gbs", bw.copy_gbs}, {"buffer_bytes", bw.buffer_bytes}};
    fmt::print("memory bandwidth here: write {:.1f} GB/s, copy {:.1f} GB/s (best of {} passes over {} MiB)\n", bw.write_gbs,
               bw.copy_gbs, a.repeats, bw.buffer_bytes >> 20);
    goals_json = nlohmann::json::array();
    for (const BenchGoal& g : bench_goals(records)) {
        const double floor = floor_ms(g.scheme, g.output_faces, bw.write_gbs);
        fmt::print("goal ({} {}): core {:.2f}x faster than the fastest reference ({}) on {} at {} levels ({} output faces, "
                   "core {:.2f} ms, peak RSS {:.0f} MB): {} (target {}x); bandwidth floor {:.2f} ms, core {:.1f}x above it\n",
                   g.scheme, g.memory, g.ratio, g.fastest_reference, g.input, g.levels, g.output_faces, g.core_ms,
                   g.core_peak_rss_mb, g.met() ? "met" : "NOT met", g.target, floor, g.core_ms / floor);
        nlohmann::json j = to_json(g);
        j["floor_ms"] = floor;
        j["core_over_floor"] = g.core_ms / floor;
        goals_json.push_back(j);
    }
    core_goals_json = nlohmann::json::array();
    for (const CoreGoal& g : core_goals(records, bw.write_gbs)) {
        if (g.kind == CoreGoal::Kind::Floor)
            fmt::print("goal ({} floor): core {:.2f}x the bandwidth floor on {} at {} levels ({} output faces, core {:.2f} ms "
                       "warm, floor {:.2f} ms): {} (target at most {}x)\n",
                       g.scheme, g.ratio, g.input, g.levels, g.output_faces, g.core_ms, g.base_ms,
                       g.met() ? "met" : "NOT met", g.target);
        else
            fmt::print("goal ({} cold over warm): core cold {:.2f}x its warm time on {} at {} levels ({} output faces, {:.2f} "
                       "against {:.2f} ms): {} (target at most {}x)\n",
                       g.scheme, g.ratio, g.input, g.levels, g.output_faces, g.core_ms, g.base_ms,
                       g.met() ? "met" : "NOT met", g.target);
        core_goals_json.push_back(to_json(g));
    }
    if (goals_json.empty()) fmt::print("goal: no input of at least {} output faces in this run\n", kBenchGoalMinFaces);
    nlohmann::json recs = nlohmann::json::array();
    for (const BenchRecord& r : records) recs.push_back(to_json(r));
    return recs;
}

int bench_command(const BenchArgs& a) {
    // The outputs' folders first: a path that cannot be written is named before minutes of timing.
    std::vector<std::string> paths;
    if (!a.json.empty()) paths.push_back(a.json);
    if (!a.out.empty()) paths.push_back((std::filesystem::path(a.out) / "bench.json").string());
    for (const std::string& path : paths) {
        const std::filesystem::path p(path);
        if (p.has_parent_path()) create_output_folder(p.parent_path().string());
        if (std::filesystem::is_directory(p)) throw InputError(path + ": is a folder; --json names the file to write");
    }
    nlohmann::json goals, core_goals, bandwidth;
    const nlohmann::json null;
    const nlohmann::json loop =
        a.runs("loop") || a.runs("catmull-clark") ? print_refinement_bench(a, goals, core_goals, bandwidth) : null;
    std::vector<int> valences = a.valences;
    if (valences.empty()) valences.assign(std::begin(kBenchValences), a.quick ? std::begin(kBenchValences) + 1 : std::end(kBenchValences));
    const nlohmann::json threads = a.runs("threads") ? print_thread_bench(a) : null;
    const nlohmann::json valence = a.runs("valence") ? print_valence_bench(valences, a.repeats) : null;
    const nlohmann::json stencils = a.runs("stencils") ? print_stencil_bench(a.quick, a.repeats) : null;
    const nlohmann::json curves = a.runs("curves") ? run_curve_bench(a.repeats) : null;
    const nlohmann::json surfaces = a.runs("sweep") ? run_surface_bench() : null;
    const nlohmann::json doc = {{"tool", "crossdiv bench"}, {"repeats", a.repeats}, {"goals", goals}, {"core_goals", core_goals},
                                {"bandwidth", bandwidth},
                                {"records", loop}, {"threads", threads}, {"valence", valence}, {"stencils", stencils},
                                {"curves", curves.is_null() ? null : curves["tessellation"]},
                                {"curve_timing", curves.is_null() ? null : curves["timing"]},
                                {"flattening_goal", curves.is_null() ? null : curves["goal"]}, {"adaptive_sweep", surfaces},
                                {"note", "references timed through their native refinement (loop_native, catmull_clark_native), "
                                         "output kept in the library's own structures"}};
    for (const std::string& path : paths) {
        write_text_file(path, verification::json_text(doc, 1) + "\n");
        fmt::print("bench results: {}\n", path);
    }
    if (!a.out.empty() && std::filesystem::exists(std::filesystem::path(a.out) / "results.json"))
        return finish_outputs(a.out, true);
    return 0;
}

}  // namespace

void add_bench_command(CLI::App& app, int& status) {
    add_command<BenchArgs>(app, "bench", "Time core Loop and Catmull-Clark against the references side by side (ratios, memory)", status,
                           bench_command);
}

}  // namespace crossdiv::cli
