#pragma once
/// @file
/// The fans the eigen-analysis and the rule oracles refine: one extraordinary vertex and its
/// ring, slightly irregular so that no symmetry hides an eigen-direction or a wrong weight.

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv::verification {

/// Triangle fan: centre 0 (interior, valence n), ring 1..n on the boundary,
/// triangles (0, 1 + k, 1 + (k + 1) % n).
TriMesh loop_fan(int n);

/// Quad fan: centre 0, spoke ends 1 + 2k, face-opposite vertices 2 + 2k, quads
/// (0, s_k, r_k, s_k+1).
PolyMesh quad_fan(int n);

}  // namespace crossdiv::verification
