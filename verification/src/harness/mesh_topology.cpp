#include "crossdiv/verification/harness/mesh_topology.h"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace crossdiv::verification {

MeshTopology mesh_topology(const PolyMesh& mesh) {
    MeshTopology t;
    t.vertices = mesh.num_vertices();
    t.faces = mesh.num_faces();
    std::vector<uint64_t> keys;
    keys.reserve(mesh.face_vertices.size());
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int n = mesh.face_size(f);
        for (int k = 0; k < n; ++k) {
            const uint64_t a = static_cast<uint32_t>(mesh.face(f)[k]), b = static_cast<uint32_t>(mesh.face(f)[(k + 1) % n]);
            keys.push_back(std::min(a, b) << 32 | std::max(a, b));
        }
    }
    std::sort(keys.begin(), keys.end());
    t.valence.assign(static_cast<size_t>(t.vertices), 0);
    t.boundary_vertex.assign(static_cast<size_t>(t.vertices), 0);
    std::vector<int> parent(static_cast<size_t>(t.vertices));
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (size_t i = 0; i < keys.size();) {
        size_t j = i;
        while (j < keys.size() && keys[j] == keys[i]) ++j;
        const int a = static_cast<int>(keys[i] >> 32), b = static_cast<int>(keys[i] & 0xffffffffu);
        t.edge_list.push_back({a, b});
        ++t.valence[a];
        ++t.valence[b];
        if (j - i == 1) {
            ++t.boundary_edges;
            t.boundary_vertex[a] = t.boundary_vertex[b] = 1;
            parent[find(a)] = find(b);
        }
        i = j;
    }
    t.edges = static_cast<int>(t.edge_list.size());
    t.euler = t.vertices - t.edges + t.faces;
    for (int v = 0; v < t.vertices; ++v) t.boundary_loops += t.boundary_vertex[v] && find(v) == v;
    return t;
}

size_t least_rotation(std::span<const int> cycle) {
    const size_t n = cycle.size();
    if (n == 0) return 0;
    const int least = *std::min_element(cycle.begin(), cycle.end());
    size_t best = n;
    for (size_t s = 0; s < n; ++s) {
        if (cycle[s] != least) continue;
        if (best == n) {
            best = s;
            continue;
        }
        for (size_t k = 1; k < n; ++k) {  // only for a face that repeats its least vertex
            const int x = cycle[(s + k) % n], y = cycle[(best + k) % n];
            if (x != y) {
                if (x < y) best = s;
                break;
            }
        }
    }
    return best;
}

}  // namespace crossdiv::verification
