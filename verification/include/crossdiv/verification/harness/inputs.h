#pragma once
/// @file
/// Input names the CLI accepts: a mesh file (.obj, .off; .dae, .ply, .stl through Assimp), `bundled:NAME`, `edgecase:NAME`, or a
/// collection: `bundled:all`, `edgecases:all`, `course:all` (../shared/data/c3100/objs),
/// `meshedit:all` (../shared/data/meshedit/dae), `cgal:all` (datasets/cgal).

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// Expands collections into single inputs, in a stable order. A collection whose folder is
/// absent expands to nothing. @throws InputError for an unknown collection.
std::vector<std::string> expand_inputs(const std::vector<std::string>& specs);

/// Loads one input. @throws InputError / ParseError naming the file and line.
PolyMesh load_input(const std::string& spec);

}  // namespace crossdiv::verification
