#pragma once
/// @file
/// The report of a suite folder: report.md, index.html and figures/, rendered from
/// results.json (and bench.json when present) by reports/make_report.py.

#include <string>

namespace crossdiv::verification {

/// Runs the report script on `dir` (Debian's /usr/bin/python3, which has matplotlib) from an
/// argument vector. Returns the script's exit status.
int render_report(const std::string& dir);

/// The schema version of results.json that this build writes (reports/results-schema.md).
inline constexpr int kResultsSchemaVersion = 5;

}  // namespace crossdiv::verification
