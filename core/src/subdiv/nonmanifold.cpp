// Loop and Catmull-Clark on topology that is not a manifold, with OpenSubdiv's rules
// (nonmanifold.h). The topology is completed from the face-vertices with flat arrays and one
// sort of the corners by edge, so the cost is O(n log n) in the corners and linear in valence.
#include "crossdiv/subdiv/nonmanifold.h"

#include <algorithm>
#include <climits>
#include <numeric>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/crease_mask.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "level_loop.h"

namespace crossdiv {
namespace {

/// One level's topology as Far completes it from face-vertices (Vtr::internal::Level), with
/// the vertex rules of prepareComponentTagsAndSharpness. Corner c is entry c of
/// face_vertices and the half-edge leaving its vertex along its face.
struct GeneralTopology {
    std::vector<int> corner_face, corner_edge;
    std::vector<int> edge_first;                  ///< the corner that numbered each edge
    std::vector<char> edge_sharp;                 ///< boundary or non-manifold: infinitely sharp
    std::vector<char> edge_nonmanifold;           ///< passed on to the edge's two halves
    std::vector<int> edge_corner_start, edge_corners;      ///< CSR: the half-edges on each edge
    std::vector<int> vertex_corner_start, vertex_corners;  ///< CSR: the corners at each vertex
    std::vector<int> vertex_edge_start, vertex_edges;      ///< CSR: the edges at each vertex
    std::vector<VertexRule> rule;
    std::vector<std::array<int, 2>> crease_ends;  ///< Crease: the other ends of its two sharp edges
    std::vector<char> nonmanifold_vertex;
    std::vector<char> sharp_vertex;  ///< infinitely sharp: passed on to the vertex's child
    /// Each corner's fan: the corners at its vertex joined across manifold edges, named by
    /// one of them (a root corner). fan_size and fan_open are indexed by the root.
    std::vector<int> corner_fan, fan_size;
    std::vector<char> fan_open;  ///< the fan ends at a sharp (boundary or non-manifold) edge
    const PolyMesh* mesh = nullptr;

