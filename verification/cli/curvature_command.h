#pragma once
// The curvature subcommand of the crossdiv CLI: discrete curvature of a triangle mesh
// (mesh/discrete_curvature.h), the Gauss-Bonnet sum, each curvature estimator among the
// references compared, per-vertex values as CSV, and the mesh coloured by a curvature as OBJ.

#include <CLI/CLI.hpp>

namespace crossdiv::cli {

/// Adds `curvature`; when selected it stores its exit status in `status`.
void add_curvature_command(CLI::App& app, int& status);

}  // namespace crossdiv::cli
