#pragma once
// The bench subcommand of the crossdiv CLI.

#include <CLI/CLI.hpp>

namespace crossdiv::cli {

/// Adds `bench`; when selected it stores its exit status in `status`.
void add_bench_command(CLI::App& app, int& status);

}  // namespace crossdiv::cli
