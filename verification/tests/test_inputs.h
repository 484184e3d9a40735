#pragma once
// Inputs shared by the tests that run programs: the source tree (where the bundled subjects
// and program adapters are) and the bundled meshes as triangle meshes. One definition for the
// whole test binary, whose files are compiled in batches (CMake's unity build).
#include <string>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv::verification::test {

/// The source tree this build was configured from (test_paths.cpp).
const std::string& source_dir();
/// The crossdiv command-line program of this build (test_paths.cpp).
const std::string& crossdiv_cli();

/// The source tree this build was configured from.
inline const std::string kSource = source_dir();
/// The crossdiv command-line program of this build.
inline const std::string kCrossdiv = crossdiv_cli();

/// The bundled mesh `name` as triangles, its source named "test".
inline TriMesh bundled(const std::string& name) { return to_tri_mesh(datasets::bundled_mesh(name), "test"); }

}  // namespace crossdiv::verification::test
