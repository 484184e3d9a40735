#include "crossdiv/subdiv/crease_level.h"

#include <cmath>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {
namespace {

/// "crease tag (3, 9) (cube.obj:40)" / "corner tag 5".
std::string describe_tag(const PolyMesh& mesh, const std::string& what, const std::vector<int>& lines, size_t k) {
    std::string s = what;
    if (k < lines.size()) s += " (" + mesh.source.file + ":" + std::to_string(lines[k]) + ")";
    return s;
}

void check_sharpness(float s, const std::string& tag) {
    if (!std::isfinite(s) || s < 0.0f)
        throw InputError(tag + ": sharpness " + std::to_string(s) + " is not a finite number >= 0");
}

}  // namespace

CreaseLevel::CreaseLevel(const PolyMesh& mesh, const PolyConnectivity& conn, CreaseMethod method, bool sharpen_corners,
                         CreaseRules rules)
    : conn_(conn), method_(method), rules_(rules) {
    const int nv = mesh.num_vertices(), ne = conn.num_edges();
    const CreaseTags& tags = mesh.creases;
    edge_.assign(static_cast<size_t>(ne), 0.0f);
    for (size_t k = 0; k < tags.edges.size(); ++k) {
        const SharpEdge& t = tags.edges[k];
        const std::string name = describe_tag(
            mesh, "crease tag (" + std::to_string(t.a) + ", " + std::to_string(t.b) + ")", tags.edge_line, k);
        check_sharpness(t.sharpness, name);
        if (t.a < 0 || t.a >= nv || t.b < 0 || t.b >= nv)
            throw InputError(name + ": vertex index out of range (the mesh has " + std::to_string(nv) + " vertices)");
        int edge = -1;
        for_each_edge_around(conn, t.a, [&](int e, int other) {
            if (other == t.b) edge = e;
        });
        if (edge < 0)
            throw InputError(name + ": vertices " + std::to_string(t.a) + " and " + std::to_string(t.b) +
                             " share no edge");
        edge_[static_cast<size_t>(edge)] = t.sharpness;  // a later tag replaces an earlier one
    }
    for (int e = 0; e < ne; ++e)
        if (conn.is_boundary_edge(e)) edge_[static_cast<size_t>(e)] = kSharpnessInfinite;

    vertex_tag_.assign(static_cast<size_t>(nv), 0.0f);
    for (size_t k = 0; k < tags.vertices.size(); ++k) {
        const SharpVertex& t = tags.vertices[k];
        const std::string name = describe_tag(mesh, "corner tag " + std::to_string(t.v), tags.vertex_line, k);
        check_sharpness(t.sharpness, name);
        if (t.v < 0 || t.v >= nv)
            throw InputError(name + ": vertex index out of range (the mesh has " + std::to_string(nv) + " vertices)");
        vertex_tag_[static_cast<size_t>(t.v)] = t.sharpness;
    }

    // Child sharpness of every edge half, and both rules of every vertex, from the sharpness
    // of the edges around it (gathered into buffers reused from vertex to vertex).
    half_.assign(2 * static_cast<size_t>(ne), 0.0f);
    vertices_.assign(static_cast<size_t>(nv), Vertex{});
    std::vector<float> around, child_around, rule_around;
    std::vector<int> edges;
    for (int v = 0; v < nv; ++v) {
        around.clear();
        edges.clear();
        for_each_edge_around(conn, v, [&](int e, int) {
            edges.push_back(e);
            around.push_back(edge_[static_cast<size_t>(e)]);
        });
        if (edges.empty()) continue;  // isolated
        child_around.resize(around.size());
        for (size_t i = 0; i < edges.size(); ++i) {
            const int e = edges[i];
            child_around[i] = rules == CreaseRules::OpenSubdiv ? child_edge_sharpness(method, around[i], around)
                                                               : hbr_child_edge_sharpness(method, around[i], around, i);
            half_[2 * static_cast<size_t>(e) + (conn.edge_vertices[e][0] == v ? 0 : 1)] = child_around[i];
        }
        float sharpness = vertex_tag_[static_cast<size_t>(v)];
        // A boundary vertex with one face has two edges (the walk above counted them).
        if (sharpen_corners && conn.is_boundary_vertex(v) && edges.size() == 2) sharpness = kSharpnessInfinite;
        const float child_sharpness = decrement_sharpness(sharpness);

        Vertex& out = vertices_[static_cast<size_t>(v)];
        out.edges = static_cast<int>(edges.size());
        auto classify = [&](const std::vector<float>& s, float vs, int ends[2]) {
            int count = 0;
            for (size_t i = 0; i < s.size(); ++i)
                if (is_sharp(s[i])) {
                    if (count < 2) ends[count] = static_cast<int>(i);
                    ++count;
                }
            return vertex_rule(vs, count);
        };
        out.parent = classify(around, sharpness, out.parent_ends);
        if (rules == CreaseRules::OpenSubdiv) {
            out.child = classify(child_around, child_sharpness, out.child_ends);
            if (out.parent != out.child) out.weight = transition_weight(sharpness, child_sharpness, around, child_around);
        } else {
            // Hbr's child rule reads the sharpness before the step (>= 1 is still sharp); the
            // decayed values above stay those of the next level's tags.
            rule_around.resize(around.size());
            for (size_t i = 0; i < around.size(); ++i) rule_around[i] = hbr_child_rule_sharpness(around[i]);
            out.child = classify(rule_around, hbr_child_rule_sharpness(sharpness), out.child_ends);
            if (out.parent != out.child) out.weight = hbr_transition_weight(sharpness, around);
        }
    }
}

CreaseTags CreaseLevel::child_tags(int first_edge_point) const {
    CreaseTags tags;
    tags.method = method_;
    for (int e = 0; e < conn_.num_edges(); ++e) {
        if (conn_.is_boundary_edge(e)) continue;  // sharp at every level anyway
        const float h0 = half_[2 * static_cast<size_t>(e)], h1 = half_[2 * static_cast<size_t>(e) + 1];
        const int m = first_edge_point + e;
        if (is_sharp(h0)) tags.edges.push_back({conn_.edge_vertices[e][0], m, h0});
        if (is_sharp(h1)) tags.edges.push_back({m, conn_.edge_vertices[e][1], h1});
    }
    for (size_t v = 0; v < vertex_tag_.size(); ++v)
        if (const float s = decrement_sharpness(vertex_tag_[v]); is_sharp(s)) tags.vertices.push_back({static_cast<int>(v), s});
    return tags;
}

void add_vertex_point_mask(StencilTable& st, const PolyConnectivity& conn, int v, const VertexPointMask& m,
                           int face_point) {
    if (!m.face.empty()) {
        size_t k = 0;
        for (int c = conn.vertex_corner[v];;) {
            if (m.face[k] != 0.0) st.add_refined(face_point + conn.corner_face[c], m.face[k]);
            ++k;
            c = conn.next_around_vertex(c);
            if (c < 0 || c == conn.vertex_corner[v]) break;
        }
    }
    if (m.has_edges) {
        size_t k = 0;
        for_each_edge_around(conn, v, [&](int, int other) {
            if (m.edge[k] != 0.0) st.add(other, m.edge[k]);
            ++k;
        });
    }
    st.add(v, m.vertex);
}

}  // namespace crossdiv
