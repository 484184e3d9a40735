#pragma once
/// @file
/// CGAL 5.5 adapter: Subdivision_method_3::Loop_subdivision on
/// Surface_mesh<Simple_cartesian<double>::Point_3>. All CGAL code is in one translation unit.

#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::cgal {

/// Loop_mask_3 has Loop's weights, the midpoint border edge and the 1-6-1 border vertex
/// (our EdgeOnly); it has no corner rule.
bool supports(const LoopOptions& options);

/// `levels` Loop_subdivision calls of one iteration each, so that every level can be read.
/// @throws Rejected for options it lacks, or when Surface_mesh refuses a face (non-manifold
///         or inconsistently oriented), naming the face.
LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels);

/// The same refinement in the library's own structures, with nothing converted back: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as loop().
size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels);

/// "CGAL 5.5.1".
std::string version();

}  // namespace crossdiv::adapters::cgal
