#include "crossdiv/subdiv/loop.h"

#include <climits>
#include <string>
#include <utility>

#include "crossdiv/error.h"
#include "finite_level.h"
#include "stencil_sum.h"

namespace crossdiv {
namespace {

/// Walks the coarse mesh once and hands every refined vertex's stencil to `sink` as groups
/// of equally weighted sources: emit(row, a, na, wa, b, nb, wb[, c, nc, wc]). Loop's and
/// Warren's masks have two (self + ring, or ends + opposites), so a sink can sum a group
/// before scaling; the tuned families' edge mask next to an extraordinary vertex has three
/// (each end, the opposites).
template <class Sink>
void apply_loop_stencils(const TriMesh& mesh, const TriConnectivity& conn, const LoopOptions& opt, Sink& sink) {
    const auto& T = mesh.triangles;
    const int nv = mesh.num_vertices();
    std::vector<int> ring;  // reused for every vertex: no allocation in the loop once grown
    ring.reserve(64);
    // The valence each vertex reads in the tuned edge mask (only the tuned families need it).
    const bool tuned = has_tuned_edges(opt.weights);
    std::vector<int> edge_valence(tuned ? static_cast<size_t>(nv) : 0);

    for (int v = 0; v < nv; ++v) {
        const int start = conn.vertex_corner[v];
        if (start < 0) {  // isolated vertex: nothing to average with, it stays
            sink.emit(v, &v, 1, 1.0, nullptr, 0, 0.0);
            continue;
        }
        // The seed's one-ring walk: one loop, no special case on a closed mesh. On a boundary
        // it starts at the corner whose incoming edge is on the boundary and ends at the one
        // whose outgoing edge is; the two boundary neighbours are the ring's ends.
        ring.clear();
        ring.push_back(T[start / 3][(start % 3 + 2) % 3]);
        int faces = 0, last = start;
        for (int c = start;;) {
            ++faces;
            last = c;
            const int next = conn.next_around_vertex(c);
            if (next < 0 || next == start) break;
            ring.push_back(T[next / 3][(next % 3 + 2) % 3]);
            c = next;
        }
        if (tuned) edge_valence[v] = tuned_edge_valence(faces, conn.is_boundary_vertex(v));
        if (conn.is_boundary_vertex(v)) {
            const int ends[2] = {ring.front(), T[last / 3][(last % 3 + 1) % 3]};
            const VertexMask m = boundary_vertex_mask(opt.boundary, faces);
            sink.emit(v, &v, 1, m.self, ends, m.neighbor != 0.0 ? 2 : 0, m.neighbor);
        } else {
            const VertexMask m = interior_vertex_mask(opt.weights, faces);
            sink.emit(v, &v, 1, m.self, ring.data(), static_cast<int>(ring.size()), m.neighbor);
        }
    }

    for (int e = 0; e < conn.num_edges(); ++e) {
        const int c = conn.edge_corner[e];
        const int i = c / 3, j = c % 3;
        const int ends[2] = {conn.edge_vertices[e][0], conn.edge_vertices[e][1]};
        const int nt = conn.neighbor_tris[i][j];
        if (nt < 0) {
            const EdgeMask m = boundary_edge_mask();
            sink.emit(nv + e, ends, 2, m.end, nullptr, 0, 0.0);
        } else {
            const int opposite[2] = {T[i][(j + 2) % 3], T[nt][(conn.neighbor_edges[i][j] + 2) % 3]};
            // Loop's and Warren's mask reads no valence (tuned_edge_mask gives 3/8, 1/8 for them).
            const TunedEdgeMask m = tuned_edge_mask(opt.weights, tuned ? edge_valence[ends[0]] : 0,
                                                    tuned ? edge_valence[ends[1]] : 0);
            if (m.end_a == m.end_b) sink.emit(nv + e, ends, 2, m.end_a, opposite, 2, m.opposite);
            else sink.emit(nv + e, ends, 1, m.end_a, opposite, 2, m.opposite, ends + 1, 1, m.end_b);
        }
    }
}

/// Applies stencils to positions and, when present, colors.
struct PointSink {
    const std::vector<Vec3>& in;
    std::vector<Vec3>& out;
    const std::vector<Vec3>* in_colors;
    std::vector<Vec3>* out_colors;

