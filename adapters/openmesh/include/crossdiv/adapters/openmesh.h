#pragma once
/// @file
/// OpenMesh 9 adapter: Subdivider::Uniform::LoopT on the double-precision OpenMesh::TriMesh.

#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::openmesh {

/// LoopT has Loop's weights and one boundary rule, the 1-6-1 boundary vertex and midpoint
/// boundary edge (our EdgeOnly); it has no corner rule.
bool supports(const LoopOptions& options);

/// `levels` LoopT steps, one call per level so that every level can be read. LoopT keeps the
/// old vertices' handles and appends one vertex per split edge; faces are renumbered.
/// LoopT's weight table defaults to valences below 50 and is read unchecked above it, so it
/// is sized to the mesh's largest valence first (init_weights, public API).
/// @throws Rejected for options it lacks, or when OpenMesh refuses a face (complex edge or
///         vertex), naming the face.
LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels);

/// The same refinement in the library's own structures, with nothing converted back: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as loop().
size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels);

/// "OpenMesh 9.0".
std::string version();

}  // namespace crossdiv::adapters::openmesh
