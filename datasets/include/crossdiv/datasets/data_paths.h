#pragma once
/// @file
/// Where the optional real meshes and curves live on this machine: the CGAL demo meshes
/// unpacked into the datasets folder (install_cgal_meshes.sh), and the course files when the
/// project is checked out beside shared/.
///
/// The two folders are compiled into data_paths.cpp alone, outside the unity batches, so that
/// a clone in another folder recompiles one small file and the compiler cache serves the rest.

#include <filesystem>

namespace crossdiv::datasets {

/// The course inputs (SWP, BEZ, BZC, OBJ, DAE): `shared/data` beside the source tree. May not exist.
std::filesystem::path shared_data_dir();

/// The datasets folder of the source tree (holds `cgal/` once the CGAL demo meshes are unpacked).
std::filesystem::path datasets_dir();

}  // namespace crossdiv::datasets
