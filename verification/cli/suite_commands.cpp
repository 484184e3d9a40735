// The suite subcommands of the crossdiv CLI: suite, merge, report.
#include "suite_commands.h"

#include <fmt/format.h>
#include <unistd.h>

#include <charconv>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "command.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/suite/manifest.h"
#include "crossdiv/verification/suite/operations.h"
#include "crossdiv/verification/suite/output_folder_lock.h"
#include "crossdiv/verification/suite/outputs.h"
#include "crossdiv/verification/suite/report.h"
#include "crossdiv/verification/suite/runner.h"
#include "crossdiv/verification/suite/failure_shrink.h"
#include "curve_commands.h"
#include "surface_commands.h"

namespace crossdiv::cli {

using namespace crossdiv::verification;

namespace {

/// Parses "I/N". @throws InputError.
/// "I/N": two whole numbers and nothing else (1/3/4 and 1/3x are refused, not read as 1/3).
std::pair<int, int> parse_shard(const std::string& s) {
    const size_t slash = s.find('/');
    const auto whole = [](std::string_view t, int& out) {
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), out);
        return !t.empty() && ec == std::errc() && end == t.data() + t.size();
    };
    int i = 0, n = 0;
    if (slash != std::string::npos && whole(std::string_view(s).substr(0, slash), i) && whole(std::string_view(s).substr(slash + 1), n))
        return {i, n};
    throw InputError("--shard " + s + ": expected I/N, e.g. 2/4");
}

/// The whole suite's job list in one word (FNV-1a over the job ids, hex): shards of two versions
/// of a manifest with the same name and job count differ here, and merge refuses them.
std::string jobs_fingerprint(const std::vector<SuiteJob>& jobs) {
    uint64_t h = 1469598103934665603ull;
    for (const SuiteJob& j : jobs) {
        for (const char c : j.id + "\n") h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    }
    return fmt::format("{:016x}", h);
}

void print_outcome_summary(const SuiteSummary& summary) {
    fmt::print("\n{} cases, {} reference runs, {} failure(s)\n", summary.cases, summary.runs, summary.failures);
    for (const auto& [outcome, n] : summary.outcomes) fmt::print("  {:>5}  {}\n", n, outcome);
}

}  // namespace

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

namespace {

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
    const OutputFolderLock lock(out);
    clear_previous_run_files(out);
    const bool tty = isatty(STDOUT_FILENO);
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<CaseRecord> records = run_jobs(mine, jobs, out, [&](int done, int total, const CaseRecord& rec) {
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
    // Each subject's first failure and each failure of a library reference, shrunk to a minimal mesh.
    shrink_failures(mine, records, out, jobs);
    nlohmann::json refs = nlohmann::json::array();
    for (const Implementation* r : references_for(Scheme::Loop)) refs.push_back({{"name", r->name()}, {"version", r->version()}});
    nlohmann::json curve_refs = nlohmann::json::array();
    for (const Implementation* r : references_with(&Capabilities::spline_evaluation))
        curve_refs.push_back({{"name", r->name()}, {"version", r->version()}});
    const nlohmann::json header = {
        {"tool", "crossdiv suite"}, {"schema_version", kResultsSchemaVersion}, {"suite", manifest.name}, {"manifest", manifest.file},
        {"shard", fmt::format("{}/{}", shard_i, shard_n)}, {"jobs_total", all.size()}, {"jobs_run", mine.size()},
        {"jobs_fingerprint", jobs_fingerprint(all)},
        {"workers", jobs}, {"references", refs}, {"curve_references", curve_refs}, {"operations", operations_json()},
        {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()}};
    const SuiteSummary summary = write_suite_outputs(out, header, records);
    print_curve_tables(records);
    print_surface_tables(records);
    fmt::print("results: {0}/results.json, {0}/results.csv, {0}/junit.xml\n", out);
    print_outcome_summary(summary);
    const int report_status = finish_outputs(out, report);
    return summary.failures ? 1 : report_status;
}

int run_merge(const std::vector<std::string>& dirs, const std::string& out, bool report) {
    const OutputFolderLock lock(out);
    const SuiteSummary summary = merge_suite_outputs(dirs, out);
    fmt::print("merged {} folder(s) into {}\n", dirs.size(), out);
    print_outcome_summary(summary);
    const int report_status = finish_outputs(out, report);
    return summary.failures ? 1 : report_status;
}

struct SuiteArgs {
    std::string manifest, out = "out", shard = "1/1";
    int jobs = 2;
    bool no_report = false;
    void add_to(CLI::App& app) {
        app.add_option("manifest", manifest, "Suite manifest (default: verification/suites/default.suite)");
        app.add_option("--out", out, "Output folder")->capture_default_str();
        app.add_option("--jobs", jobs, "Worker processes")->check(CLI::Range(1, 64))->capture_default_str();
        app.add_option("--shard", shard, "Run slice I of N (job index mod N = I - 1)")->capture_default_str();
        app.add_flag("--no-report", no_report, "Skip report.md/index.html (e.g. for shards merged later)");
    }
};
int suite_command(const SuiteArgs& a) { return run_suite(a.manifest, a.out, a.jobs, a.shard, !a.no_report); }

struct MergeArgs {
    std::vector<std::string> dirs;
    std::string out = "out";
    bool no_report = false;
    void add_to(CLI::App& app) {
        app.add_option("dirs", dirs, "Shard output folders")->required();
        app.add_option("--out", out, "Output folder")->capture_default_str();
        app.add_flag("--no-report", no_report, "Skip report.md/index.html");
    }
};
int merge_command(const MergeArgs& a) { return run_merge(a.dirs, a.out, !a.no_report); }

struct ReportArgs {
    std::string dir;
    void add_to(CLI::App& app) { app.add_option("dir", dir, "Folder with results.json (and bench.json)")->required(); }
};
int report_command(const ReportArgs& a) {
    // The report reads results.json: a folder without one is not a suite's output (and the
    // script's traceback would blame matplotlib).
    const std::filesystem::path results = std::filesystem::path(a.dir) / "results.json";
    if (!std::filesystem::is_regular_file(results))
        throw InputError(results.string() + ": no results.json (not a suite output folder; crossdiv suite --out writes one)");
    return finish_outputs(a.dir, true);
}

}  // namespace

void add_suite_commands(CLI::App& app, int& status) {
    add_command<SuiteArgs>(app, "suite", "Run a conformance suite; write results.json/.csv, junit.xml and the report", status,
                           suite_command);
    add_command<MergeArgs>(app, "merge", "Join the results of suite shards into one report", status, merge_command);
    add_command<ReportArgs>(app, "report", "Render report.md and index.html from a suite output folder", status,
                            report_command);
}

}  // namespace crossdiv::cli
