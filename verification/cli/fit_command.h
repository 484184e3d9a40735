#pragma once
// The fit subcommand of the crossdiv CLI: a Loop or Catmull-Clark limit surface fitted to a
// target mesh (subdiv/limit_fitting.h), from a given control mesh or one simplified from the
// target, with each iteration's distances and a reference's Hausdorff distance.

#include <CLI/CLI.hpp>

namespace crossdiv::cli {

/// Adds `fit`; when selected it stores its exit status in `status`.
void add_fit_command(CLI::App& app, int& status);

}  // namespace crossdiv::cli
