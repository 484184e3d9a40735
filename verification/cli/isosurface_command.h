#pragma once
// The isosurface subcommand of the crossdiv CLI: marching cubes (volume/marching_cubes.h) over
// an implicit surface sampled at a resolution or a volume file, the mesh's facts, its distance
// to the exact surface, and scikit-image's marching cubes compared.

#include <CLI/CLI.hpp>

namespace crossdiv::cli {

/// Adds `isosurface`; when selected it stores its exit status in `status`.
void add_isosurface_command(CLI::App& app, int& status);

}  // namespace crossdiv::cli