    void emit(int row, const int* a, int na, double wa, const int* b, int nb, double wb, const int* c = nullptr,
              int nc = 0, double wc = 0.0) {
        out[row] = detail::stencil_sum(in, a, na, wa, b, nb, wb, c, nc, wc);
        if (out_colors) (*out_colors)[row] = detail::stencil_sum(*in_colors, a, na, wa, b, nb, wb, c, nc, wc);
    }
};

/// Collects stencils as matrix triplets.
struct TripletSink {
    std::vector<Eigen::Triplet<double>> triplets;
    void emit(int row, const int* a, int na, double wa, const int* b, int nb, double wb, const int* c = nullptr,
              int nc = 0, double wc = 0.0) {
        for (int k = 0; k < na; ++k) triplets.emplace_back(row, a[k], wa);
        for (int k = 0; k < nb; ++k) triplets.emplace_back(row, b[k], wb);
        for (int k = 0; k < nc; ++k) triplets.emplace_back(row, c[k], wc);
    }
};

/// Index of the half of edge e that touches endpoint v: 2e at edge_vertices[e][0], else 2e+1.
inline int half_edge_id(const TriConnectivity& conn, int e, int v) {
    return 2 * e + (conn.edge_vertices[e][0] == v ? 0 : 1);
}

}  // namespace

TriConnectivity loop_input_connectivity(const TriMesh& mesh) {
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (!mesh.positions[v].allFinite())
            throw InputError(mesh.source.describe_vertex(v) + ": coordinate is NaN or infinite");
    return build_tri_connectivity(mesh);
}

TriConnectivity refine_tri_connectivity(const TriMesh& coarse, const TriConnectivity& conn) {
    const auto& T = coarse.triangles;
    const int nv = coarse.num_vertices(), nf = coarse.num_faces(), ne = conn.num_edges();
    TriConnectivity child;
    child.neighbor_tris.resize(4 * static_cast<size_t>(nf));
    child.neighbor_edges.resize(4 * static_cast<size_t>(nf));
    child.tri_edges.resize(4 * static_cast<size_t>(nf));
    child.edge_corner.resize(2 * static_cast<size_t>(ne) + 3 * static_cast<size_t>(nf));
    child.edge_vertices.resize(child.edge_corner.size());
    child.vertex_corner.resize(static_cast<size_t>(nv) + ne);

    for (int i = 0; i < nf; ++i) {
        const auto& nt = conn.neighbor_tris[i];
        const auto& nE = conn.neighbor_edges[i];
        const auto& te = conn.tri_edges[i];
        for (int k = 0; k < 3; ++k) {
            // Corner child k = (v_k, m_k, m_{k+2}). Edge 0 is the half of parent edge k at v_k,
            // whose other half lies in the neighbour's child (ne+1)%3 as its edge 2; edge 2 is
            // the half of parent edge k+2 at v_k, mirrored by the neighbour's child ne, edge 0.
            const int c = 4 * i + k, k2 = (k + 2) % 3;
            child.neighbor_tris[c] = {nt[k] < 0 ? -1 : 4 * nt[k] + (nE[k] + 1) % 3, 4 * i + 3,
                                      nt[k2] < 0 ? -1 : 4 * nt[k2] + nE[k2]};
            child.neighbor_edges[c] = {nt[k] < 0 ? -1 : 2, k2, nt[k2] < 0 ? -1 : 0};
            child.tri_edges[c] = {half_edge_id(conn, te[k], T[i][k]), 2 * ne + 3 * i + k2,
                                  half_edge_id(conn, te[k2], T[i][k])};
            // Centre edge c' = (m_c', m_c'+1) borders corner child (c'+1)%3 at its edge 1.
            child.neighbor_tris[4 * i + 3][k] = 4 * i + (k + 1) % 3;
            child.neighbor_edges[4 * i + 3][k] = 1;
            child.tri_edges[4 * i + 3][k] = 2 * ne + 3 * i + k;
            const int interior = 2 * ne + 3 * i + k;
            child.edge_corner[interior] = 3 * (4 * i + 3) + k;
            child.edge_vertices[interior] = {nv + te[k], nv + te[(k + 1) % 3]};
        }
    }
    for (int e = 0; e < ne; ++e) {
        // Halves keep the parent's direction: 2e = (a, m), 2e+1 = (m, b) with (a, b) the
        // parent edge as seen from its corner (i, j); their corners are then (child j, 0) and
        // (child j+1, 2), and m's walk starts at (child j, 1), whose incoming edge is half 2e.
        const int c = conn.edge_corner[e], i = c / 3, j = c % 3, m = nv + e;
        child.edge_corner[2 * e] = 3 * (4 * i + j) + 0;
        child.edge_corner[2 * e + 1] = 3 * (4 * i + (j + 1) % 3) + 2;
        child.edge_vertices[2 * e] = {conn.edge_vertices[e][0], m};
        child.edge_vertices[2 * e + 1] = {m, conn.edge_vertices[e][1]};
        child.vertex_corner[m] = 3 * (4 * i + j) + 1;
    }
    for (int v = 0; v < nv; ++v) {
        // An old vertex sits at corner 0 of corner child j; its incoming edge there is half of
        // the parent's incoming edge, so a boundary start stays a boundary start.
        const int c = conn.vertex_corner[v];
        child.vertex_corner[v] = c < 0 ? -1 : 3 * (4 * (c / 3) + c % 3);
    }
    return child;
}

TriMesh loop_refine_once(const TriMesh& mesh, const TriConnectivity& conn, const LoopOptions& options) {
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    // Indices are int (as in the seed and in OpenSubdiv); refuse a level they cannot address.
    if (4LL * nf > INT_MAX || 3LL * (4LL * nf) > INT_MAX || static_cast<long long>(nv) + conn.num_edges() > INT_MAX)
        throw InputError("the next Loop level would have " + std::to_string(4LL * nf) +
                         " faces, more than 32-bit indices address; use fewer levels");
    TriMesh out;
    out.positions.resize(static_cast<size_t>(nv) + conn.num_edges());
    const bool colors = !mesh.colors.empty();
    if (colors) out.colors.resize(out.positions.size());
    PointSink sink{mesh.positions, out.positions, colors ? &mesh.colors : nullptr, colors ? &out.colors : nullptr};
    apply_loop_stencils(mesh, conn, options, sink);

    out.triangles.resize(4 * static_cast<size_t>(nf));
    for (int i = 0; i < nf; ++i) {
        const Triangle& t = mesh.triangles[i];
        const int m0 = nv + conn.tri_edges[i][0], m1 = nv + conn.tri_edges[i][1], m2 = nv + conn.tri_edges[i][2];
        out.triangles[4 * i + 0] = {t[0], m0, m2};
        out.triangles[4 * i + 1] = {t[1], m1, m0};
        out.triangles[4 * i + 2] = {t[2], m2, m1};
        out.triangles[4 * i + 3] = {m0, m1, m2};
    }
    return out;
}

LoopRefiner::LoopRefiner(TriMesh base, LoopOptions options) : options_(options) {
    TriConnectivity conn = loop_input_connectivity(base);
    levels_.push_back({std::move(base), std::move(conn)});
}

void LoopRefiner::refine(int levels) {
    for (int l = 0; l < levels; ++l) {
        const Level& coarse = levels_.back();
        Level fine{loop_refine_once(coarse.mesh, coarse.conn, options_),
                   refine_tri_connectivity(coarse.mesh, coarse.conn)};
        detail::require_finite_level(fine.mesh.positions, coarse.mesh.positions, static_cast<int>(levels_.size()));
        levels_.push_back(std::move(fine));
    }
}

std::vector<VertexOrigin> LoopRefiner::origins(int level) const {
    const Level& coarse = levels_.at(static_cast<size_t>(level) - 1);
    std::vector<VertexOrigin> o;
    o.reserve(static_cast<size_t>(coarse.mesh.num_vertices()) + coarse.conn.num_edges());
    for (int v = 0; v < coarse.mesh.num_vertices(); ++v) o.push_back({v, -1});
    for (const auto& ev : coarse.conn.edge_vertices) o.push_back({ev[0], ev[1]});
    return o;
}

TriMesh loop_subdivide(const TriMesh& mesh, const LoopOptions& options, int levels) {
    if (levels < 0) throw InputError("number of levels must be >= 0, got " + std::to_string(levels));
    TriMesh current = mesh;
    TriConnectivity conn = loop_input_connectivity(current);
    for (int l = 0; l < levels; ++l) {
        TriMesh next = loop_refine_once(current, conn, options);
        detail::require_finite_level(next.positions, current.positions, l + 1);
        if (l + 1 < levels) conn = refine_tri_connectivity(current, conn);
        current = std::move(next);
    }
    current.source = {};
    return current;
}

Eigen::SparseMatrix<double> loop_subdivision_matrix(const TriMesh& mesh, const LoopOptions& options) {
    return loop_subdivision_matrix(mesh, loop_input_connectivity(mesh), options);
}

Eigen::SparseMatrix<double> loop_subdivision_matrix(const TriMesh& mesh, const TriConnectivity& conn,
                                                    const LoopOptions& options) {
    TripletSink sink;
    apply_loop_stencils(mesh, conn, options, sink);
    Eigen::SparseMatrix<double> S(mesh.num_vertices() + conn.num_edges(), mesh.num_vertices());
    S.setFromTriplets(sink.triplets.begin(), sink.triplets.end());
    return S;
}

}  // namespace crossdiv