    int num_edges() const { return static_cast<int>(edge_first.size()); }
    int vertex(int c) const { return mesh->face_vertices[static_cast<size_t>(c)]; }
    int next(int c) const {
        const int f = corner_face[static_cast<size_t>(c)];
        return c + 1 == mesh->face_start[f + 1] ? mesh->face_start[f] : c + 1;
    }
    int prev(int c) const {
        const int f = corner_face[static_cast<size_t>(c)];
        return c == mesh->face_start[f] ? mesh->face_start[f + 1] - 1 : c - 1;
    }
    /// The child edge (a label, PolyMesh::corner_edges) of corner c's edge that ends at c's
    /// vertex (`at_start`) or at the next corner's: 2e for the half at the edge's first end,
    /// 2e + 1 at its second. Two faces that traverse the edge the same way share its halves.
    int child_half(int c, bool at_start) const {
        const int e = corner_edge[static_cast<size_t>(c)];
        const int start_end = vertex(c) == vertex(edge_first[static_cast<size_t>(e)]) ? 0 : 1;
        return 2 * e + (at_start ? start_end : 1 - start_end);
    }
    int other_end(int e, int v) const {
        const int c = edge_first[static_cast<size_t>(e)];
        return vertex(c) == v ? vertex(next(c)) : vertex(c);
    }
    /// The valence corner c's vertex reads in the tuned edge mask of an edge of c's face: its
    /// fan's, as tuned_edge_valence reads a manifold vertex (loop_mask.h).
    int tuned_valence(int c) const {
        const int fan = corner_fan[static_cast<size_t>(c)];
        return tuned_edge_valence(fan_size[static_cast<size_t>(fan)], fan_open[static_cast<size_t>(fan)] != 0);
    }
};

int find(std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

/// CSR from (key, value) pairs with keys in [0, n): values grouped by key, in input order.
void group(int n, const std::vector<std::pair<int, int>>& items, std::vector<int>& start, std::vector<int>& values) {
    start.assign(static_cast<size_t>(n) + 1, 0);
    for (const auto& [k, v] : items) ++start[static_cast<size_t>(k) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    values.resize(items.size());
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const auto& [k, v] : items) values[static_cast<size_t>(fill[static_cast<size_t>(k)]++)] = v;
}

/// @throws InputError unless `derived` states an edge for each of `nc` corners, a tag for
///         each of its labels and one for each of `nv` vertices.
void require_consistent(const DerivedTopology& derived, int nc, int nv) {
    if (derived.corner_edges.size() != static_cast<size_t>(nc))
        throw InputError("the mesh states " + std::to_string(derived.corner_edges.size()) + " corner edges for " +
                         std::to_string(nc) + " corners");
    for (int label : derived.corner_edges)
        if (label < 0 || static_cast<size_t>(label) >= derived.nonmanifold_edges.size())
            throw InputError("the mesh states edge " + std::to_string(label) + " but tags " +
                             std::to_string(derived.nonmanifold_edges.size()) + " edges");
    if (derived.sharp_vertices.size() != static_cast<size_t>(nv))
        throw InputError("the mesh states the sharpness of " + std::to_string(derived.sharp_vertices.size()) +
                         " vertices for " + std::to_string(nv));
}

GeneralTopology complete_topology(const PolyMesh& mesh, bool sharpen_corners) {
    GeneralTopology t;
    t.mesh = &mesh;
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    const int nc = static_cast<int>(mesh.face_vertices.size());
    t.corner_face.resize(static_cast<size_t>(nc));
    for (int f = 0; f < nf; ++f) {
        if (mesh.face_size(f) < 3)
            throw InputError(mesh.source.describe_face(f) + ": has " + std::to_string(mesh.face_size(f)) +
                             " corners, needs at least 3");
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
            const int v = mesh.face_vertices[static_cast<size_t>(c)];
            if (v < 0 || v >= nv)
                throw InputError(mesh.source.describe_face(f) + ": vertex index " + std::to_string(v) + " out of range");
            t.corner_face[static_cast<size_t>(c)] = f;
        }
    }

    // Edges, numbered at their first corner. Given explicitly (a refined level), the corners
    // with one label; otherwise as completeTopologyFromFaceVertices makes them, corners in
    // face order: a vertex pair is one edge, except that a degenerate pair (a, a) is a new
    // edge at every corner, and so is a pair the edge's last face already uses (a face that
    // names it twice); those are non-manifold.
    const DerivedTopology& derived = mesh.derived;
    const bool labelled = !derived.empty();
    if (labelled) require_consistent(derived, nc, nv);
    auto key = [&](int c) {
        if (labelled) return std::pair{derived.corner_edges[static_cast<size_t>(c)], 0};
        const int a = t.vertex(c), b = t.vertex(t.next(c));
        return std::pair{std::min(a, b), std::max(a, b)};
    };
    std::vector<int> order(static_cast<size_t>(nc));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int x, int y) { return std::pair{key(x), x} < std::pair{key(y), y}; });
    std::vector<int> group_first;   // per edge found, its first corner
    std::vector<char> group_forced;  // made non-manifold by the rules above
    std::vector<int> corner_group(static_cast<size_t>(nc));
    int run_group = -1, run_last_face = -1;  // the pair's first edge, and the last face that joined it
    for (size_t k = 0; k < order.size(); ++k) {
        const int c = order[k];
        const bool new_run = k == 0 || key(c) != key(order[k - 1]);
        const int face = t.corner_face[static_cast<size_t>(c)];
        const bool degenerate = !labelled && t.vertex(c) == t.vertex(t.next(c));
        if (!new_run && (labelled || (!degenerate && face != run_last_face))) {
            corner_group[static_cast<size_t>(c)] = run_group;
            run_last_face = face;
            continue;
        }
        const bool repeated = !labelled && !new_run && !degenerate;  // in the face that last joined
        if (repeated) group_forced[static_cast<size_t>(run_group)] = 1;
        group_first.push_back(c);
        group_forced.push_back(degenerate || repeated);
        corner_group[static_cast<size_t>(c)] = static_cast<int>(group_first.size()) - 1;
        if (new_run) {
            run_group = corner_group[static_cast<size_t>(c)];
            run_last_face = face;
        }
    }
    std::vector<int> by_first(group_first.size());
    std::iota(by_first.begin(), by_first.end(), 0);
    std::sort(by_first.begin(), by_first.end(), [&](int x, int y) { return group_first[x] < group_first[y]; });
    std::vector<int> edge_of_group(group_first.size());
    std::vector<char> forced(group_first.size());
    for (size_t e = 0; e < by_first.size(); ++e) {
        edge_of_group[static_cast<size_t>(by_first[e])] = static_cast<int>(e);
        t.edge_first.push_back(group_first[static_cast<size_t>(by_first[e])]);
        forced[e] = group_forced[static_cast<size_t>(by_first[e])];
    }
    const int ne = t.num_edges();
    t.corner_edge.resize(static_cast<size_t>(nc));
    std::vector<std::pair<int, int>> items;
    items.reserve(static_cast<size_t>(nc));
    for (int c = 0; c < nc; ++c) {
        t.corner_edge[static_cast<size_t>(c)] = edge_of_group[static_cast<size_t>(corner_group[static_cast<size_t>(c)])];
        items.emplace_back(t.corner_edge[static_cast<size_t>(c)], c);
    }
    group(ne, items, t.edge_corner_start, t.edge_corners);

