#pragma once
// The suite subcommands of the crossdiv CLI: suite, merge, report.

#include <CLI/CLI.hpp>
#include <string>

namespace crossdiv::cli {

/// Adds the subcommands; the one selected stores its exit status in `status`.
void add_suite_commands(CLI::App& app, int& status);

/// Renders the report of the suite folder `dir` when `report` is set (prints where, or why it
/// failed). Returns 0, or 1 when the report script failed.
int finish_outputs(const std::string& dir, bool report);

}  // namespace crossdiv::cli
