#pragma once
// The multires subcommand of the crossdiv CLI: a Loop multiresolution hierarchy
// (subdiv/multiresolution.h) decomposed and recomposed, a base vertex edited.

#include <CLI/CLI.hpp>

namespace crossdiv::cli {

/// Adds `multires`; when selected it stores its exit status in `status`.
void add_multires_command(CLI::App& app, int& status);

}  // namespace crossdiv::cli
