#pragma once
// The catalog the scheme tests run over, and what they ask of a mesh.

#include <vector>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/mesh/poly_connectivity.h"

namespace crossdiv::verification::test {

/// The polygon meshes, then the bundled triangle meshes.
inline std::vector<datasets::BundledMesh> catalog() { return datasets::catalog_meshes(); }

/// Whether the mesh has a boundary edge.
inline bool open_mesh(const PolyMesh& m) {
    const PolyConnectivity c = build_poly_connectivity(m);
    for (int e = 0; e < c.num_edges(); ++e)
        if (c.is_boundary_edge(e)) return true;
    return false;
}

}  // namespace crossdiv::verification::test
