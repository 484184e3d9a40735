#include "crossdiv/mesh/halfedge_validity.h"

#include "brace_format.h"

#include <numeric>

namespace crossdiv {
namespace {

int find_root(std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

}  // namespace

const char* to_string(HalfedgeIssueKind kind) {
    switch (kind) {
        case HalfedgeIssueKind::OutOfRange: return "out-of-range";
        case HalfedgeIssueKind::TwinMismatch: return "twin";
        case HalfedgeIssueKind::NextPrevMismatch: return "next-prev";
        case HalfedgeIssueKind::FaceCycle: return "face-cycle";
        case HalfedgeIssueKind::DegenerateFace: return "degenerate-face";
        case HalfedgeIssueKind::BoundaryLoop: return "boundary-loop";
        case HalfedgeIssueKind::VertexLink: return "vertex-link";
        case HalfedgeIssueKind::EulerCharacteristic: return "euler-characteristic";
    }
    return "?";
}

std::vector<HalfedgeIssue> check_halfedge_mesh(const HalfedgeMesh& m) {
    std::vector<HalfedgeIssue> issues;
    auto report = [&](HalfedgeIssueKind k, std::string msg) { issues.push_back({k, std::move(msg)}); };
    const int nh = m.num_halfedges(), nv = m.num_vertices(), nf = m.num_faces(), nl = m.num_boundary_loops();
    using K = HalfedgeIssueKind;
    // Raw face code of a half-edge: the face, or -1 - loop for a boundary loop.
    auto code = [&](HalfedgeId h) { return m.is_boundary(h) ? -1 - m.boundary_loop(h) : m.face(h).idx; };
    auto name_code = [&](int c) { return c >= 0 ? detail::brace_format("face {}", c) : detail::brace_format("boundary loop {}", -1 - c); };

    // 1. Every link in range; nothing else is safe to follow until this holds.
    for (int i = 0; i < nh; ++i) {
        const HalfedgeId h(i);
        const int n = m.next(h).idx, p = m.prev(h).idx, o = m.origin(h).idx, c = code(h);
        if (n < 0 || n >= nh || p < 0 || p >= nh || o < 0 || o >= nv || c >= nf || c < -nl)
            report(K::OutOfRange, detail::brace_format("halfedge {}: next {}, prev {}, origin {}, {} (halfedges < {}, vertices < {}, faces < {}, loops < {})",
                                              i, n, p, o, name_code(c), nh, nv, nf, nl));
    }
    for (int v = 0; v < nv; ++v) {
        const int h = m.halfedge(VertexId(v)).idx;
        if (h < -1 || h >= nh) report(K::OutOfRange, detail::brace_format("vertex {}: halfedge {} (halfedges < {})", v, h, nh));
    }
    for (int f = 0; f < nf; ++f) {
        const int h = m.halfedge(FaceId(f)).idx;
        if (h < 0 || h >= nh) report(K::OutOfRange, detail::brace_format("face {}: halfedge {} (halfedges < {})", f, h, nh));
    }
    for (int l = 0; l < nl; ++l) {
        const int h = m.loop_halfedge(l).idx;
        if (h < 0 || h >= nh) report(K::OutOfRange, detail::brace_format("boundary loop {}: halfedge {} (halfedges < {})", l, h, nh));
    }
    if (!issues.empty()) return issues;

    // 2. Per half-edge links.
    for (int i = 0; i < nh; ++i) {
        const HalfedgeId h(i), n = m.next(h), p = m.prev(h), t = HalfedgeMesh::twin(h);
        if (m.prev(n) != h)
            report(K::NextPrevMismatch, detail::brace_format("halfedge {}: prev(next({})) = {}, should be {} (next({}) = {})", i, i, m.prev(n).idx, i, i, n.idx));
        if (m.next(p) != h)
            report(K::NextPrevMismatch, detail::brace_format("halfedge {}: next(prev({})) = {}, should be {} (prev({}) = {})", i, i, m.next(p).idx, i, i, p.idx));
        if (m.origin(n) != m.origin(t))
            report(K::TwinMismatch, detail::brace_format("halfedge {}: its next {} starts at vertex {}, its twin {} at vertex {}; both should start where {} ends",
                                                i, n.idx, m.origin(n).idx, t.idx, m.origin(t).idx, i));
        if (m.origin(h) == m.origin(t))
            report(K::TwinMismatch, detail::brace_format("halfedge {}: it and its twin {} both start at vertex {} (a loop edge)", i, t.idx, m.origin(h).idx));
        if (code(n) != code(h))
            report(K::FaceCycle, detail::brace_format("halfedge {}: on {}, but its next {} is on {}", i, name_code(code(h)), n.idx, name_code(code(n))));
        if (m.is_boundary(h) && m.is_boundary(t))
            report(K::TwinMismatch, detail::brace_format("edge {}: both halfedges {} and {} are on boundary loops (an edge with no face)", i / 2, i, t.idx));
    }

    // 3. Faces and boundary loops: closed cycles over exactly the half-edges that name them.
    std::vector<int> named(static_cast<size_t>(nf + nl), 0);
    for (int i = 0; i < nh; ++i) {  // faces first, then loops: slot nf + L for code -1 - L
        const int c = code(HalfedgeId(i));
        ++named[static_cast<size_t>(c >= 0 ? c : nf - 1 - c)];
    }
    auto cycle_length = [&](HalfedgeId start, int c) {
        int len = 0;
        HalfedgeId h = start;
        do {
            if (code(h) != c || ++len > nh) return -1;
            h = m.next(h);
        } while (h != start);
        return len;
    };
    for (int f = 0; f < nf; ++f) {
        const HalfedgeId h0 = m.halfedge(FaceId(f));
        const int len = cycle_length(h0, f);
        if (len != 3 || named[static_cast<size_t>(f)] != 3) {
            report(K::FaceCycle, detail::brace_format("face {}: its halfedge {} (on {}) starts a next-cycle of {}, and {} halfedges name the face; both should be 3",
                                             f, h0.idx, name_code(code(h0)), len < 0 ? std::string("no closed length") : std::to_string(len),
                                             named[static_cast<size_t>(f)]));
            continue;
        }
        const int a = m.origin(h0).idx, b = m.origin(m.next(h0)).idx, c = m.origin(m.prev(h0)).idx;
        if (a == b || b == c || a == c)
            report(K::DegenerateFace, detail::brace_format("face {}: vertices ({}, {}, {}) repeat a vertex", f, a, b, c));
    }
    for (int l = 0; l < nl; ++l) {
        const HalfedgeId h0 = m.loop_halfedge(l);
        const int len = cycle_length(h0, -1 - l), count = named[static_cast<size_t>(nf + l)];
        if (len != count || len < 0)
            report(K::BoundaryLoop, detail::brace_format("boundary loop {}: its halfedge {} (on {}) starts a next-cycle of {}, but {} halfedges name the loop",
                                                l, h0.idx, name_code(code(h0)), len < 0 ? std::string("no closed length") : std::to_string(len), count));
    }

    // 4. Vertices: the half-edge leaves the vertex, and the ring reaches every half-edge that does.
    std::vector<int> leaving(static_cast<size_t>(nv), 0);
    std::vector<int> first_leaving(static_cast<size_t>(nv), -1);
    for (int i = 0; i < nh; ++i) {
        const int o = m.origin(HalfedgeId(i)).idx;
        if (leaving[static_cast<size_t>(o)]++ == 0) first_leaving[static_cast<size_t>(o)] = i;
    }
    for (int v = 0; v < nv; ++v) {
        const HalfedgeId h0 = m.halfedge(VertexId(v));
        const int count = leaving[static_cast<size_t>(v)];
        if (!h0.valid()) {
            if (count > 0)
                report(K::VertexLink, detail::brace_format("vertex {}: has no halfedge, but {} halfedges leave it (first: {})", v, count, first_leaving[static_cast<size_t>(v)]));
            continue;
        }
        if (m.origin(h0).idx != v) {
            report(K::VertexLink, detail::brace_format("vertex {}: its halfedge {} leaves vertex {}, should leave {} (halfedges leaving {}: {}, first {})",
                                              v, h0.idx, m.origin(h0).idx, v, v, count, first_leaving[static_cast<size_t>(v)]));
            continue;
        }
        int ring = 0;
        HalfedgeId h = h0;
        do {
            if (m.origin(h).idx != v || ++ring > nh) break;
            h = m.next_around_origin(h);
        } while (h != h0);
        if (h != h0 || ring != count)
            report(K::VertexLink, detail::brace_format("vertex {}: the ring from its halfedge {} reaches {} halfedges{}, but {} leave it (more than one fan, or a broken link)",
                                              v, h0.idx, ring, h != h0 ? " without closing" : "", count));
    }

    // 5. Euler characteristic per connected component.
    std::vector<int> parent(static_cast<size_t>(nv));
    std::iota(parent.begin(), parent.end(), 0);
    for (int e = 0; e < m.num_edges(); ++e) {
        const HalfedgeId h = HalfedgeMesh::halfedge(EdgeId(e));
        const int a = find_root(parent, m.origin(h).idx), b = find_root(parent, m.target(h).idx);
        if (a != b) parent[static_cast<size_t>(a)] = b;
    }
    std::vector<long> chi(static_cast<size_t>(nv), 0), loops(static_cast<size_t>(nv), 0);
    std::vector<char> used(static_cast<size_t>(nv), 0);
    for (int v = 0; v < nv; ++v)
        if (leaving[static_cast<size_t>(v)] > 0) {
            used[static_cast<size_t>(find_root(parent, v))] = 1;
            ++chi[static_cast<size_t>(find_root(parent, v))];
        }
    for (int e = 0; e < m.num_edges(); ++e) --chi[static_cast<size_t>(find_root(parent, m.origin(HalfedgeMesh::halfedge(EdgeId(e))).idx))];
    for (int f = 0; f < nf; ++f) ++chi[static_cast<size_t>(find_root(parent, m.origin(m.halfedge(FaceId(f))).idx))];
    for (int l = 0; l < nl; ++l) ++loops[static_cast<size_t>(find_root(parent, m.origin(m.loop_halfedge(l)).idx))];
    for (int r = 0; r < nv; ++r) {
        if (!used[static_cast<size_t>(r)]) continue;
        const long twice_genus = 2 - chi[static_cast<size_t>(r)] - loops[static_cast<size_t>(r)];
        if (twice_genus < 0 || twice_genus % 2 != 0)
            report(K::EulerCharacteristic, detail::brace_format("component of vertex {}: V - E + F = {} with {} boundary loop(s) gives genus {}/2, not a non-negative integer",
                                                       r, chi[static_cast<size_t>(r)], loops[static_cast<size_t>(r)], twice_genus));
    }
    return issues;
}

}  // namespace crossdiv