    // Edge tags: boundary (one face), non-manifold (more than two, or two the same way; on a
    // refined level, inherited from the parent edge, as Far's child edges take their tags).
    std::vector<char> boundary(static_cast<size_t>(ne));
    std::vector<char>& nonmanifold = t.edge_nonmanifold;
    nonmanifold.resize(static_cast<size_t>(ne));
    t.edge_sharp.resize(static_cast<size_t>(ne));
    std::vector<int> parent(static_cast<size_t>(nc));  // fans: corners at a vertex joined across manifold edges
    std::iota(parent.begin(), parent.end(), 0);
    for (int e = 0; e < ne; ++e) {
        const int b = t.edge_corner_start[e], n = t.edge_corner_start[e + 1] - b;
        const int h1 = t.edge_corners[static_cast<size_t>(b)];
        const int h2 = n == 2 ? t.edge_corners[static_cast<size_t>(b) + 1] : -1;
        boundary[static_cast<size_t>(e)] = n == 1;
        nonmanifold[static_cast<size_t>(e)] =
            labelled ? derived.nonmanifold_edges[static_cast<size_t>(key(h1).first)] != 0
                     : forced[static_cast<size_t>(e)] || n > 2 || (n == 2 && t.vertex(h1) == t.vertex(h2));
        t.edge_sharp[static_cast<size_t>(e)] = boundary[static_cast<size_t>(e)] || nonmanifold[static_cast<size_t>(e)];
        if (n == 2 && !nonmanifold[static_cast<size_t>(e)]) {
            parent[static_cast<size_t>(find(parent, h1))] = find(parent, t.next(h2));  // both at h1's vertex
            parent[static_cast<size_t>(find(parent, t.next(h1)))] = find(parent, h2);  // both at h2's vertex
        }
    }

    t.corner_fan.resize(static_cast<size_t>(nc));
    t.fan_size.assign(static_cast<size_t>(nc), 0);
    t.fan_open.assign(static_cast<size_t>(nc), 0);
    for (int c = 0; c < nc; ++c) {
        const int r = find(parent, c);
        t.corner_fan[static_cast<size_t>(c)] = r;
        ++t.fan_size[static_cast<size_t>(r)];
        if (t.edge_sharp[static_cast<size_t>(t.corner_edge[static_cast<size_t>(c)])] ||
            t.edge_sharp[static_cast<size_t>(t.corner_edge[static_cast<size_t>(t.prev(c))])])
            t.fan_open[static_cast<size_t>(r)] = 1;
    }

    items.clear();
    for (int c = 0; c < nc; ++c) items.emplace_back(t.vertex(c), c);
    group(nv, items, t.vertex_corner_start, t.vertex_corners);
    items.clear();
    for (int e = 0; e < ne; ++e) {
        const int c = t.edge_first[static_cast<size_t>(e)];
        items.emplace_back(t.vertex(c), e);
        items.emplace_back(t.vertex(t.next(c)), e);
    }
    group(nv, items, t.vertex_edge_start, t.vertex_edges);

