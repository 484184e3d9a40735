#include "crossdiv/subdiv/loop_split_flip.h"

#include <stdexcept>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/subdiv/loop.h"
#include "finite_level.h"
#include "stencil_sum.h"

namespace crossdiv {
namespace {

/// The new points of one attribute (positions or colors), old vertices then edges, computed
/// on the coarse half-edge mesh before any operation.
std::vector<Vec3> loop_points(const HalfedgeMesh& he, const std::vector<Vec3>& p, const LoopOptions& opt) {
    const int nv = he.num_vertices(), ne = he.num_edges();
    std::vector<Vec3> out(static_cast<size_t>(nv + ne));
    std::vector<int> ring;
    ring.reserve(64);
    const bool tuned = has_tuned_edges(opt.weights);  // the tuned edge mask reads each end's valence
    std::vector<int> edge_valence(tuned ? static_cast<size_t>(nv) : 0);
    for (int v = 0; v < nv; ++v) {
        HalfedgeId start = he.halfedge(VertexId(v));
        if (!start.valid()) {
            out[v] = p[v];
            continue;
        }
        // On a boundary, walk from the face after the boundary half-edge leaving v, so that
        // the ring's ends are the two boundary neighbours (as the index-based walk does).
        HalfedgeId boundary_out;
        for (HalfedgeId h = start;;) {
            if (he.is_boundary(h)) boundary_out = h;
            h = he.next_around_origin(h);
            if (h == start) break;
        }
        if (boundary_out.valid()) start = he.next_around_origin(boundary_out);
        ring.clear();
        int faces = 0;
        HalfedgeId last = start;
        for (HalfedgeId h = start;;) {
            ring.push_back(he.origin(he.prev(h)).idx);
            ++faces;
            last = h;
            h = he.next_around_origin(h);
            if (h == start || he.is_boundary(h)) break;
        }
        if (tuned) edge_valence[v] = tuned_edge_valence(faces, boundary_out.valid());
        if (boundary_out.valid()) {
            const int ends[2] = {ring.front(), he.target(last).idx};
            const VertexMask m = boundary_vertex_mask(opt.boundary, faces);
            out[v] = detail::stencil_sum(p, &v, 1, m.self, ends, m.neighbor != 0.0 ? 2 : 0, m.neighbor);
        } else {
            const VertexMask m = interior_vertex_mask(opt.weights, faces);
            out[v] = detail::stencil_sum(p, &v, 1, m.self, ring.data(), static_cast<int>(ring.size()), m.neighbor);
        }
    }
    for (int e = 0; e < ne; ++e) {
        const HalfedgeId h = HalfedgeMesh::halfedge(EdgeId(e), 0), t = HalfedgeMesh::twin(h);
        const int ends[2] = {he.origin(h).idx, he.origin(t).idx};
        if (he.is_boundary(EdgeId(e))) {
            const EdgeMask m = boundary_edge_mask();
            out[nv + e] = detail::stencil_sum(p, ends, 2, m.end, nullptr, 0, 0.0);
        } else {
            const int opposite[2] = {he.origin(he.prev(h)).idx, he.origin(he.prev(t)).idx};
            const TunedEdgeMask m = tuned_edge_mask(opt.weights, tuned ? edge_valence[ends[0]] : 0,
                                                    tuned ? edge_valence[ends[1]] : 0);
            out[nv + e] = m.end_a == m.end_b
                              ? detail::stencil_sum(p, ends, 2, m.end_a, opposite, 2, m.opposite)
                              : detail::stencil_sum(p, ends, 1, m.end_a, opposite, 2, m.opposite, ends + 1, 1, m.end_b);
        }
    }
    return out;
}

}  // namespace

TriMesh loop_by_split_and_flip(const TriMesh& mesh, const LoopOptions& options) {
    const TriConnectivity conn = loop_input_connectivity(mesh);
    HalfedgeMesh he = HalfedgeMesh::from_connectivity(mesh, conn);
    const int nv = he.num_vertices(), ne = he.num_edges();

    TriMesh out;
    out.positions = loop_points(he, mesh.positions, options);
    detail::require_finite_level(out.positions, mesh.positions, 1);
    if (!mesh.colors.empty()) out.colors = loop_points(he, mesh.colors, options);

    // Split every old edge. split() numbers its new edges: the other half of the old edge
    // first, then the edges across the faces; only the latter may need a flip.
    std::vector<char> crosses;  // per edge after the splits: joins the new vertex to a face's third vertex
    crosses.assign(static_cast<size_t>(ne), 0);
    for (int e = 0; e < ne; ++e) {
        const int before = he.num_edges();
        const VertexId m = he.split(EdgeId(e));
        if (m.idx != nv + e) throw std::logic_error("split of edge " + std::to_string(e) + " made vertex " + std::to_string(m.idx));
        crosses.push_back(0);
        for (int k = before + 1; k < he.num_edges(); ++k) crosses.push_back(1);
    }
    // Flip each cross edge with exactly one old endpoint; cross edges between two new
    // vertices already bound the centre triangles.
    for (int e = ne; e < he.num_edges(); ++e) {
        if (!crosses[static_cast<size_t>(e)]) continue;
        const HalfedgeId h = HalfedgeMesh::halfedge(EdgeId(e));
        if ((he.origin(h).idx < nv) == (he.target(h).idx < nv)) continue;
        // The flipped edge joins two new vertices. It can already exist only when two coarse
        // faces share all three vertices (a doubled triangle, e.g. a two-face pillow): the
        // index-based driver then makes two edges between the same vertices, which a flip,
        // refusing to duplicate an edge, cannot.
        const VertexId c = he.origin(he.prev(h)), d = he.origin(he.prev(HalfedgeMesh::twin(h)));
        const FlipRefusal r = he.flip(EdgeId(e));
        if (r != FlipRefusal::None)
            throw InputError("Loop by split and flip: flipping the new edge (" + std::to_string(he.origin(h).idx) + ", " +
                             std::to_string(he.target(h).idx) + ") to (" + std::to_string(c.idx) + ", " + std::to_string(d.idx) +
                             ") is refused: " + std::string(to_string(r)) +
                             "; the input has two faces on the same three vertices, whose refinement needs a doubled edge");
    }
    out.triangles = he.triangles();
    return out;
}

}  // namespace crossdiv
