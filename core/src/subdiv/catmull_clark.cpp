#include "crossdiv/subdiv/catmull_clark.h"

#include <climits>
#include <optional>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/crease_level.h"
#include "crossdiv/subdiv/hierarchical_edit_walk.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "level_loop.h"

namespace crossdiv {
namespace {

/// The smooth interior mask in VertexPointMask form (for blending with a sharper rule).
void set_smooth_mask(VertexPointMask& m, int valence, CatmullClarkVertexRule rule) {
    const CatmullClarkVertexMask w = catmull_clark_interior_vertex_mask(valence, rule);
    m.vertex = w.self;
    m.has_edges = true;
    m.edge.assign(static_cast<size_t>(valence), w.ring);
    m.face.assign(static_cast<size_t>(valence), w.face);
}

}  // namespace

RefinementStep catmull_clark_step(const PolyMesh& mesh, const PolyConnectivity& conn, const CatmullClarkOptions& options) {
    detail::require_no_hierarchical_edits(mesh, "a single Catmull-Clark step");
    const int nv = mesh.num_vertices(), nf = mesh.num_faces(), ne = conn.num_edges(), nc = conn.num_corners();
    if (static_cast<long long>(nv) + nf + ne > INT_MAX || 4LL * nc > INT_MAX)
        throw InputError("the next Catmull-Clark level would have " + std::to_string(nc) +
                         " faces, more than 32-bit indices address; use fewer levels");
    const int face_point = nv, edge_point = nv + nf;
    RefinementStep step(nv);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + nf + ne, 8 * static_cast<size_t>(nc) + nv);

    // Crease tags switch on OpenSubdiv's sharp rules, whose boundary is edge-only or
    // edge-and-corner; an untagged mesh takes the plain masks below (the same weights).
    std::optional<CreaseLevel> crease;
    if (!mesh.creases.empty()) {
        if (options.boundary == CatmullClarkBoundary::MidpointAverage)
            throw InputError("crease and hole tags follow OpenSubdiv's rules, whose boundary is edge-only or "
                             "edge-and-corner; the midpoint-average boundary rule has no tags");
        crease.emplace(mesh, conn, options.creasing, options.boundary == CatmullClarkBoundary::EdgeAndCorner, options.crease_rules);
        step.creases = crease->child_tags(edge_point);
        // One quad per corner, in corner order (below): face f's children are its corners.
        step.creases.holes = child_holes(mesh.creases.holes, [&](int f) { return mesh.face_start[f]; });
    }
    VertexPointMask mask, child_mask;  // reused: no allocation per vertex once grown

