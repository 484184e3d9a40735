#pragma once
/// @file
/// The suite's output files from its records: results.json (header, summary, cases),
/// results.csv (one row per run), junit.xml (one testcase per run); and `crossdiv merge`,
/// which joins shard folders into one. Formats: reports/results-schema.md.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/verification/suite/case_record.h"

namespace crossdiv::verification {

/// The counts the summary reports.
struct SuiteSummary {
    int cases = 0, runs = 0, failures = 0;
    std::map<std::string, int> outcomes;  ///< outcome label -> runs
};

SuiteSummary summarize(const std::vector<CaseRecord>& cases);

/// Writes results.json, results.csv and junit.xml into `dir` from the suite's header (name,
/// manifest, shard, references, ...) and its records; returns the summary written.
SuiteSummary write_suite_outputs(const std::string& dir, const nlohmann::json& header, const std::vector<CaseRecord>& cases);

/// Joins the results.json of several shard folders into `out_dir` (records ordered by job,
/// error fields copied) and returns the summary. @throws InputError if a folder lacks
/// results.json, the suites differ, or two shards hold the same job.
SuiteSummary merge_suite_outputs(const std::vector<std::string>& dirs, const std::string& out_dir);

/// Removes the folders of files a suite run writes beside its results (views/, minimal/) from
/// `dir` before a run into it, so that the folder holds this run's files only (the report lists
/// this run's, and a merge copies a shard's whole folders).
/// @throws InputError naming the folder when it cannot be removed.
void clear_previous_run_files(const std::string& dir);

}  // namespace crossdiv::verification
