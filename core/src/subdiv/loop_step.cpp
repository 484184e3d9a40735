// Loop subdivision as a RefinementStep of the generic driver: the path of crease-tagged
// meshes, whose sharp rules (crease_mask.h) need every vertex's whole mask, not the two
// equally weighted groups of the fast driver in loop.cpp. Vertex and face order are those
// of loop_refine_once; each stencil is summed term by term, in OpenSubdiv's order.
#include <climits>
#include <optional>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/crease_level.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "level_loop.h"

namespace crossdiv {
namespace {

/// The smooth interior mask in VertexPointMask form.
void set_smooth_mask(VertexPointMask& m, LoopWeights weights, int valence) {
    const VertexMask w = interior_vertex_mask(weights, valence);
    m.vertex = w.self;
    m.has_edges = true;
    m.edge.assign(static_cast<size_t>(valence), w.neighbor);
    m.face.clear();
}

}  // namespace

RefinementStep loop_step(const PolyMesh& mesh, const PolyConnectivity& conn, const LoopOptions& options) {
    detail::require_no_hierarchical_edits(mesh, "Loop subdivision");
    detail::require_triangles(mesh, "Loop subdivision");
    // The sharp rules (crease_mask.h) blend with the symmetric edge mask of Loop and Warren;
    // no rule is defined for a crease next to the tuned families' asymmetric one.
    if (has_tuned_edges(options.weights))
        throw InputError("crease rules are defined for the weight families with Loop's edge mask (loop, warren), not for " +
                         std::string(to_string(options.weights)));
    const int nv = mesh.num_vertices(), nf = mesh.num_faces(), ne = conn.num_edges();
    if (4LL * nf > INT_MAX || static_cast<long long>(nv) + ne > INT_MAX)
        throw InputError("the next Loop level would have " + std::to_string(4LL * nf) +
                         " faces, more than 32-bit indices address; use fewer levels");
    RefinementStep step(nv);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + ne, 7 * static_cast<size_t>(nv) + 4 * static_cast<size_t>(ne));

    std::optional<CreaseLevel> crease;
    if (!mesh.creases.empty()) {
        crease.emplace(mesh, conn, options.creasing, options.boundary == LoopBoundary::EdgeAndCorner, options.crease_rules);
        step.creases = crease->child_tags(nv);
        step.creases.holes = child_holes(mesh.creases.holes, [](int f) { return 4 * f; });  // 4 per triangle, below
    }
    VertexPointMask mask, child;  // reused: no allocation per vertex once grown

    for (int v = 0; v < nv; ++v) {
        if (conn.vertex_corner[v] < 0) {  // isolated: it stays
            st.add(v, 1.0);
            st.end_row();
            continue;
        }
        if (crease) {
            const CreaseLevel::Vertex& r = crease->vertex(v);
            vertex_point_mask(r, mask, child, [&](VertexPointMask& m) { set_smooth_mask(m, options.weights, r.edges); });
        } else if (conn.is_boundary_vertex(v)) {
            const PolyConnectivity::Fan fan = conn.fan(v);
            const VertexMask m = boundary_vertex_mask(options.boundary, fan.faces);
            if (m.neighbor == 0.0) {
                mask.set_corner();
            } else {  // for_each_edge_around ends with the incoming boundary edge
                mask.set_crease(fan.faces + 1, fan.faces - 1, fan.faces);
                mask.vertex = m.self;
                mask.edge[static_cast<size_t>(fan.faces - 1)] = mask.edge[static_cast<size_t>(fan.faces)] = m.neighbor;
            }
        } else {
            set_smooth_mask(mask, options.weights, conn.fan(v).faces);
        }
        add_vertex_point_mask(st, conn, v, mask, 0);
        st.end_row();
    }

    for (int e = 0; e < ne; ++e) {
        const int c = conn.edge_corner[e], t = conn.twin[c];
        const auto& ends = conn.edge_vertices[e];
        const EdgeMask smooth = interior_edge_mask();
        EdgePointWeights w{smooth.end, smooth.opposite};
        if (t < 0 || (crease && crease->edge_child_is_crease(e))) {
            w = {0.5, 0.0};  // the crease mask: the midpoint (boundary_edge_mask)
        } else if (crease && is_sharp(crease->edge_sharpness(e))) {
            w = transition_edge_weights(w, crease->edge_sharpness(e));
        }
        st.add(ends[0], w.end);
        st.add(ends[1], w.end);
        if (w.other != 0.0) {  // the vertices opposite the edge in its two triangles
            st.add(conn.corner_vertex[conn.prev[c]], w.other);
            st.add(conn.corner_vertex[conn.prev[t]], w.other);
        }
        st.end_row();
    }

    step.face_vertices.reserve(12 * static_cast<size_t>(nf));
    step.face_start.reserve(4 * static_cast<size_t>(nf) + 1);
    for (int f = 0; f < nf; ++f) {
        const int c = mesh.face_start[f];
        const int* v = mesh.face(f);
        const int m0 = nv + conn.corner_edge[c], m1 = nv + conn.corner_edge[c + 1], m2 = nv + conn.corner_edge[c + 2];
        step.add_face({v[0], m0, m2});
        step.add_face({v[1], m1, m0});
        step.add_face({v[2], m2, m1});
        step.add_face({m0, m1, m2});
    }
    return step;
}

void check_loop_input(const TriMesh& mesh, const LoopOptions& options) {
    try {
        loop_input_connectivity(mesh);
    } catch (const NonManifoldInput&) {
        // A triangle mesh without tags: the rules refine its every topology under every weight family.
        if (options.nonmanifold == NonManifoldRule::Refuse) throw;
    }
}

PolyMesh loop_subdivide(const PolyMesh& mesh, const LoopOptions& options, int levels) {
    detail::require_no_hierarchical_edits(mesh, "Loop subdivision");
    return detail::with_nonmanifold_rules(
        mesh, options.nonmanifold,
        [&] {
            if (mesh.creases.empty()) {  // the fast path; the result is the same
                detail::require_triangles(mesh, "Loop subdivision");
                return to_poly_mesh(loop_subdivide(to_tri_mesh(mesh, "Loop subdivision"), options, levels));
            }
            return detail::refine_levels(mesh, levels, [&](const PolyMesh& m, const PolyConnectivity& conn, int) {
                return loop_step(m, conn, options);
            });
        },
        [&] { return loop_subdivide_nonmanifold(mesh, options, levels); });
}

}  // namespace crossdiv