    // Vertex tags and rules (prepareComponentTagsAndSharpness, DetermineVertexVertexRule).
    // The base level sharpens its non-manifold vertices and corners; a refined level's
    // vertices keep their parents' sharpness (an edge's or a face's point has none).
    t.rule.assign(static_cast<size_t>(nv), VertexRule::Smooth);
    t.crease_ends.assign(static_cast<size_t>(nv), {-1, -1});
    t.nonmanifold_vertex.assign(static_cast<size_t>(nv), 0);
    t.sharp_vertex.assign(static_cast<size_t>(nv), 0);
    std::vector<int> root_seen(static_cast<size_t>(nc), -1);
    for (int v = 0; v < nv; ++v) {
        const int faces = t.vertex_corner_start[v + 1] - t.vertex_corner_start[v];
        const int edges = t.vertex_edge_start[v + 1] - t.vertex_edge_start[v];
        if (faces == 0) {  // isolated: it stays
            t.rule[static_cast<size_t>(v)] = VertexRule::Corner;
            continue;
        }
        int fans = 0;
        for (int k = t.vertex_corner_start[v]; k < t.vertex_corner_start[v + 1]; ++k) {
            const int r = t.corner_fan[static_cast<size_t>(t.vertex_corners[static_cast<size_t>(k)])];
            if (root_seen[static_cast<size_t>(r)] != v) {
                root_seen[static_cast<size_t>(r)] = v;
                ++fans;
            }
        }
        int boundary_edges = 0, nonmanifold_edges = 0, sharp_edges = 0;
        std::array<int, 2> ends{-1, -1};
        for (int k = t.vertex_edge_start[v]; k < t.vertex_edge_start[v + 1]; ++k) {
            const int e = t.vertex_edges[static_cast<size_t>(k)];
            boundary_edges += boundary[static_cast<size_t>(e)];
            nonmanifold_edges += nonmanifold[static_cast<size_t>(e)];
            if (t.edge_sharp[static_cast<size_t>(e)]) {
                if (sharp_edges < 2) ends[static_cast<size_t>(sharp_edges)] = t.other_end(e, v);
                ++sharp_edges;
            }
        }
        // A manifold boundary vertex has one fan that ends at two boundary edges.
        const bool nonmanifold_vertex = nonmanifold_edges > 0 || fans > 1;
        t.nonmanifold_vertex[static_cast<size_t>(v)] = nonmanifold_vertex;
        const bool interior_crease = nonmanifold_edges == 2 && boundary_edges == 0 && faces > edges;
        const bool sharp = labelled ? derived.sharp_vertices[static_cast<size_t>(v)] != 0
                                    : (nonmanifold_vertex && !interior_crease) || (sharpen_corners && faces == 1 && edges == 2);
        t.sharp_vertex[static_cast<size_t>(v)] = sharp;
        t.rule[static_cast<size_t>(v)] = vertex_rule(sharp ? kSharpnessInfinite : 0.0f, sharp_edges);
        t.crease_ends[static_cast<size_t>(v)] = ends;
    }
    return t;
}

void require_untagged(const PolyMesh& mesh) {
    if (!mesh.creases.edges.empty() || !mesh.creases.vertices.empty())
        throw InputError((mesh.source.file.empty() ? std::string("the mesh") : mesh.source.file) +
                         " is not a manifold and has crease or corner tags; sharpness tags on a non-manifold mesh "
                         "are not implemented (refine it without the tags, or fix the topology)");
}

/// Corner and crease rows, shared by both schemes; false for the smooth rule.
bool add_sharp_vertex_row(StencilTable& st, const GeneralTopology& t, int v) {
    switch (t.rule[static_cast<size_t>(v)]) {
        case VertexRule::Corner: st.add(v, 1.0); return true;
        case VertexRule::Crease:
            st.add(v, 0.75);
            st.add(t.crease_ends[static_cast<size_t>(v)][0], 0.125);
            st.add(t.crease_ends[static_cast<size_t>(v)][1], 0.125);
            return true;
        default: return false;
    }
}

