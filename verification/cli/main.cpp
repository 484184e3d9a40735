// crossdiv: the command-line front of the testbed. Exit codes: 0 success (compare: every
// reference agrees), 1 compare found a disagreement, 2 bad input or usage (with a message).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_split_flip.h"
#include "crossdiv/verification/bench/bench.h"
#include "crossdiv/verification/harness/inputs.h"
#include "crossdiv/verification/comparisons/loop_comparison.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/suite/manifest.h"
#include "crossdiv/verification/suite/outputs.h"
#include "crossdiv/verification/suite/report.h"
#include "crossdiv/verification/suite/runner.h"
#include "curve_commands.h"
#include "edit_commands.h"
#include "scheme_commands.h"
#include "surface_commands.h"

namespace {

using namespace crossdiv;
using namespace crossdiv::verification;

struct SchemeArgs {
    std::string scheme = "loop";
    std::string weights = "loop";
    std::string boundary;  ///< empty: the scheme's default (edge-only, chaikin-boundary, count-from-input)
    int levels = 1;
    std::string creasing;  ///< empty: the input's t creasemethod tag, else uniform

    void add_to(CLI::App& app) {
        app.add_option("--scheme", scheme, "Subdivision scheme")
            ->check(CLI::IsMember({"loop", "catmull-clark", "doo-sabin", "sqrt3", "butterfly", "modified-butterfly"}))
            ->capture_default_str();
        app.add_option("--weights", weights, "Even-vertex weight family: loop (Loop 1987) or warren (3/(8n))")
            ->check(CLI::IsMember({"loop", "warren"}))
            ->capture_default_str();
        app.add_option("--boundary", boundary,
                       "Boundary rule. loop: edge-only (default) or edge-and-corner; catmull-clark: those and "
                       "midpoint-average (OpenMesh's); doo-sabin: chaikin-boundary (default) or drop-border-faces "
                       "(CGAL's); sqrt3, when the boundary is refined: count-from-input (default) or "
                       "restart-each-level (a library called once per level)")
            ->check(CLI::IsMember({"edge-only", "edge-and-corner", "midpoint-average", "chaikin-boundary",
                                   "drop-border-faces", "count-from-input", "restart-each-level"}));
        app.add_option("--levels", levels, "Number of subdivision levels")->check(CLI::Range(0, 12))->capture_default_str();
        app.add_option("--crease-method", creasing,
                       "Decay of semi-sharp crease tags (loop, catmull-clark): uniform (OpenSubdiv's default) or "
                       "chaikin. Default: the input's 't creasemethod' tag, else uniform")
            ->check(CLI::IsMember({"uniform", "chaikin"}));
    }
    cli::PolySchemeArgs poly() const { return {scheme, boundary, levels, creasing}; }
    LoopOptions options() const {
        if (!boundary.empty() && boundary != "edge-only" && boundary != "edge-and-corner")
            throw InputError("loop has no boundary rule '" + boundary + "' (edge-only, edge-and-corner)");
        return {weights == "loop" ? LoopWeights::Loop : LoopWeights::Warren,
                boundary == "edge-and-corner" ? LoopBoundary::EdgeAndCorner : LoopBoundary::EdgeOnly};
    }
};

/// Loop output larger than this is refused before any work: core holds ~100 bytes per face
/// over all levels and a reference several times that, so 64M faces is the most a 24 GB
/// machine refines with the three references side by side.
constexpr long long kMaxOutputFaces = 64LL << 20;

void check_output_size(long long faces, int levels, const std::string& name) {
    for (int l = 0; l < levels; ++l) faces *= 4;
    if (faces > kMaxOutputFaces)
        throw InputError(name + ": " + std::to_string(levels) + " levels would produce " + std::to_string(faces) +
                         " faces, over the limit of " + std::to_string(kMaxOutputFaces) + "; use fewer levels");
}

void check_output_size(const TriMesh& mesh, int levels, const std::string& name) {
    check_output_size(mesh.num_faces(), levels, name);
}

/// Loop on a crease-tagged input: core's generic step, or OpenSubdiv, the one reference with
/// crease rules; the others (and split-and-flip) have none and refuse.
int run_loop_subdivide_creased(const std::string& in, const PolyMesh& input, const SchemeArgs& s,
                               const std::string& impl, const std::string& out) {
    LoopOptions o = s.options();
    o.creasing = cli::crease_method(s.creasing, input);
    check_output_size(input.num_faces(), s.levels, in);
    PolyMesh result;
    RefineRequest request{Scheme::Loop, {}, s.levels};
    request.rule.loop = o;
    const Implementation& chosen = find_implementation(impl == "split-flip" ? "core" : impl);
    const SchemeSupport* support = chosen.support(Scheme::Loop);
    if (impl != "split-flip" && support && support->creases) {
        if (!chosen.applies(Scheme::Loop, request.rule))
            throw InputError(impl + " has no Loop with weights=" + std::string(to_string(o.weights)));
        try {
            result = chosen.refine_last(input, request);
        } catch (const adapters::Rejected& e) {
            throw InputError(impl + " refused " + in + ": " + e.what());
        }
    } else {
        throw InputError(in + " has crease or corner tags; " + impl +
                         " has no crease rules (core and opensubdiv have; drop the tags to compare the smooth scheme)");
    }
    write_mesh(out, result);
    fmt::print("{}: {} vertices, {} faces, {} crease and {} corner tag(s) -> {} ({} vertices, {} faces, {} level(s), "
               "{} decay, {})\n",
               in, input.num_vertices(), input.num_faces(), input.creases.edges.size(), input.creases.vertices.size(),
               out, result.num_vertices(), result.num_faces(), s.levels, to_string(o.creasing), impl);
    return 0;
}

int run_subdivide(const std::string& in, const SchemeArgs& s, const std::string& impl, const std::string& out) {
    if (s.scheme != "loop") {
        if (impl == "split-flip") throw InputError("split-flip is Loop's method; " + s.scheme + " has none");
        return cli::run_scheme_subdivide(in, s.poly(), impl, out);
    }
    const PolyMesh input = load_input(in);
    if (!input.creases.empty()) return run_loop_subdivide_creased(in, input, s, impl, out);
    const TriMesh mesh = to_tri_mesh(input, "Loop subdivision");
    check_output_size(mesh, s.levels, in);
    PolyMesh result;
    if (impl == "core") {
        result = to_poly_mesh(loop_subdivide(mesh, s.options(), s.levels));
    } else if (impl == "split-flip") {
        TriMesh level = mesh;
        for (int l = 0; l < s.levels; ++l) level = loop_by_split_and_flip(level, s.options());
        result = to_poly_mesh(level);
    } else {
        const Implementation& ref = *select_references(Scheme::Loop, {impl}).front();
        RefineRequest request{Scheme::Loop, {}, s.levels};
        request.rule.loop = s.options();
        if (!ref.applies(Scheme::Loop, request.rule))
            throw InputError(impl + " has no Loop with weights=" + s.weights + " boundary=" + std::string(to_string(s.options().boundary)));
        result = ref.refine(input, request).back();
    }
    write_mesh(out, result);
    fmt::print("{}: {} vertices, {} faces -> {} ({} vertices, {} faces, {} level(s), {})\n", in, mesh.num_vertices(),
               mesh.num_faces(), out, result.num_vertices(), result.num_faces(), s.levels, impl);
    return 0;
}

void print_table(const LoopComparison& c) {
    fmt::print("\n{} ({} vertices, {} faces) loop weights={} boundary={} levels={} (core {:.3f} s)\n", c.input,
               c.input_vertices, c.input_faces, to_string(c.options.weights), to_string(c.options.boundary), c.levels,
               c.core_seconds);
    fmt::print("  {:<11} {:<9} {:<13} {:<9} {:<8} {:>10} {:>10}  {}\n", "reference", "status", "verdict", "match",
               "topology", "max rel", "rms rel", "class / explanation");
    for (const ReferenceRun& r : c.runs) {
        const bool ok = r.outcome.status == RunStatus::Ok;
        fmt::print("  {:<11} {:<9} {:<13} {:<9} {:<8} {:>10} {:>10}  {}{}\n", r.reference,
                   to_string(r.outcome.status), to_string(r.verdict),
                   ok ? to_string(r.correspondence.method) : "-",
                   ok ? (r.comparison.topology_equal() ? "equal" : "differs") : "-",
                   ok ? fmt::format("{:.3g}", r.comparison.max_rel) : "-",
                   ok ? fmt::format("{:.3g}", r.comparison.rms_rel) : "-",
                   r.divergence_class == DivergenceClass::None ? "" : std::string(to_string(r.divergence_class)) + ": ",
                   r.explanation);
        if (ok && r.verdict == Verdict::Diverge)
            for (const WorstVertex& w : r.comparison.worst)
                fmt::print("      vertex {:>6} valence {:>2} {:<8} dist {:.3g}  core ({:.6g}, {:.6g}, {:.6g})  "
                           "{} ({:.6g}, {:.6g}, {:.6g})\n",
                           w.ours_index, w.valence, w.boundary ? "boundary" : "interior", w.distance, w.ours.x(),
                           w.ours.y(), w.ours.z(), r.reference, w.ref.x(), w.ref.y(), w.ref.z());
    }
}

int run_compare(const std::vector<std::string>& specs, const SchemeArgs& s, const std::string& against,
                const std::string& json_path, double timeout, bool no_isolate) {
    if (s.scheme != "loop") return cli::run_scheme_compare(specs, s.poly(), against, json_path, timeout, no_isolate);
    LoopComparisonRequest req;
    req.options = s.options();
    req.levels = s.levels;
    req.timeout_seconds = timeout;
    req.isolate = !no_isolate;
    for (size_t b = 0, e; b < against.size(); b = e + 1) {
        e = against.find(',', b);
        if (e == std::string::npos) e = against.size();
        if (e > b) req.references.push_back(against.substr(b, e - b));
    }
    select_references(Scheme::Loop, req.references);  // fail early on a typo

    const std::vector<std::string> inputs = expand_inputs(specs);
    if (inputs.empty()) throw InputError("no inputs (a collection folder may be absent)");
    // Load and validate every input before running anything: bad input is exit 2.
    // Crease-tagged inputs are compared with OpenSubdiv alone, level by level (the Loop
    // comparison's other references have no crease rules).
    std::vector<TriMesh> meshes;
    std::vector<PolyMesh> tagged(inputs.size());
    for (size_t i = 0; i < inputs.size(); ++i) {
        PolyMesh m = load_input(inputs[i]);
        if (!m.creases.empty()) {
            tagged[i] = std::move(m);
            meshes.emplace_back();
            continue;
        }
        meshes.push_back(to_tri_mesh(m, "Loop subdivision"));
        loop_input_connectivity(meshes.back());
        check_output_size(meshes.back(), s.levels, inputs[i]);
    }
    nlohmann::json results = nlohmann::json::array();
    bool all_agree = true;
    for (size_t i = 0; i < inputs.size(); ++i) {
        if (!tagged[i].creases.empty()) {
            nlohmann::json record;
            all_agree &= cli::compare_loop_creases(tagged[i], inputs[i], s.weights, s.boundary,
                                                   cli::crease_method(s.creasing, tagged[i]), s.levels, timeout,
                                                   !no_isolate, record);
            results.push_back(record);
            continue;
        }
        const LoopComparison c = compare_loop(meshes[i], inputs[i], req);
        print_table(c);
        all_agree &= c.all_agree();
        results.push_back(to_json(c));
    }
    if (!json_path.empty()) cli::write_json(json_path, {{"tool", "crossdiv compare"}, {"comparisons", results}});
    fmt::print("\n{}\n", all_agree ? "every reference agrees" : "some references disagree (see above)");
    return all_agree ? 0 : 1;
}

int run_check(const std::string& in) {
    const PolyMesh mesh = load_input(in);
    const auto issues = check_mesh(mesh);
    int errors = 0;
    for (const std::string& note : mesh.source.notes) fmt::print("note: {}\n", note);
    for (const MeshIssue& i : issues) {
        errors += i.severity == Severity::Error;
        fmt::print("{} [{}] {}\n", i.severity == Severity::Error ? "error" : "warning", to_string(i.kind), i.message);
    }
    if (errors == 0) errors += cli::print_halfedge_report(mesh);
    fmt::print("{}: {} vertices, {} faces, {} error(s), {} warning(s)\n", in, mesh.num_vertices(), mesh.num_faces(),
               errors, issues.size() - errors);
    return errors ? 2 : 0;
}

int run_datasets(const std::string& dir) {
    std::filesystem::create_directories(dir);
    for (const auto& b : datasets::bundled_meshes()) {
        const std::string path = (std::filesystem::path(dir) / (b.name + ".obj")).string();
        write_mesh(path, b.mesh);
        fmt::print("{:<48} {}\n", path, b.description);
    }
    return 0;
}

int run_edgecases(const std::string& dir) {
    std::filesystem::create_directories(dir);
    for (const auto& c : datasets::edge_cases()) {
        const std::string path = (std::filesystem::path(dir) / (c.name + ".obj")).string();
        write_mesh(path, c.mesh);
        fmt::print("{:<48} {}{}\n", path, c.description, c.valid_loop_input ? "" : " [invalid Loop input]");
    }
    return 0;
}

/// Parses "I/N". @throws InputError.
std::pair<int, int> parse_shard(const std::string& s) {
    const size_t slash = s.find('/');
    try {
        if (slash != std::string::npos) return {std::stoi(s.substr(0, slash)), std::stoi(s.substr(slash + 1))};
    } catch (const std::exception&) {
    }
    throw InputError("--shard " + s + ": expected I/N, e.g. 2/4");
}

void print_outcome_summary(const SuiteSummary& summary) {
    fmt::print("\n{} cases, {} reference runs, {} failure(s)\n", summary.cases, summary.runs, summary.failures);
    for (const auto& [outcome, n] : summary.outcomes) fmt::print("  {:>5}  {}\n", n, outcome);
}

int finish_outputs(const std::string& dir, bool report) {
    if (report) {
        if (render_report(dir) != 0) {
            std::cerr << "crossdiv: reports/make_report.py failed (its message is above; it needs /usr/bin/python3 "
                         "with matplotlib: apt-get install python3-matplotlib)\n";
            return 1;
        }
        fmt::print("report: {}/report.md and {}/index.html\n", dir, dir);
    }
    return 0;
}

int run_suite(const std::string& manifest_path, const std::string& out, int jobs, const std::string& shard,
              bool report) {
    const Manifest manifest = read_manifest(manifest_path.empty() ? default_manifest_path() : manifest_path);
    const std::vector<SuiteJob> all = expand_jobs(manifest);
    if (all.empty())
        throw InputError(manifest.file + ": the suite expands to no jobs (are the collections' folders absent?)");
    const auto [shard_i, shard_n] = parse_shard(shard);
    const std::vector<SuiteJob> mine = shard_jobs(all, shard_i, shard_n);
    fmt::print("suite {} ({}): {} jobs, shard {}/{} runs {} with {} worker(s)\n", manifest.name, manifest.file, all.size(),
               shard_i, shard_n, mine.size(), jobs);
    const bool tty = isatty(STDOUT_FILENO);
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<CaseRecord> records = run_jobs(mine, jobs, out, [&](int done, int total, const CaseRecord& rec) {
        if (tty) {
            const int width = 30, filled = total ? width * done / total : width;
            fmt::print("\r\033[K[{}{}] {}/{} {}", std::string(filled, '#'), std::string(width - filled, '.'), done, total,
                       rec.id.substr(0, 60));
            if (done == total) fmt::print("\n");
        } else {
            fmt::print("[{}/{}] {}: {}\n", done, total, rec.id, describe_record(rec));
        }
        std::fflush(stdout);
    });
    nlohmann::json refs = nlohmann::json::array();
    for (const Implementation* r : references_for(Scheme::Loop)) refs.push_back({{"name", r->name()}, {"version", r->version()}});
    nlohmann::json curve_refs = nlohmann::json::array();
    for (const Implementation* r : references_with(&Capabilities::spline_evaluation))
        curve_refs.push_back({{"name", r->name()}, {"version", r->version()}});
    const nlohmann::json header = {
        {"tool", "crossdiv suite"}, {"schema_version", kResultsSchemaVersion}, {"suite", manifest.name}, {"manifest", manifest.file},
        {"shard", fmt::format("{}/{}", shard_i, shard_n)}, {"jobs_total", all.size()}, {"jobs_run", mine.size()},
        {"workers", jobs}, {"references", refs}, {"curve_references", curve_refs},
        {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()}};
    const SuiteSummary summary = write_suite_outputs(out, header, records);
    cli::print_curve_tables(records);
    cli::print_surface_tables(records);
    fmt::print("results: {0}/results.json, {0}/results.csv, {0}/junit.xml\n", out);
    print_outcome_summary(summary);
    const int report_status = finish_outputs(out, report);
    return summary.failures ? 1 : report_status;
}

int run_merge(const std::vector<std::string>& dirs, const std::string& out, bool report) {
    const SuiteSummary summary = merge_suite_outputs(dirs, out);
    fmt::print("merged {} folder(s) into {}\n", dirs.size(), out);
    print_outcome_summary(summary);
    const int report_status = finish_outputs(out, report);
    return summary.failures ? 1 : report_status;
}

int run_diff(const std::string& in, const SchemeArgs& s, const std::string& against, const std::string& out_dir) {
    const TriMesh mesh = to_tri_mesh(load_input(in), "Loop subdivision");
    loop_input_connectivity(mesh);
    check_output_size(mesh, s.levels, in);
    LoopComparisonRequest req;
    req.options = s.options();
    req.levels = s.levels;
    req.references = {against};
    select_references(Scheme::Loop, {against});
    const ShrinkResult r = shrink_divergence(mesh, in, req);
    const ReferenceRun& orig = r.original.runs[0];
    fmt::print("{} ({} faces): {} diverges from core, class {}: {}\n", in, mesh.num_faces(), against,
               to_string(r.divergence_class), orig.explanation);
    std::filesystem::create_directories(out_dir);
    const std::string ring = (std::filesystem::path(out_dir) / "neighbourhood.obj").string();
    const std::string minimal = (std::filesystem::path(out_dir) / "minimal.obj").string();
    write_mesh(ring, to_poly_mesh(r.neighbourhood));
    write_mesh(minimal, to_poly_mesh(r.minimal));
    const ReferenceRun& m = r.minimal_comparison.runs[0];
    fmt::print("neighbourhood: {} ({} faces, {})\n", ring, r.neighbourhood.num_faces(),
               r.k ? fmt::format("{}-ring of the worst vertex's coarse ancestors", r.k) : std::string("the whole mesh"));
    fmt::print("minimal:       {} ({} faces, {} vertices) after {} comparisons: {} ({})\n", minimal, r.minimal.num_faces(),
               r.minimal.num_vertices(), r.tests, to_string(m.divergence_class), m.explanation);
    fmt::print("reproduce:     crossdiv compare {} --weights {} --boundary {} --levels {} --against {}\n", minimal,
               s.weights, to_string(s.options().boundary), s.levels, against);
    return 0;
}

/// The performance goal of the suite issue: core Loop at least this many times faster than
/// the fastest reference on the 20k-face closed mesh refined 2 levels.
constexpr double kBenchGoalRatio = 4.0;

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
    nlohmann::json goal = nullptr;
    for (const BenchRecord& core : records) {
        if (core.impl != "core" || core.levels != 2 || core.input_faces < 19000 || core.status != "ok") continue;
        const BenchRecord* fastest = nullptr;
        for (const BenchRecord& r : records)
            if (r.impl != "core" && r.input == core.input && r.levels == core.levels && r.status == "ok" &&
                (!fastest || r.median_ms < fastest->median_ms))
                fastest = &r;
        if (!fastest) continue;
        const double ratio = fastest->median_ms / core.median_ms;
        goal = {{"input", core.input}, {"levels", core.levels}, {"output_faces", core.output_faces},
                {"core_ms", core.median_ms}, {"fastest_reference", fastest->impl}, {"fastest_reference_ms", fastest->median_ms},
                {"ratio", ratio}, {"target_ratio", kBenchGoalRatio}, {"met", ratio >= kBenchGoalRatio},
                {"core_peak_rss_mb", core.peak_rss_mb}};
        fmt::print("\ngoal: core {:.2f}x faster than the fastest reference ({}) on {} at 2 levels ({} output faces, "
                   "core peak RSS {:.0f} MB): {} (target {}x)\n",
                   ratio, fastest->impl, core.input, core.output_faces, core.peak_rss_mb,
                   ratio >= kBenchGoalRatio ? "met" : "NOT met", kBenchGoalRatio);
    }
    const nlohmann::json curves = cli::run_curve_bench(repeats);
    const nlohmann::json surfaces = cli::run_surface_bench();
    nlohmann::json recs = nlohmann::json::array();
    for (const BenchRecord& r : records) recs.push_back(to_json(r));
    const nlohmann::json doc = {{"tool", "crossdiv bench"}, {"repeats", repeats}, {"memory", cold ? "cold" : "warm"},
                                {"goal", goal}, {"records", recs}, {"curves", curves["tessellation"]},
                                {"curve_timing", curves["timing"]}, {"adaptive_sweep", surfaces},
                                {"note", "references timed through their native refinement (loop_native), output kept "
                                         "in the library's own structures"}};
    std::vector<std::string> paths;
    if (!json_path.empty()) paths.push_back(json_path);
    if (!out_dir.empty()) paths.push_back((std::filesystem::path(out_dir) / "bench.json").string());
    for (const std::string& path : paths) {
        const std::filesystem::path p(path);
        if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
        std::ofstream(path) << doc.dump(1) << "\n";
        fmt::print("bench results: {}\n", path);
    }
    if (!out_dir.empty() && std::filesystem::exists(std::filesystem::path(out_dir) / "results.json"))
        return finish_outputs(out_dir, true);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"crossdiv: spline and subdivision algorithms verified against OpenSubdiv, OpenMesh and CGAL"};
    app.require_subcommand(1);

    SchemeArgs sub_args, cmp_args;
    std::string sub_in, sub_impl = "core", sub_out;
    auto* sub = app.add_subcommand("subdivide", "Subdivide a mesh with core or a reference");
    sub->add_option("input", sub_in, "Mesh file (.obj, .off) or bundled:NAME")->required();
    sub_args.add_to(*sub);
    sub->add_option("--impl", sub_impl, "Implementation (split-flip: our Loop by edge splits and flips)")
        ->check(CLI::IsMember({"core", "split-flip", "opensubdiv", "openmesh", "cgal"}))
        ->capture_default_str();
    sub->add_option("-o,--output", sub_out, "Output mesh (.obj, .off)")->required();

    std::vector<std::string> cmp_in;
    std::string against, json_path;  // empty: every reference that has the scheme
    double timeout = 120;
    bool no_isolate = false;
    auto* cmp = app.add_subcommand("compare", "Compare core with reference libraries");
    cmp->add_option("inputs", cmp_in, "Mesh files, bundled:NAME, bundled:all, course:all, cgal:all")->required();
    cmp_args.add_to(*cmp);
    cmp->add_option("--against", against,
                    "Comma-separated references (default: every one that has the scheme; sqrt3 also has "
                    "openmesh-one-call and cgal-one-call, all levels in one call)");
    cmp->add_option("--json", json_path, "Write the results as JSON to this file");
    cmp->add_option("--timeout", timeout, "Seconds a reference may run before it counts as hung")->capture_default_str();
    cmp->add_flag("--no-isolate", no_isolate, "Run references in this process (debugging; a crash ends the run)");

    std::string check_in;
    auto* chk = app.add_subcommand("check", "Report every problem of a mesh, by element");
    chk->add_option("input", check_in, "Mesh file or bundled:NAME")->required();

    std::string ds_out;
    auto* ds = app.add_subcommand("datasets", "Write the bundled meshes as OBJ files");
    ds->add_option("--out", ds_out, "Output folder")->required();

    std::string ec_out;
    auto* ec = app.add_subcommand("edgecases", "Write the edge-case catalog as OBJ files (one line each: what it tests)");
    ec->add_option("--out", ec_out, "Output folder")->required();

    std::string suite_manifest, suite_out = "out", suite_shard = "1/1";
    int suite_jobs = 2;
    bool suite_no_report = false;
    auto* suite = app.add_subcommand("suite", "Run a conformance suite; write results.json/.csv, junit.xml and the report");
    suite->add_option("manifest", suite_manifest, "Suite manifest (default: verification/suites/default.suite)");
    suite->add_option("--out", suite_out, "Output folder")->capture_default_str();
    suite->add_option("--jobs", suite_jobs, "Worker processes")->check(CLI::Range(1, 64))->capture_default_str();
    suite->add_option("--shard", suite_shard, "Run slice I of N (job index mod N = I - 1)")->capture_default_str();
    suite->add_flag("--no-report", suite_no_report, "Skip report.md/index.html (e.g. for shards merged later)");

    std::vector<std::string> merge_in;
    std::string merge_out = "out";
    bool merge_no_report = false;
    auto* merge = app.add_subcommand("merge", "Join the results of suite shards into one report");
    merge->add_option("dirs", merge_in, "Shard output folders")->required();
    merge->add_option("--out", merge_out, "Output folder")->capture_default_str();
    merge->add_flag("--no-report", merge_no_report, "Skip report.md/index.html");

    std::string report_dir;
    auto* rep = app.add_subcommand("report", "Render report.md and index.html from a suite output folder");
    rep->add_option("dir", report_dir, "Folder with results.json (and bench.json)")->required();

    SchemeArgs diff_args;
    std::string diff_in, diff_against, diff_out = "diff-out";
    auto* diff = app.add_subcommand("diff", "Shrink a divergence to the worst vertex's neighbourhood and a minimal mesh");
    diff->add_option("input", diff_in, "Mesh file, bundled:NAME or edgecase:NAME")->required();
    diff_args.add_to(*diff);
    diff->add_option("--against", diff_against, "The reference that diverges")
        ->required()
        ->check(CLI::IsMember({"opensubdiv", "openmesh", "cgal"}));
    diff->add_option("--out", diff_out, "Output folder")->capture_default_str();

    std::string bench_json, bench_out;
    int bench_repeats = 5;
    bool bench_quick = false, bench_cold = false;
    auto* bench = app.add_subcommand("bench", "Time core Loop against the references side by side (ratios, memory)");
    bench->add_option("--json", bench_json, "Write the records to this JSON file");
    bench->add_option("--out", bench_out, "Suite output folder: write bench.json there and re-render its report");
    bench->add_option("--repeats", bench_repeats, "Timed runs per measurement")->check(CLI::Range(1, 64))->capture_default_str();
    bench->add_flag("--quick", bench_quick, "Two mesh sizes only (320 and 20000 faces)");
    bench->add_flag("--cold", bench_cold, "Return freed memory to the kernel between repeats (page faults counted)");

    cli::TessellateArgs tess_args;
    auto* tess = app.add_subcommand("tessellate", "Tessellate every curve of an SWP or BZC file (points, tangents, normals, frames)");
    tess_args.add_to(*tess);
    cli::SweepArgs sweep_args;
    auto* sweep = app.add_subcommand("sweep", "Build every srev and gcyl record of an SWP file into an OBJ with normals");
    sweep_args.add_to(*sweep);
    cli::PatchArgs patch_args;
    auto* patch = app.add_subcommand("patch", "Tessellate the Bezier patches of a BEZ file into one welded OBJ with normals");
    patch_args.add_to(*patch);
    cli::EditArgs edit_args;
    auto* edit = app.add_subcommand("edit", "Flip and split edges in order on a half-edge mesh (edges as A-B, 0-based)");
    edit_args.add_to(*edit);
    cli::NormalsArgs normals_args;
    auto* normals = app.add_subcommand("normals", "Vertex normals (area, angle, uniform) against OpenMesh and CGAL");
    normals_args.add_to(*normals);
    cli::LimitArgs limit_args;
    auto* lim = app.add_subcommand("limit", "Limit positions of a level's vertices (Loop, Catmull-Clark), against OpenSubdiv");
    lim->add_option("input", limit_args.input, "Mesh file or bundled:NAME")->required();
    lim->add_option("--scheme", limit_args.scheme, "loop or catmull-clark")
        ->check(CLI::IsMember({"loop", "catmull-clark"}))
        ->capture_default_str();
    lim->add_option("--weights", limit_args.weights, "Loop weight family: loop or warren")->capture_default_str();
    lim->add_option("--boundary", limit_args.boundary, "edge-only or edge-and-corner")->capture_default_str();
    lim->add_option("--levels", limit_args.levels, "Level whose vertices are moved (0: the input)")->capture_default_str();
    lim->add_option("--against", limit_args.against, "opensubdiv: compare with PrimvarRefiner::Limit");
    lim->add_option("--json", limit_args.json, "Write the results as JSON");
    lim->add_option("-o,--output", limit_args.out, "Write the level with every vertex at its limit position");
    cli::SpectrumArgs spectrum_args;
    auto* spec = app.add_subcommand("spectrum", "Eigen table of the local subdivision matrices and the convergence table");
    spec->add_option("--scheme", spectrum_args.scheme, "loop, warren, catmull-clark or all")
        ->check(CLI::IsMember({"loop", "warren", "catmull-clark", "all"}))
        ->capture_default_str();
    spec->add_option("--valence", spectrum_args.valence, "N or A..B (3..64)")->capture_default_str();
    spec->add_option("--levels", spectrum_args.levels, "Levels of the convergence table")
        ->check(CLI::Range(2, 8))
        ->capture_default_str();
    spec->add_option("--json", spectrum_args.json, "Write both tables as JSON");
    cli::CasteljauArgs cast_args;
    auto* cast = app.add_subcommand("casteljau", "Every de Casteljau level of a Bezier curve at t");
    cast_args.add_to(*cast);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        if (*sub) return run_subdivide(sub_in, sub_args, sub_impl, sub_out);
        if (*cmp) return run_compare(cmp_in, cmp_args, against, json_path, timeout, no_isolate);
        if (*chk) return run_check(check_in);
        if (*ds) return run_datasets(ds_out);
        if (*ec) return run_edgecases(ec_out);
        if (*suite) return run_suite(suite_manifest, suite_out, suite_jobs, suite_shard, !suite_no_report);
        if (*merge) return run_merge(merge_in, merge_out, !merge_no_report);
        if (*rep) return finish_outputs(report_dir, true);
        if (*diff) return run_diff(diff_in, diff_args, diff_against, diff_out);
        if (*tess) return cli::run_tessellate(tess_args);
        if (*cast) return cli::run_casteljau(cast_args);
        if (*sweep) return cli::run_sweep(sweep_args);
        if (*patch) return cli::run_patch(patch_args);
        if (*edit) return cli::run_edit(edit_args);
        if (*normals) return cli::run_normals(normals_args);
        if (*lim) return cli::run_limit(limit_args);
        if (*spec) return cli::run_spectrum(spectrum_args);
        if (*bench) return run_bench_command(bench_json, bench_out, bench_repeats, bench_quick, bench_cold);
    } catch (const InputError& e) {
        std::cerr << "crossdiv: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "crossdiv: internal error: " << e.what() << "\n";
        return 3;
    }
    return 0;
}
