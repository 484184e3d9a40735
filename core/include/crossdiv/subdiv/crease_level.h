#pragma once
/// @file
/// The sharpness of one level of a crease-tagged mesh and the rules it selects, for the
/// traversals of Loop and Catmull-Clark (the rules themselves are crease_mask.h). Built from
/// the mesh's CreaseTags and its connectivity as OpenSubdiv's Vtr builds its levels: boundary
/// edges are infinitely sharp, and so is a boundary vertex with one face under the
/// edge-and-corner rule; every vertex's rule at this level and the next is known before any
/// point is computed, and the refined mesh's tags are the decayed halves of the sharp edges.

#include <vector>

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/crease_mask.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// Calls f(edge, other_end) for each edge around vertex v in the crease order every mask of
/// this file indexes by: the outgoing edge of each corner of v's one-ring walk, then, on a
/// boundary, the incoming boundary edge.
template <class F>
void for_each_edge_around(const PolyConnectivity& conn, int v, F f) {
    const int start = conn.vertex_corner[v];
    if (start < 0) return;
    for (int c = start;;) {
        f(conn.corner_edge[c], conn.head(c));
        c = conn.next_around_vertex(c);
        if (c < 0 || c == start) break;
    }
    if (conn.is_boundary_vertex(v)) {
        const int in = conn.prev[start];
        f(conn.corner_edge[in], conn.corner_vertex[in]);
    }
}

class CreaseLevel {
public:
    /// @param sharpen_corners the edge-and-corner boundary rule (a boundary vertex with one
    ///        face is an infinitely sharp corner).
    /// @throws InputError naming the tag (and its file line) for a crease whose two vertices
    ///         share no edge, a vertex index out of range, or a sharpness that is negative or
    ///         not finite.
    /// @param rules whose semi-sharp rules: the decay of Chaikin's creasing and the rule change
    ///        of a vertex whose features decay (Far's, or Hbr's: crease_tags.h).
    CreaseLevel(const PolyMesh& mesh, const PolyConnectivity& conn, CreaseMethod method, bool sharpen_corners,
                CreaseRules rules = CreaseRules::OpenSubdiv);

    /// The rules of a vertex at this level and the next, and how to blend them.
    struct Vertex {
        VertexRule parent = VertexRule::Smooth, child = VertexRule::Smooth;
        int parent_ends[2] = {-1, -1};  ///< its two sharp edges under Crease (for_each_edge_around indices)
        int child_ends[2] = {-1, -1};   ///< the same for the child rule
        int edges = 0;                  ///< incident edges
        float weight = 0.0f;            ///< transition_weight, when the rules differ
    };
    const Vertex& vertex(int v) const { return vertices_[static_cast<size_t>(v)]; }

    /// Sharpness of edge e at this level (infinite on the boundary).
    float edge_sharpness(int e) const { return edge_[static_cast<size_t>(e)]; }
    /// Sharpness of vertex v at this level as tagged (a corner sharpened by the edge-and-corner
    /// rule not included).
    float vertex_tag(int v) const { return vertex_tag_[static_cast<size_t>(v)]; }
    /// Sharpness of the next level's half of edge e that ends at vertex v (an end of e).
    float child_half_sharpness(int e, int v) const {
        return half_[2 * static_cast<size_t>(e) + (conn_.edge_vertices[e][0] == v ? 0 : 1)];
    }
    /// Whether the new point on edge e takes the crease rule (the edge's midpoint) whole: when
    /// both halves stay sharp in the next level (Far), or when the edge's sharpness is at least
    /// 1 (Hbr's rules: below 1 it blends by the sharpness, HbrCatmarkSubdivision::Subdivide).
    bool edge_child_is_crease(int e) const {
        if (rules_ == CreaseRules::Hbr) return edge_[static_cast<size_t>(e)] >= 1.0f;
        return is_sharp(half_[2 * static_cast<size_t>(e)]) && is_sharp(half_[2 * static_cast<size_t>(e) + 1]);
    }

    /// The tags of the refined mesh, whose point on edge e is vertex `first_edge_point + e`:
    /// the halves of every sharp interior edge that stay sharp, and the decayed vertex tags.
    CreaseTags child_tags(int first_edge_point) const;

private:
    const PolyConnectivity& conn_;
    CreaseMethod method_;
    CreaseRules rules_;
    std::vector<float> edge_;        ///< per edge
    std::vector<float> half_;        ///< child sharpness of edge e's half at edge_vertices[e][k]: 2e + k
    std::vector<float> vertex_tag_;  ///< per vertex, as tagged (not sharpened)
    std::vector<Vertex> vertices_;
};

/// The vertex-point mask of a vertex with rules `r` (OpenSubdiv's ComputeVertexVertexMask):
/// the parent rule's mask, blended with the child rule's when they differ. `set_smooth(m)`
/// writes the scheme's smooth mask (used for Smooth and Dart, which occur at interior
/// vertices only, where edges and faces are equally many); `child` is scratch space.
template <class SetSmooth>
void vertex_point_mask(const CreaseLevel::Vertex& r, VertexPointMask& mask, VertexPointMask& child,
                       const SetSmooth& set_smooth) {
    auto assign = [&](VertexPointMask& m, VertexRule rule, const int ends[2]) {
        if (rule == VertexRule::Crease) m.set_crease(r.edges, ends[0], ends[1]);
        else if (rule == VertexRule::Corner) m.set_corner();
        else set_smooth(m);
    };
    assign(mask, r.parent, r.parent_ends);
    if (r.child != r.parent) {
        assign(child, r.child, r.child_ends);
        blend_vertex_masks(mask, child, r.weight);
    }
}

/// Appends vertex-point mask `m` of vertex v to the row being built, in OpenSubdiv's order
/// (face points, the other ends of the edges, the vertex), leaving out zero weights. Face k
/// is the k-th face of v's one-ring walk; its new point is refined row `face_point + face`.
void add_vertex_point_mask(StencilTable& st, const PolyConnectivity& conn, int v, const VertexPointMask& m,
                           int face_point);

}  // namespace crossdiv
