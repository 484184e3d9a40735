#pragma once
/// @file
/// OpenSubdiv 3.5 (Far) adapter: uniform Loop refinement through Far::TopologyRefiner and
/// Far::PrimvarRefinerReal<double>.

#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::opensubdiv {

/// OpenSubdiv's Loop has Loop's 1987 weights only; both boundary rules map to Sdc options
/// (EdgeOnly -> VTX_BOUNDARY_EDGE_ONLY, EdgeAndCorner -> VTX_BOUNDARY_EDGE_AND_CORNER; the
/// library default, VTX_BOUNDARY_NONE, would make boundary faces holes and is never used).
bool supports(const LoopOptions& options);

/// `levels` uniform Loop levels. Vertex positions are interpolated level by level in double
/// precision; the last level has full topology (fullTopologyInLastLevel), so its edges and
/// Limit() are available to later checks. Refined vertices: the parent level's vertices keep
/// their indices, then one per edge (nv + edge index), as the trace shows.
/// @throws Rejected for Warren weights or when Far's factory reports a topology error.
LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels);

/// The same refinement in the library's own structures, with nothing converted back: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as loop().
size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels);

/// "OpenSubdiv 3.5.0" (from opensubdiv/version.h).
std::string version();

}  // namespace crossdiv::adapters::opensubdiv
