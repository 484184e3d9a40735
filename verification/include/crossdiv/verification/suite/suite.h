#pragma once
/// @file
/// Conformance suites: a manifest (cases x operations x references x tolerances), its
/// expansion into jobs, running a shard of them with worker processes, and the outputs
/// (results.json, results.csv, JUnit XML). The manifest format is documented in
/// reports/suite-manifest.md; the results in reports/results-schema.md.

#include <nlohmann/json.hpp>
#include <functional>
#include <string>
#include <vector>

#include "crossdiv/verification/comparisons/loop_comparison.h"

namespace crossdiv::verification {

/// One `case` line of a manifest: inputs x one operation with its rules and tier.
struct ManifestEntry {
    int line = 0;                     ///< in the manifest file
    std::vector<std::string> inputs;  ///< specs as inputs.h accepts them (collections allowed)
    std::string operation;            ///< "loop"
    LoopComparisonRequest request;    ///< rules, levels, references, tier, tolerance
};

struct Manifest {
    std::string file;  ///< where it was read from
    std::string name;  ///< the `suite` line
    double timeout_seconds = 60;
    std::vector<ManifestEntry> entries;
};

/// Reads a manifest. @throws ParseError naming the file and line of any bad statement.
Manifest read_manifest(const std::string& path);

/// The manifest `crossdiv suite` runs without an argument (verification/suites/default.suite).
std::string default_manifest_path();

/// One unit of work: an expanded input under one entry. `index` is its place in the whole
/// suite, the same on every machine with the same data, so shards can be merged.
struct SuiteJob {
    int index = 0;
    std::string input;
    const ManifestEntry* entry = nullptr;
    std::string id;  ///< "input | loop weights=.. boundary=.. L3 weak"
};

/// Every job of the manifest, in order. Collections whose data is absent expand to nothing.
std::vector<SuiteJob> expand_jobs(const Manifest& manifest);

/// Slice `shard` (1-based) of `count`: jobs whose index % count == shard - 1.
std::vector<SuiteJob> shard_jobs(const std::vector<SuiteJob>& jobs, int shard, int count);

/// Runs one job and returns its record (a comparison as to_json, plus "job", "id",
/// "manifest_line", "outcome"); writes error fields of divergences under `fields_dir`
/// (file names relative to the output folder go into the record). Never throws for bad
/// input: core's refusal is recorded.
nlohmann::json run_job(const SuiteJob& job, const std::string& out_dir);

/// Runs `jobs` with `workers` processes; `progress(done, total, record)` is called in this
/// process after each job. Records come back ordered by job index.
std::vector<nlohmann::json> run_jobs(const std::vector<SuiteJob>& jobs, int workers, const std::string& out_dir,
                                     const std::function<void(int, int, const nlohmann::json&)>& progress);

/// The outcome of one reference run in a record: "agree", "diverge (<class>)",
/// "ref-crashed", "ref-rejected", "ours-rejected (<class>)", "ours-failed".
std::string run_outcome(const nlohmann::json& case_record, const nlohmann::json& run);

/// One line for progress output: each reference's outcome, or core's refusal or failure.
std::string describe_record(const nlohmann::json& case_record);

/// Whether a run counts as a failure in JUnit: an unexplained divergence, or ours-failed.
bool run_is_failure(const nlohmann::json& case_record, const nlohmann::json& run);

/// Writes results.json, results.csv and junit.xml into `dir` from the suite's header
/// (name, manifest, shard, references) and its case records. Returns the summary written
/// into results.json ({"cases", "runs", "failures", "outcomes"}).
nlohmann::json write_suite_outputs(const std::string& dir, const nlohmann::json& header, const std::vector<nlohmann::json>& cases);

/// Joins the results.json of several shard folders into `out_dir` (records ordered by job,
/// error fields copied) and returns the summary. @throws InputError if a folder lacks
/// results.json, the suites differ, or two shards hold the same job.
nlohmann::json merge_suite_outputs(const std::vector<std::string>& dirs, const std::string& out_dir);

/// Renders report.md, index.html and the figures from results.json (and bench.json when
/// present) in `dir` with reports/make_report.py. Returns the python exit status.
int render_report(const std::string& dir);

}  // namespace crossdiv::verification