    // Vertex points. The terms are added in OpenSubdiv's order (PrimvarRefiner::interpFromVerts:
    // face points, then ring vertices, then the vertex) so that rounding can match.
    for (int v = 0; v < nv; ++v) {
        const int start = conn.vertex_corner[v];
        if (start < 0) {  // isolated: nothing to average with, it stays
            st.add(v, 1.0);
            st.end_row();
            continue;
        }
        if (crease) {
            const CreaseLevel::Vertex& r = crease->vertex(v);
            if (r.parent == VertexRule::Crease || r.parent == VertexRule::Corner) {
                vertex_point_mask(r, mask, child_mask, [&](VertexPointMask& m) { set_smooth_mask(m, r.edges, options.vertex); });
                add_vertex_point_mask(st, conn, v, mask, face_point);
                st.end_row();
                continue;
            }
        }
        const PolyConnectivity::Fan fan = conn.fan(v);
        const int faces = fan.faces;
        if (conn.is_boundary_vertex(v)) {
            const CatmullClarkBoundaryMask m = catmull_clark_boundary_vertex_mask(options.boundary, faces);
            if (m.neighbor != 0.0) {
                const PolyConnectivity::BoundaryNeighbors nb = conn.boundary_neighbors(v, fan);
                st.add(nb.before, m.neighbor);
                st.add(nb.after, m.neighbor);
            }
            st.add(v, m.self);
        } else {
            const CatmullClarkVertexMask m = catmull_clark_interior_vertex_mask(faces, options.vertex);
            for (int c = start;;) {
                st.add_refined(face_point + conn.corner_face[c], m.face);
                c = conn.next_around_vertex(c);
                if (c == start) break;
            }
            for (int c = start;;) {
                st.add(conn.head(c), m.ring);
                c = conn.next_around_vertex(c);
                if (c == start) break;
            }
            st.add(v, m.self);
        }
        st.end_row();
    }
    // Face points: the centroid.
    for (int f = 0; f < nf; ++f) {
        const double w = 1.0 / mesh.face_size(f);
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) st.add(conn.corner_vertex[c], w);
        st.end_row();
    }
    // Edge points: the endpoints, then the face points of the two faces.
    for (int e = 0; e < ne; ++e) {
        const int c = conn.edge_corner[e], t = conn.twin[c];
        const auto& ends = conn.edge_vertices[e];
        const CatmullClarkEdgeWeights smooth =
            t < 0 ? CatmullClarkEdgeWeights{kCatmullClarkEdgeEnd, kCatmullClarkEdgeFace}
                  : catmull_clark_edge_weights(options.smooth_triangles, mesh.face_size(conn.corner_face[c]) == 3,
                                               mesh.face_size(conn.corner_face[t]) == 3);
        EdgePointWeights w{smooth.end, smooth.face};
        if (t < 0 || (crease && crease->edge_child_is_crease(e))) {
            w = {0.5, 0.0};  // the crease mask: the midpoint
        } else if (crease && is_sharp(crease->edge_sharpness(e))) {
            w = transition_edge_weights(w, crease->edge_sharpness(e));
        }
        st.add(ends[0], w.end);
        st.add(ends[1], w.end);
        if (w.other != 0.0) {
            st.add_refined(face_point + conn.corner_face[c], w.other);
            st.add_refined(face_point + conn.corner_face[t], w.other);
        }
        st.end_row();
    }

    step.face_vertices.reserve(4 * static_cast<size_t>(nc));
    step.face_start.reserve(static_cast<size_t>(nc) + 1);
    for (int c = 0; c < nc; ++c)
        step.add_face({conn.corner_vertex[c], edge_point + conn.corner_edge[c], face_point + conn.corner_face[c],
                       edge_point + conn.corner_edge[conn.prev[c]]});
    return step;
}

std::vector<PolyMesh> catmull_clark_levels(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels) {
    if (levels < 0) throw InputError("number of levels must be >= 0, got " + std::to_string(levels));
    std::vector<PolyMesh> out;
    out.reserve(static_cast<size_t>(levels) + 1);
    HierarchicalEditWalk walk(mesh);
    if (!walk.empty() && !mesh.derived.empty())
        throw InputError("hierarchical edits are applied on a manifold refinement only; this level's edges are stated per corner");
    PolyMesh current = mesh;
    current.creases.edits.clear();  // the walk applies them, level by level
    walk.apply(current, 0);
    out.push_back(current);
    for (int l = 0; l < levels; ++l) {
        PolyMesh next = walk.empty() ? catmull_clark_subdivide(current, options, 1)
                                     : detail::refine_levels(current, 1, [&](const PolyMesh& m, const PolyConnectivity& conn, int) {
                                           return catmull_clark_step(m, conn, options);
                                       });
        walk.descend(current, l);
        walk.apply(next, l + 1);
        out.push_back(next);
        current = std::move(next);
    }
    return out;
}

PolyMesh catmull_clark_subdivide(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels) {
    if (!mesh.creases.edits.empty()) return std::move(catmull_clark_levels(mesh, options, levels).back());
    return detail::with_nonmanifold_rules(
        mesh, options.nonmanifold,
        [&] {
            return detail::refine_levels(mesh, levels, [&](const PolyMesh& m, const PolyConnectivity& conn, int) {
                return catmull_clark_step(m, conn, options);
            });
        },
        [&] { return catmull_clark_subdivide_nonmanifold(mesh, options, levels); });
}

Eigen::SparseMatrix<double> catmull_clark_subdivision_matrix(const PolyMesh& mesh, const CatmullClarkOptions& options) {
    return catmull_clark_step(mesh, build_poly_connectivity(mesh), options).stencils.matrix();
}

}  // namespace crossdiv
