#include "crossdiv/mesh/halfedge_mesh.h"

#include <stdexcept>
#include <string>

namespace crossdiv {

std::string_view to_string(FlipRefusal r) {
    switch (r) {
        case FlipRefusal::None: return "flipped";
        case FlipRefusal::BoundaryEdge: return "boundary edge (one face)";
        case FlipRefusal::OppositeVerticesCoincide: return "both faces have the same opposite vertex";
        case FlipRefusal::EdgeExists: return "the flipped edge already exists";
    }
    return "?";
}

HalfedgeMesh HalfedgeMesh::from_triangles(const TriMesh& mesh) {
    return from_connectivity(mesh, build_tri_connectivity(mesh));
}

HalfedgeMesh HalfedgeMesh::from_connectivity(const TriMesh& mesh, const TriConnectivity& conn) {
    const int nf = mesh.num_faces(), ne = conn.num_edges();
    HalfedgeMesh m;
    m.next_.assign(2 * static_cast<size_t>(ne), -1);
    m.prev_.assign(m.next_.size(), -1);
    m.origin_.assign(m.next_.size(), -1);
    m.face_.assign(m.next_.size(), -1);
    m.vertex_he_.assign(static_cast<size_t>(mesh.num_vertices()), -1);
    m.face_he_.resize(static_cast<size_t>(nf));

    // Corner c = 3i + j is the half-edge j of triangle i; it is side 0 of its edge exactly
    // when it is the edge's edge_corner.
    auto corner_he = [&](int c) {
        const int e = conn.tri_edges[c / 3][c % 3];
        return conn.edge_corner[e] == c ? 2 * e : 2 * e + 1;
    };
    for (int i = 0; i < nf; ++i) {
        const int h[3] = {corner_he(3 * i), corner_he(3 * i + 1), corner_he(3 * i + 2)};
        for (int j = 0; j < 3; ++j) {
            m.origin_[h[j]] = mesh.triangles[i][j];
            m.face_[h[j]] = i;
            m.link(h[j], h[(j + 1) % 3]);
        }
        m.face_he_[i] = h[0];
    }
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (conn.vertex_corner[v] >= 0) m.vertex_he_[v] = corner_he(conn.vertex_corner[v]);

    // Boundary half-edges (side 1 of a boundary edge). A manifold vertex has at most one
    // boundary half-edge leaving it, so next(b) is the boundary half-edge leaving b's target.
    std::vector<int> boundary_out(static_cast<size_t>(mesh.num_vertices()), -1);
    for (int e = 0; e < ne; ++e) {
        if (!conn.is_boundary_edge(e)) continue;
        m.origin_[2 * e + 1] = conn.edge_vertices[e][1];
        boundary_out[conn.edge_vertices[e][1]] = 2 * e + 1;
    }
    for (int e = 0; e < ne; ++e)
        if (conn.is_boundary_edge(e)) m.link(2 * e + 1, boundary_out[conn.edge_vertices[e][0]]);
    for (int e = 0; e < ne; ++e) {
        const int b = 2 * e + 1;
        if (!conn.is_boundary_edge(e) || m.face_[b] != -1) continue;  // -1: not yet in a loop
        const int code = -2 - m.num_boundary_loops();  // loop L is stored as -1 - L; -1 is "unassigned"
        m.loop_he_.push_back(b);
        for (int h = b; m.face_[h] == -1; h = m.next_[h]) m.face_[h] = code;
    }
    // Codes were offset by one while -1 meant unassigned; shift them to -1 - loop.
    for (int& f : m.face_)
        if (f < -1) f += 1;
    return m;
}

std::vector<Triangle> HalfedgeMesh::triangles() const {
    std::vector<Triangle> out(face_he_.size());
    for (size_t f = 0; f < out.size(); ++f) {
        const int h = face_he_[f];
        out[f] = {origin_[h], origin_[next_[h]], origin_[next_[next_[h]]]};
    }
    return out;
}

HalfedgeId HalfedgeMesh::find_halfedge(VertexId a, VertexId b) const {
    const HalfedgeId start = halfedge(a);
    if (!start.valid()) return {};
    HalfedgeId h = start;
    do {
        if (target(h) == b) return h;
        h = next_around_origin(h);
    } while (h != start);
    return {};
}

int HalfedgeMesh::valence(VertexId v) const {
    const HalfedgeId start = halfedge(v);
    if (!start.valid()) return 0;
    int n = 0;
    HalfedgeId h = start;
    do {
        ++n;
        h = next_around_origin(h);
    } while (h != start);
    return n;
}

bool HalfedgeMesh::is_boundary(VertexId v) const {
    const HalfedgeId start = halfedge(v);
    if (!start.valid()) return false;
    HalfedgeId h = start;
    do {
        if (is_boundary(h)) return true;
        h = next_around_origin(h);
    } while (h != start);
    return false;
}

FlipRefusal HalfedgeMesh::flip(EdgeId e) {
    // Before: face f0 = (a, b, c) along h = a->b, face f1 = (b, a, d) along t = b->a.
    // After:  f0 = (d, c, a) along h = d->c,  f1 = (c, d, b) along t = c->d.
    const int h = 2 * e.idx, t = h + 1;
    if (face_[h] < 0 || face_[t] < 0) return FlipRefusal::BoundaryEdge;
    const int hn = next_[h], hp = prev_[h], tn = next_[t], tp = prev_[t];
    const int a = origin_[h], b = origin_[t], c = origin_[hp], d = origin_[tp];
    if (c == d) return FlipRefusal::OppositeVerticesCoincide;
    if (find_halfedge(VertexId(c), VertexId(d)).valid()) return FlipRefusal::EdgeExists;

    const int f0 = face_[h], f1 = face_[t];
    origin_[h] = d;
    origin_[t] = c;
    link(h, hp), link(hp, tn), link(tn, h);
    link(t, tp), link(tp, hn), link(hn, t);
    face_[tn] = f0;
    face_[hn] = f1;
    face_he_[f0] = h;
    face_he_[f1] = t;
    // a and b lose the edge; their half-edge must still leave them.
    if (vertex_he_[a] == h) vertex_he_[a] = tn;
    if (vertex_he_[b] == t) vertex_he_[b] = hn;
    return FlipRefusal::None;
}

int HalfedgeMesh::new_edge(int origin_a, int origin_b) {
    for (int o : {origin_a, origin_b}) {
        next_.push_back(-1);
        prev_.push_back(-1);
        origin_.push_back(o);
        face_.push_back(-1);
    }
    return num_edges() - 1;
}

VertexId HalfedgeMesh::split(EdgeId e) {
    // Before: h = a->b (face f0 = (a, b, c) or boundary), t = b->a (face f1 = (b, a, d) or
    // boundary). After: e = a-m (h = a->m, t = m->a), e1 = m-b (h1 = m->b, t1 = b->m); an
    // interior side gets the edge m-c (f0 = (a, m, c), new f2 = (m, b, c)) or m-d
    // (f1 = (m, a, d), new f3 = (b, m, d)).
    const int h = 2 * e.idx, t = h + 1;
    const int hn = next_[h], hp = prev_[h], tn = next_[t], tp = prev_[t];
    const int b = origin_[t];  // a = origin_[h] keeps its half-edge h
    const int m = num_vertices();
    vertex_he_.push_back(-1);

    const int e1 = new_edge(m, b), h1 = 2 * e1, t1 = h1 + 1;
    origin_[t] = m;
    vertex_he_[m] = h1;
    if (vertex_he_[b] == t) vertex_he_[b] = t1;

    if (face_[h] >= 0) {
        const int f0 = face_[h], c = origin_[hp];
        const int e2 = new_edge(m, c), h2 = 2 * e2, t2 = h2 + 1;
        const int f2 = num_faces();
        face_he_.push_back(h1);
        link(h, h2), link(h2, hp), link(hp, h);
        link(h1, hn), link(hn, t2), link(t2, h1);
        face_[h2] = f0;
        face_[h1] = face_[hn] = face_[t2] = f2;
        face_he_[f0] = h;
    } else {  // h's side is a boundary loop: m sits on it between a and b
        link(h1, hn);
        link(h, h1);
        face_[h1] = face_[h];
    }

    if (face_[t] >= 0) {
        const int f1 = face_[t], d = origin_[tp];
        const int e3 = new_edge(m, d), h3 = 2 * e3, t3 = h3 + 1;
        const int f3 = num_faces();
        face_he_.push_back(t1);
        link(t, tn), link(tn, t3), link(t3, t);
        link(t1, h3), link(h3, tp), link(tp, t1);
        face_[t3] = f1;
        face_[t1] = face_[h3] = face_[tp] = f3;
        face_he_[f1] = t;
    } else {
        link(tp, t1);
        link(t1, t);
        face_[t1] = face_[t];
    }
    return VertexId(m);
}

VertexId split_at_midpoint(HalfedgeMesh& mesh, std::vector<Vec3>& positions, EdgeId e) {
    if (static_cast<int>(positions.size()) != mesh.num_vertices())
        throw std::logic_error("split_at_midpoint: " + std::to_string(positions.size()) + " positions for " +
                               std::to_string(mesh.num_vertices()) + " vertices");
    const HalfedgeId h = HalfedgeMesh::halfedge(e);
    const Vec3 mid = 0.5 * (positions[mesh.origin(h).idx] + positions[mesh.target(h).idx]);
    const VertexId m = mesh.split(e);
    positions.push_back(mid);
    return m;
}

TriMesh to_tri_mesh(const HalfedgeMesh& mesh, const std::vector<Vec3>& positions) {
    TriMesh out;
    out.positions = positions;
    out.triangles = mesh.triangles();
    return out;
}

}  // namespace crossdiv
