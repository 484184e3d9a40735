#include "crossdiv/subdiv/sqrt3.h"

#include <climits>
#include <string>

#include "crossdiv/error.h"
#include "level_loop.h"

namespace crossdiv {

RefinementStep sqrt3_step(const PolyMesh& mesh, const PolyConnectivity& conn, bool refine_boundary) {
    const int nv = mesh.num_vertices(), nf = mesh.num_faces(), ne = conn.num_edges();
    detail::require_triangles(mesh, "sqrt3");
    if (static_cast<long long>(nv) + 2LL * nf > INT_MAX || 3LL * nf > INT_MAX)
        throw InputError("the next sqrt3 level would have " + std::to_string(3LL * nf) +
                         " faces, more than 32-bit indices address; use fewer levels");

    // Which faces are split at a boundary edge on this step, and at which corner (the corner
    // whose outgoing half-edge is the boundary edge); -1 for a face that gets its centroid.
    std::vector<int> boundary_corner(static_cast<size_t>(nf), -1);
    if (refine_boundary)
        for (int c = 0; c < conn.num_corners(); ++c) {
            if (conn.twin[c] >= 0) continue;
            const int f = conn.corner_face[c];
            if (boundary_corner[f] >= 0)
                throw InputError(mesh.source.describe_face(f) +
                                 ": has more than one boundary edge, and a boundary step of sqrt3 needs one "
                                 "(refine without the boundary first: generations count from 0)");
            boundary_corner[f] = c;
        }

    RefinementStep step(nv);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + 2 * static_cast<size_t>(nf), 8 * static_cast<size_t>(nv) + 6 * static_cast<size_t>(nf));

    // Old vertices.
    for (int v = 0; v < nv; ++v) {
        if (conn.vertex_corner[v] < 0) {  // isolated: it stays
            st.add(v, 1.0);
        } else if (conn.is_boundary_vertex(v)) {
            if (refine_boundary) {
                const PolyConnectivity::BoundaryNeighbors nb = conn.boundary_neighbors(v);
                st.add(nb.before, kSqrt3BoundaryVertexNeighbor);
                st.add(v, kSqrt3BoundaryVertexSelf);
                st.add(nb.after, kSqrt3BoundaryVertexNeighbor);
            } else {
                st.add(v, 1.0);  // the boundary waits for the next (odd) generation
            }
        } else {
            const int start = conn.vertex_corner[v];
            const Sqrt3VertexMask m = sqrt3_interior_vertex_mask(conn.fan(v).faces);
            st.add(v, m.self);
            for (int c = start;;) {
                st.add(conn.head(c), m.ring);
                c = conn.next_around_vertex(c);
                if (c == start) break;
            }
        }
        st.end_row();
    }

    // New points per face: the centroid, or the two trisection points of the boundary edge.
    std::vector<int> first_point(static_cast<size_t>(nf));
    for (int f = 0; f < nf; ++f) {
        const int bc = boundary_corner[f];
        if (bc < 0) {
            for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) st.add(conn.corner_vertex[c], kSqrt3FacePoint);
            first_point[f] = st.end_row();
            continue;
        }
        const int a = conn.corner_vertex[bc], b = conn.head(bc);
        const int before_a = conn.boundary_neighbors(a).before, after_b = conn.boundary_neighbors(b).after;
        st.add(before_a, kSqrt3BoundaryEdgeFar);
        st.add(a, kSqrt3BoundaryEdgeNear);
        st.add(b, kSqrt3BoundaryEdgeOther);
        first_point[f] = st.end_row();
        st.add(a, kSqrt3BoundaryEdgeOther);
        st.add(b, kSqrt3BoundaryEdgeNear);
        st.add(after_b, kSqrt3BoundaryEdgeFar);
        st.end_row();
    }
    // The new point of corner c's face on the side of c's half-edge: the centroid, or, in a
    // face split at boundary corner bc = (a -> b, opposite o), t1 for the edge o -> a and t2
    // for b -> o.
    const auto side_point = [&](int c) {
        const int f = conn.corner_face[c], bc = boundary_corner[f];
        if (bc < 0) return first_point[f];
        return c == conn.prev[bc] ? first_point[f] : first_point[f] + 1;
    };

    step.face_vertices.reserve(9 * static_cast<size_t>(nf));
    step.face_start.reserve(3 * static_cast<size_t>(nf) + 1);
    for (int e = 0; e < ne; ++e) {
        const int c = conn.edge_corner[e], t = conn.twin[c];
        const int a = conn.corner_vertex[c], b = conn.head(c);
        if (t >= 0) {  // flipped: (a, b) becomes (left point, right point)
            const int left = side_point(c), right = side_point(t);
            step.add_face({a, right, left});
            step.add_face({b, left, right});
        } else if (boundary_corner[conn.corner_face[c]] < 0) {
            step.add_face({a, b, first_point[conn.corner_face[c]]});
        } else {
            const int t1 = first_point[conn.corner_face[c]];
            step.add_face({t1, t1 + 1, conn.corner_vertex[conn.prev[c]]});
        }
    }
    return step;
}

PolyMesh sqrt3_subdivide(const PolyMesh& mesh, const Sqrt3Options& options, int levels) {
    detail::require_triangles(mesh, "sqrt3");  // also for levels = 0
    detail::require_no_creases(mesh, "sqrt3");
    return detail::refine_levels(mesh, levels, [&](const PolyMesh& m, const PolyConnectivity& conn, int level) {
        const bool odd_generation = options.parity == Sqrt3Parity::CountFromInput && level % 2 == 1;
        return sqrt3_step(m, conn, odd_generation);
    });
}

}  // namespace crossdiv
