#pragma once
// Test doubles that seed a realistic bug into a core feature, shared by the tests that show
// the oracles and the suite catch it.

#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/surfaces/sweep_mesh.h"
#include "crossdiv/surfaces/sweep_surface.h"
#include "crossdiv/verification/harness/mesh_topology.h"

namespace crossdiv::verification::test {

/// Warren's beta mistyped as 3 / (9 n), applied to one refined level `fine` of `coarse`: each
/// interior vertex of valence n > 3 moved by (3 / (9 n) - 3 / (8 n)) times the sum of its
/// neighbours' offsets, which is what the slip does to the vertex mask.
inline void warren_beta_slip(const PolyMesh& coarse, PolyMesh& fine) {
    const MeshTopology t = mesh_topology(coarse);
    std::vector<Vec3> offsets(coarse.positions.size(), Vec3::Zero());
    for (const auto& [a, b] : t.edge_list) {
        offsets[a] += coarse.positions[b] - coarse.positions[a];
        offsets[b] += coarse.positions[a] - coarse.positions[b];
    }
    for (size_t v = 0; v < offsets.size(); ++v) {
        const int n = t.valence[v];
        if (!t.boundary_vertex[v] && n > 3) fine.positions[v] += (3.0 / (9.0 * n) - 3.0 / (8.0 * n)) * offsets[v];
    }
}

/// build_sweep with a tessellation that drops the profile's last sample: a surface of
/// revolution loses its last ring of profile points, and the construction, judging closedness
/// from its samples, calls it open.
inline SweepSurface sweep_dropping_last_point(const CurveFile& file, int k, const SweepOptions& o) {
    SweepSurface s = build_sweep(file, k, o);
    if (file.sweeps[static_cast<size_t>(k)].kind != SweepRecord::Kind::Revolution) return s;
    SweepGrid g = s.grid;
    const int n = g.ring_size - 1;
    std::vector<Vec3> p, nrm;
    for (int i = 0; i < g.rings; ++i)
        for (int j = 0; j < n; ++j) {
            p.push_back(g.at(i, j));
            nrm.push_back(g.normals[static_cast<size_t>(i) * g.ring_size + j]);
        }
    g.positions = std::move(p);
    g.normals = std::move(nrm);
    g.ring_size = n;
    g.profile_params.pop_back();
    s.grid = g;
    s.surface = mesh_sweep(g);
    s.closed = false;
    return s;
}

}  // namespace crossdiv::verification::test