/// The refined level's tags, as Far's Refinement passes them on: each edge's two halves
/// (labels 2e, 2e + 1) non-manifold when it is, the edges inside the faces (the labels
/// after them, `num_labels` in all) manifold; each vertex's child (the first of the
/// `num_child_vertices`) sharp when it is, the edge and face points smooth.
void pass_on_tags(const GeneralTopology& t, int num_child_vertices, int num_labels, DerivedTopology& child) {
    child.nonmanifold_edges.assign(static_cast<size_t>(num_labels), 0);
    for (int e = 0; e < t.num_edges(); ++e) {
        child.nonmanifold_edges[2 * static_cast<size_t>(e)] = t.edge_nonmanifold[static_cast<size_t>(e)];
        child.nonmanifold_edges[2 * static_cast<size_t>(e) + 1] = t.edge_nonmanifold[static_cast<size_t>(e)];
    }
    child.sharp_vertices.assign(static_cast<size_t>(num_child_vertices), 0);
    std::copy(t.sharp_vertex.begin(), t.sharp_vertex.end(), child.sharp_vertices.begin());
}

/// Four triangles per triangle (v_k, E(k), E(k-1)) for k = 0, 1, 2, then (E0, E1, E2) --
/// loop_step's order -- with the refined edges stated per corner: two halves per edge, three
/// inside the face (i_k opposite corner k's child), so that edges of different faces with the
/// same ends stay apart.
void add_triangles(const GeneralTopology& t, int nv, RefinementStep& step) {
    const PolyMesh& mesh = *t.mesh;
    const int nf = mesh.num_faces(), ne = t.num_edges();
    pass_on_tags(t, nv + ne, 2 * ne + 3 * nf, step.derived);
    step.face_vertices.reserve(12 * static_cast<size_t>(nf));
    step.derived.corner_edges.reserve(12 * static_cast<size_t>(nf));
    for (int f = 0; f < nf; ++f) {
        const int c = mesh.face_start[f];
        const int* v = mesh.face(f);
        const int m0 = nv + t.corner_edge[static_cast<size_t>(c)], m1 = nv + t.corner_edge[static_cast<size_t>(c) + 1],
                  m2 = nv + t.corner_edge[static_cast<size_t>(c) + 2];
        step.add_face({v[0], m0, m2});
        step.add_face({v[1], m1, m0});
        step.add_face({v[2], m2, m1});
        step.add_face({m0, m1, m2});
        const int i0 = 2 * ne + 3 * f, i1 = i0 + 1, i2 = i0 + 2;
        std::vector<int>& edges = step.derived.corner_edges;
        edges.insert(edges.end(), {t.child_half(c, true), i0, t.child_half(c + 2, false),      // v0 m0 m2
                                   t.child_half(c + 1, true), i1, t.child_half(c, false),      // v1 m1 m0
                                   t.child_half(c + 2, true), i2, t.child_half(c + 1, false),  // v2 m2 m1
                                   i1, i2, i0});                                               // m0 m1 m2
    }
}

/// The ends of each edge, in edge-point order.
std::vector<std::array<int, 2>> edge_ends(const GeneralTopology& t) {
    std::vector<std::array<int, 2>> ends;
    ends.reserve(static_cast<size_t>(t.num_edges()));
    for (int h : t.edge_first) ends.push_back({t.vertex(h), t.vertex(t.next(h))});
    return ends;
}

}  // namespace

