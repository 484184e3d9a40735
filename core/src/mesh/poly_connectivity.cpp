#include "crossdiv/mesh/poly_connectivity.h"

#include <string>

#include "crossdiv/error.h"
#include "one_ring_starts.h"
#include "twin_search.h"

namespace crossdiv {
PolyConnectivity build_poly_connectivity(const PolyMesh& mesh) {
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    const MeshSource& src = mesh.source;
    for (int v = 0; v < nv; ++v)
        if (!mesh.positions[v].allFinite())
            throw InputError(src.describe_vertex(v) + ": coordinate is NaN or infinite");

    PolyConnectivity conn;
    const int nc = static_cast<int>(mesh.face_vertices.size());
    conn.corner_vertex = mesh.face_vertices;
    conn.corner_face.resize(nc);
    conn.next.resize(nc);
    conn.prev.resize(nc);
    std::vector<int> seen_in_face(static_cast<size_t>(nv), -1);
    for (int f = 0; f < nf; ++f) {
        const int b = mesh.face_start[f], e = mesh.face_start[f + 1], n = e - b;
        if (n < 3) throw InputError(src.describe_face(f) + ": has " + std::to_string(n) + " corners, needs at least 3");
        for (int k = 0; k < n; ++k) {
            const int c = b + k, v = conn.corner_vertex[c];
            if (v < 0 || v >= nv)
                throw InputError(src.describe_face(f) + ": vertex index " + std::to_string(v) + " out of range [0, " +
                                 std::to_string(nv) + ")");
            if (seen_in_face[static_cast<size_t>(v)] == f)  // a stamp per vertex: linear in the face's size
                throw NonManifoldInput(src.describe_face(f) + ": repeated vertex " + std::to_string(v));
            seen_in_face[static_cast<size_t>(v)] = f;
            conn.corner_face[c] = f;
            conn.next[c] = k + 1 < n ? c + 1 : b;
            conn.prev[c] = k > 0 ? c - 1 : e - 1;
        }
    }

    // Outgoing corners of each vertex in compressed-row form: the twin of a -> b is found
    // among b's outgoing corners, so no edge map is needed.
    std::vector<int> out_start(static_cast<size_t>(nv) + 1, 0);
    for (int v : conn.corner_vertex) ++out_start[static_cast<size_t>(v) + 1];
    for (int v = 0; v < nv; ++v) out_start[v + 1] += out_start[v];
    std::vector<int> out_corners(static_cast<size_t>(nc));
    {
        std::vector<int> fill(out_start.begin(), out_start.end() - 1);
        for (int c = 0; c < nc; ++c) out_corners[fill[conn.corner_vertex[c]]++] = c;
    }

    conn.twin.assign(nc, -1);
    conn.corner_edge.assign(nc, -1);
    conn.vertex_corner.assign(nv, -1);
    conn.edge_corner.reserve(static_cast<size_t>(nc) / 2 + 16);
    conn.edge_vertices.reserve(static_cast<size_t>(nc) / 2 + 16);
    const detail::EdgeFault fault = detail::find_twins(
        out_start, out_corners, [&conn](int c) { return conn.head(c); }, [&conn](int c) { return conn.prev[c]; },
        [&conn](int p) { return conn.corner_vertex[p]; }, conn.twin);
    if (fault.corner >= 0) {
        const int c = fault.corner;
        detail::throw_edge_fault(fault, conn.corner_vertex[c], conn.head(c), "faces", src.describe_face(conn.corner_face[c]));
    }
    for (int c = 0; c < nc; ++c) {
        const int a = conn.corner_vertex[c], b = conn.head(c), twin = conn.twin[c];
        if (twin < 0 || twin > c) {
            conn.corner_edge[c] = conn.num_edges();
            conn.edge_corner.push_back(c);
            conn.edge_vertices.push_back({a, b});
        } else {
            conn.corner_edge[c] = conn.corner_edge[twin];
        }
    }

    // One-ring entry corners; a vertex whose corners do not form one fan is a bowtie.
    detail::find_one_ring_starts(
        conn, out_start, out_corners, [&](int c) { return conn.twin[conn.prev[c]] < 0; }, src, "faces");
    return conn;
}

}  // namespace crossdiv
