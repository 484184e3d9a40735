#include "crossdiv/mesh/tri_connectivity.h"

#include <string>

#include "crossdiv/error.h"
#include "one_ring_starts.h"
#include "twin_search.h"

namespace crossdiv {
TriConnectivity build_tri_connectivity(const TriMesh& mesh) {
    const int nv = mesh.num_vertices();
    const int nf = mesh.num_faces();
    const auto& T = mesh.triangles;
    const MeshSource& src = mesh.source;

    for (int i = 0; i < nf; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (T[i][j] < 0 || T[i][j] >= nv)
                throw InputError(src.describe_face(i) + ": vertex index " + std::to_string(T[i][j]) +
                                 " out of range [0, " + std::to_string(nv) + ")");
        }
        if (T[i][0] == T[i][1] || T[i][1] == T[i][2] || T[i][2] == T[i][0])
            throw NonManifoldInput(src.describe_face(i) + ": repeated vertex in triangle (" + std::to_string(T[i][0]) +
                             ", " + std::to_string(T[i][1]) + ", " + std::to_string(T[i][2]) + ")");
    }

    // Outgoing corners of each vertex in compressed-row form: the twin of a -> b is found
    // among b's outgoing corners, so no edge map is needed.
    std::vector<int> out_start(static_cast<size_t>(nv) + 1, 0);
    for (const Triangle& t : T)
        for (int v : t) ++out_start[static_cast<size_t>(v) + 1];
    for (int v = 0; v < nv; ++v) out_start[v + 1] += out_start[v];
    std::vector<int> out_corners(static_cast<size_t>(3) * nf);
    {
        std::vector<int> fill(out_start.begin(), out_start.end() - 1);
        for (int c = 0; c < 3 * nf; ++c) out_corners[fill[T[c / 3][c % 3]]++] = c;
    }
    // The head of every corner's outgoing edge, once: the twin search below reads it ~12
    // times per corner.
    std::vector<int> heads(static_cast<size_t>(3) * nf);
    for (int i = 0; i < nf; ++i) {
        heads[3 * i] = T[i][1];
        heads[3 * i + 1] = T[i][2];
        heads[3 * i + 2] = T[i][0];
    }
    auto head = [&](int c) { return heads[c]; };

    TriConnectivity conn;
    conn.neighbor_tris.assign(nf, {-1, -1, -1});
    conn.neighbor_edges.assign(nf, {-1, -1, -1});
    conn.tri_edges.assign(nf, {-1, -1, -1});
    conn.vertex_corner.assign(nv, -1);
    conn.edge_corner.reserve(static_cast<size_t>(3) * nf / 2 + 16);  // closed: exactly 3F/2
    conn.edge_vertices.reserve(static_cast<size_t>(3) * nf / 2 + 16);

    std::vector<int> twins(static_cast<size_t>(3) * nf);
    const detail::EdgeFault fault = detail::find_twins(
        out_start, out_corners, head, [](int c) { return c - c % 3 + (c % 3 + 2) % 3; },
        [&](int p) { return T[p / 3][p % 3]; }, twins);
    if (fault.corner >= 0) {
        const int c = fault.corner;
        detail::throw_edge_fault(fault, T[c / 3][c % 3], head(c), "triangles", src.describe_face(c / 3));
    }
    for (int c = 0; c < 3 * nf; ++c) {
        const int a = T[c / 3][c % 3], b = head(c), twin = twins[c];
        if (twin >= 0) {
            conn.neighbor_tris[c / 3][c % 3] = twin / 3;
            conn.neighbor_edges[c / 3][c % 3] = twin % 3;
        }
        // Number the edge at its first corner in scan order.
        if (twin < 0 || twin > c) {
            conn.tri_edges[c / 3][c % 3] = conn.num_edges();
            conn.edge_corner.push_back(c);
            conn.edge_vertices.push_back({a, b});
        } else {
            conn.tri_edges[c / 3][c % 3] = conn.tri_edges[twin / 3][twin % 3];
        }
    }

    // One-ring entry corners; a vertex whose corners do not form one fan is a bowtie.
    detail::find_one_ring_starts(
        conn, out_start, out_corners, [&](int c) { return conn.neighbor_tris[c / 3][(c % 3 + 2) % 3] < 0; }, src, "triangles");
    return conn;
}

}  // namespace crossdiv