RefinementStep loop_nonmanifold_step(const PolyMesh& mesh, const LoopOptions& options) {
    detail::require_no_hierarchical_edits(mesh, "Loop subdivision");
    for (int f = 0; f < mesh.num_faces(); ++f)
        if (mesh.face_size(f) != 3)
            throw InputError(mesh.source.describe_face(f) + ": has " + std::to_string(mesh.face_size(f)) +
                             " corners; Loop subdivision refines triangles only");
    require_untagged(mesh);
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    if (12LL * nf > INT_MAX) throw InputError("the next Loop level would have more than 2^31 corners; use fewer levels");
    const GeneralTopology t = complete_topology(mesh, options.boundary == LoopBoundary::EdgeAndCorner);
    const int ne = t.num_edges();
    RefinementStep step(nv);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + ne, 7 * static_cast<size_t>(nv) + 4 * static_cast<size_t>(ne));
    for (int v = 0; v < nv; ++v) {
        if (!add_sharp_vertex_row(st, t, v)) {
            const int n = t.vertex_edge_start[v + 1] - t.vertex_edge_start[v];
            const VertexMask m = interior_vertex_mask(options.weights, n);
            for (int k = t.vertex_edge_start[v]; k < t.vertex_edge_start[v + 1]; ++k)
                st.add(t.other_end(t.vertex_edges[static_cast<size_t>(k)], v), m.neighbor);
            st.add(v, m.self);
        }
        st.end_row();
    }
    const bool tuned = has_tuned_edges(options.weights);  // the tuned edge mask reads each end's fan
    for (int e = 0; e < ne; ++e) {
        const int h = t.edge_first[static_cast<size_t>(e)];
        if (t.edge_sharp[static_cast<size_t>(e)]) {
            const EdgeMask m = boundary_edge_mask();
            st.add(t.vertex(h), m.end);
            st.add(t.vertex(t.next(h)), m.end);
        } else {  // two triangles: the edge's ends, then the vertices opposite it
            const TunedEdgeMask m = tuned_edge_mask(options.weights, tuned ? t.tuned_valence(h) : 0,
                                                    tuned ? t.tuned_valence(t.next(h)) : 0);
            st.add(t.vertex(h), m.end_a);
            st.add(t.vertex(t.next(h)), m.end_b);
            for (int k = t.edge_corner_start[e]; k < t.edge_corner_start[e + 1]; ++k)
                st.add(t.vertex(t.prev(t.edge_corners[static_cast<size_t>(k)])), m.opposite);
        }
        st.end_row();
    }
    add_triangles(t, nv, step);
    step.creases.holes = child_holes(mesh.creases.holes, [](int f) { return 4 * f; });
    return step;
}

/// One quad per corner (v_c, E(c), F(f), E(prev c)) with the refined edges stated per corner:
/// two halves per edge, and per corner the one from its edge's point to the face point
/// (shared with the next corner's quad).
void add_quads(const GeneralTopology& t, int nv, int nf, RefinementStep& step) {
    const int nc = static_cast<int>(t.corner_face.size()), ne = t.num_edges(), face_point = nv, edge_point = nv + nf;
    pass_on_tags(t, nv + nf + ne, 2 * ne + nc, step.derived);
    step.face_vertices.reserve(4 * static_cast<size_t>(nc));
    step.derived.corner_edges.reserve(4 * static_cast<size_t>(nc));
    for (int c = 0; c < nc; ++c) {
        const int p = t.prev(c);
        step.add_face({t.vertex(c), edge_point + t.corner_edge[static_cast<size_t>(c)],
                       face_point + t.corner_face[static_cast<size_t>(c)], edge_point + t.corner_edge[static_cast<size_t>(p)]});
        std::vector<int>& edges = step.derived.corner_edges;
        edges.insert(edges.end(), {t.child_half(c, true), 2 * ne + c, 2 * ne + p, t.child_half(p, false)});
    }
}

