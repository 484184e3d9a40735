#pragma once
/// @file analytic_surfaces.h
/// Triangle meshes whose vertices lie exactly on a surface with known curvature, at a chosen
/// resolution: the inputs of convergence tables (discrete curvature against the analytic
/// values as the mesh is refined).

#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv::datasets {

/// The unit sphere: the icosahedron, each triangle split into four by its edge midpoints,
/// pushed onto the sphere, `level` times (10 4^level + 2 vertices; valence 5 at the 12
/// original vertices, 6 elsewhere). @throws InputError for level outside 0..8.
TriMesh icosphere(int level);

/// The torus (R + r cos v)(cos u, sin u, 0) + r sin v (0, 0, 1) sampled at u = 2 pi i / nu,
/// v = 2 pi j / nv (vertex i nv + j), each quad split along the same diagonal; every vertex
/// of valence 6, faces outward. @throws InputError unless nu, nv >= 3 and 0 < r < R.
TriMesh regular_torus(int nu, int nv, double R, double r);

}  // namespace crossdiv::datasets
