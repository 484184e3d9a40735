#pragma once
// The mesh subcommands of the crossdiv CLI: subdivide, compare, check, datasets, edgecases, diff.

#include <CLI/CLI.hpp>

namespace crossdiv::cli {

/// Adds the subcommands; the one selected stores its exit status in `status`.
void add_mesh_commands(CLI::App& app, int& status);

}  // namespace crossdiv::cli