RefinementStep catmull_clark_nonmanifold_step(const PolyMesh& mesh, const CatmullClarkOptions& options) {
    detail::require_no_hierarchical_edits(mesh, "the non-manifold Catmull-Clark refinement");
    require_untagged(mesh);
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    const int nc = static_cast<int>(mesh.face_vertices.size());
    if (4LL * nc > INT_MAX)
        throw InputError("the next Catmull-Clark level would have more than 2^31 indices; use fewer levels");
    const GeneralTopology t = complete_topology(mesh, options.boundary == CatmullClarkBoundary::EdgeAndCorner);
    const int ne = t.num_edges(), face_point = nv;
    RefinementStep step(nv);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + nf + ne, 8 * static_cast<size_t>(nc) + nv);
    const bool midpoint_average = options.boundary == CatmullClarkBoundary::MidpointAverage;
    for (int v = 0; v < nv; ++v) {
        if (midpoint_average && t.rule[static_cast<size_t>(v)] == VertexRule::Crease && !t.nonmanifold_vertex[static_cast<size_t>(v)]) {
            // A manifold boundary vertex under the midpoint-average rule (the manifold driver's
            // mask); the non-manifold vertices keep OpenSubdiv's rules.
            const int faces = t.vertex_corner_start[v + 1] - t.vertex_corner_start[v];
            const CatmullClarkBoundaryMask m = catmull_clark_boundary_vertex_mask(CatmullClarkBoundary::MidpointAverage, faces);
            st.add(t.crease_ends[static_cast<size_t>(v)][0], m.neighbor);
            st.add(t.crease_ends[static_cast<size_t>(v)][1], m.neighbor);
            st.add(v, m.self);
        } else if (!add_sharp_vertex_row(st, t, v)) {
            // Smooth or dart: a manifold interior vertex, as many faces as edges.
            const int n = t.vertex_edge_start[v + 1] - t.vertex_edge_start[v];
            const CatmullClarkVertexMask m = catmull_clark_interior_vertex_mask(n, options.vertex);
            for (int k = t.vertex_corner_start[v]; k < t.vertex_corner_start[v + 1]; ++k)
                st.add_refined(face_point + t.corner_face[static_cast<size_t>(t.vertex_corners[static_cast<size_t>(k)])], m.face);
            for (int k = t.vertex_edge_start[v]; k < t.vertex_edge_start[v + 1]; ++k)
                st.add(t.other_end(t.vertex_edges[static_cast<size_t>(k)], v), m.ring);
            st.add(v, m.self);
        }
        st.end_row();
    }
    for (int f = 0; f < nf; ++f) {
        const double w = 1.0 / mesh.face_size(f);
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) st.add(t.vertex(c), w);
        st.end_row();
    }
    for (int e = 0; e < ne; ++e) {
        const int h = t.edge_first[static_cast<size_t>(e)];
        if (t.edge_sharp[static_cast<size_t>(e)]) {
            st.add(t.vertex(h), 0.5);
            st.add(t.vertex(t.next(h)), 0.5);
        } else {
            const int f0 = t.corner_face[static_cast<size_t>(t.edge_corners[static_cast<size_t>(t.edge_corner_start[e])])];
            const int f1 = t.corner_face[static_cast<size_t>(t.edge_corners[static_cast<size_t>(t.edge_corner_start[e]) + 1])];
            const CatmullClarkEdgeWeights w =
                catmull_clark_edge_weights(options.smooth_triangles, mesh.face_size(f0) == 3, mesh.face_size(f1) == 3);
            st.add(t.vertex(h), w.end);
            st.add(t.vertex(t.next(h)), w.end);
            st.add_refined(face_point + f0, w.face);
            st.add_refined(face_point + f1, w.face);
        }
        st.end_row();
    }
    add_quads(t, nv, nf, step);
    step.creases.holes = child_holes(mesh.creases.holes, [&](int f) { return mesh.face_start[f]; });
    return step;
}

std::vector<std::array<int, 2>> add_quad_split(const PolyMesh& mesh, RefinementStep& step) {
    const GeneralTopology t = complete_topology(mesh, false);
    add_quads(t, mesh.num_vertices(), mesh.num_faces(), step);
    return edge_ends(t);
}

std::vector<std::array<int, 2>> add_triangle_split(const PolyMesh& mesh, RefinementStep& step) {
    const GeneralTopology t = complete_topology(mesh, false);
    add_triangles(t, mesh.num_vertices(), step);
    return edge_ends(t);
}

std::vector<std::array<int, 2>> nonmanifold_edges(const PolyMesh& mesh) {
    const GeneralTopology t = complete_topology(mesh, false);
    return edge_ends(t);
}

