#include "crossdiv/verification/harness/mesh_topology.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>

namespace crossdiv::verification {

MeshTopology mesh_topology(const PolyMesh& mesh) {
    MeshTopology t;
    t.vertices = mesh.num_vertices();
    t.faces = mesh.num_faces();
    const size_t nv = static_cast<size_t>(t.vertices);
    // Every corner's edge (corner, next corner) under its smaller end, by a counting sort (the
    // comparisons take meshes of millions of faces, where sorting 64-bit edge keys took half
    // the time), then ordered within each end's few edges by the larger end: the edges in
    // sorted order, each as often as faces use it.
    std::vector<int> first(nv + 1, 0);
    const auto for_each_corner_edge = [&](auto&& visit) {
        for (int f = 0; f < t.faces; ++f) {
            const int* c = mesh.face(f);
            const int n = mesh.face_size(f);
            for (int k = 0; k < n; ++k) visit(f, c[k], c[k + 1 < n ? k + 1 : 0]);
        }
    };
    for_each_corner_edge([&](int f, int a, int b) {
        for (int v : {a, b})
            if (v < 0 || v >= t.vertices)
                throw std::invalid_argument("face " + std::to_string(f) + " names vertex " + std::to_string(v) + " of a mesh of " +
                                            std::to_string(t.vertices) + " vertices");
        ++first[static_cast<size_t>(std::min(a, b)) + 1];
    });
    std::partial_sum(first.begin(), first.end(), first.begin());
    std::vector<int> larger(static_cast<size_t>(first[nv]));
    std::vector<int> fill(first.begin(), first.end() - 1);
    for_each_corner_edge([&](int, int a, int b) { larger[static_cast<size_t>(fill[static_cast<size_t>(std::min(a, b))]++)] = std::max(a, b); });

    t.valence.assign(nv, 0);
    t.boundary_vertex.assign(nv, 0);
    std::vector<int> parent(nv);
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (int a = 0; a < t.vertices; ++a) {
        const auto begin = larger.begin() + first[static_cast<size_t>(a)], end = larger.begin() + first[static_cast<size_t>(a) + 1];
        std::sort(begin, end);
        for (auto i = begin; i != end;) {
            auto j = i;
            while (j != end && *j == *i) ++j;
            const int b = *i;
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
