#pragma once
// Shape generators shared by the bundled meshes, the edge-case catalog and the benchmark
// mesh (internal to crossdiv_datasets). Every generator is deterministic.

#include <functional>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::datasets::shapes {

PolyMesh make(std::vector<Vec3> positions, const std::vector<std::vector<int>>& faces);

PolyMesh tetrahedron();
PolyMesh octahedron();
PolyMesh icosahedron();
PolyMesh cube_symmetric();   ///< each cube face split into 4 triangles around its centre
PolyMesh cube_asymmetric();  ///< each cube face split by one diagonal: valences 3 to 6

/// A (n+1) x (n+1) grid over [0,1]^2 with a smooth height field, one diagonal per quad.
PolyMesh open_patch(int n);
/// nx x ny quads over [0,1]^2 at z = height(x, y); quads split along one diagonal, or the
/// two diagonals alternating (then every corner has one or two faces in turn).
PolyMesh grid_patch(int nx, int ny, const std::function<double(double, double)>& height, bool alternate_diagonals);
/// Regular torus (valence 6), nu x nv quads split in two.
PolyMesh torus(int nu, int nv, double R, double r);
/// Torus whose quad diagonals follow a fixed hash: valences 4..8, 2 nu nv faces.
PolyMesh irregular_torus(int nu, int nv);
/// One interior vertex of valence n inside a boundary ring.
PolyMesh fan(int n);
/// One boundary vertex with k incident faces (k + 2 vertices, k triangles).
PolyMesh boundary_fan(int k);
/// Closed sphere-like mesh with two poles of valence n and `rings` parallels.
PolyMesh pole(int n, int rings);
/// Two triangles back to back: closed, every vertex and edge of valence 2.
PolyMesh pillow();
/// Polygon meshes for the schemes that take any polygon.
PolyMesh quad_cube();                      ///< six quads, valence 3 corners
PolyMesh quad_grid(int n, double bend);    ///< n x n quads, open, z = bend (x^2 - y^2): four one-face corners
PolyMesh quad_torus(int nu, int nv);       ///< nu x nv quads, every vertex of valence 4, slightly irregular radii
PolyMesh prism(int n);                     ///< two n-gons and n quads, closed
PolyMesh quad_fan(int n);                  ///< n quads around one interior vertex of valence n, open
/// A slab with `holes` square holes through it: closed, genus = holes.
PolyMesh slab_with_holes(int holes);

}  // namespace crossdiv::datasets::shapes