namespace {

/// Far's walk around vertex v (Vtr::internal::Level::orderVertexFacesAndEdges) on a base level:
/// whether it succeeds. Far enters a face at the vertex's (or the edge's) first corner in it,
/// whichever it came in by (findInArray).
bool far_walk_succeeds(const GeneralTopology& t, int v) {
    const PolyMesh& mesh = *t.mesh;
    const int faces = t.vertex_corner_start[v + 1] - t.vertex_corner_start[v];
    const int edges = t.vertex_edge_start[v + 1] - t.vertex_edge_start[v];
    if (faces == 0 || edges < 2 || edges - faces > 1) return false;
    auto first_corner = [&](int f, auto&& is_it) {
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c)
            if (is_it(c)) return c;
        return -1;
    };
    auto at_vertex = [&](int f) { return first_corner(f, [&](int c) { return t.vertex(c) == v; }); };
    auto edge_faces = [&](int e) { return t.edge_corner_start[e + 1] - t.edge_corner_start[e]; };
    auto edge_face = [&](int e, int k) {
        return t.corner_face[static_cast<size_t>(t.edge_corners[static_cast<size_t>(t.edge_corner_start[e] + k)])];
    };
    int face = -1, edge = -1, corner = -1;
    if (edges == faces) {  // interior: from the first face
        face = t.corner_face[static_cast<size_t>(t.vertex_corners[static_cast<size_t>(t.vertex_corner_start[v])])];
        corner = at_vertex(face);
        edge = t.corner_edge[static_cast<size_t>(corner)];
    } else {  // boundary: from the last edge with one face, unless one leaves v along its face
        for (int k = t.vertex_edge_start[v]; k < t.vertex_edge_start[v + 1]; ++k) {
            const int e = t.vertex_edges[static_cast<size_t>(k)];
            if (edge_faces(e) != 1) continue;
            edge = e;
            face = edge_face(e, 0);
            corner = at_vertex(face);
            if (t.corner_edge[static_cast<size_t>(corner)] == edge) break;
        }
        if (face < 0) return false;  // Far reads past its arrays here; take it as a failure
    }
    const int first_edge = edge;
    for (int edges_ordered = 1, faces_ordered = 1; edges_ordered < edges; ++edges_ordered) {
        const int next = t.corner_edge[static_cast<size_t>(t.prev(corner))];
        if (next == edge || next == first_edge) return false;
        if (faces_ordered < faces) {
            const int n = edge_faces(next);
            if (n == 0 || (n == 1 && edge_face(next, 0) == face)) return false;
            face = edge_face(next, edge_face(next, 0) == face ? 1 : 0);
            corner = first_corner(face, [&](int c) { return t.corner_edge[static_cast<size_t>(c)] == next; });
            ++faces_ordered;
        }
        edge = next;
    }
    return true;
}

}  // namespace

std::vector<int> opensubdiv_walk_accepted_vertices(const PolyMesh& mesh) {
    if (!mesh.derived.empty()) return {};  // Far walks its base level only
    const GeneralTopology t = complete_topology(mesh, false);
    std::vector<char> on_nonmanifold_edge(static_cast<size_t>(mesh.num_vertices()), 0);
    for (int e = 0; e < t.num_edges(); ++e)
        if (t.edge_nonmanifold[static_cast<size_t>(e)]) {
            const int c = t.edge_first[static_cast<size_t>(e)];
            on_nonmanifold_edge[static_cast<size_t>(t.vertex(c))] = 1;
            on_nonmanifold_edge[static_cast<size_t>(t.vertex(t.next(c)))] = 1;
        }
    std::vector<int> out;
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (t.nonmanifold_vertex[static_cast<size_t>(v)] && !on_nonmanifold_edge[static_cast<size_t>(v)] &&
            far_walk_succeeds(t, v))
            out.push_back(v);
    return out;
}

std::vector<int> nonmanifold_vertices(const PolyMesh& mesh) {
    const GeneralTopology t = complete_topology(mesh, false);
    std::vector<int> out;
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (t.nonmanifold_vertex[static_cast<size_t>(v)]) out.push_back(v);
    return out;
}

PolyMesh loop_subdivide_nonmanifold(const PolyMesh& mesh, const LoopOptions& options, int levels) {
    return detail::apply_levels(mesh, levels, [&](const PolyMesh& m, int) { return loop_nonmanifold_step(m, options); });
}

PolyMesh catmull_clark_subdivide_nonmanifold(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels) {
    return detail::apply_levels(mesh, levels,
                                [&](const PolyMesh& m, int) { return catmull_clark_nonmanifold_step(m, options); });
}

}  // namespace crossdiv
