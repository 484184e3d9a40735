#pragma once
/// @file
/// Connectivity of a manifold polygon mesh, for the schemes that refine any polygon
/// (Catmull-Clark, Doo-Sabin) and for the triangle schemes that need more than TriConnectivity
/// gives (sqrt3, the Butterflies). Flat arrays over *corners*: corner c is entry c of
/// PolyMesh::face_vertices, the vertex it names, and equally the directed edge (half-edge)
/// leaving that vertex along its face.

#include <array>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// Connectivity of a manifold, consistently oriented polygon mesh (the TriConnectivity of
/// any polygon; same conventions: edges numbered at their first corner in scan order, the
/// one-ring walk of a boundary vertex starts where the boundary comes in).
struct PolyConnectivity {
    std::vector<int> corner_vertex;  ///< vertex of each corner (a copy of face_vertices)
    std::vector<int> corner_face;    ///< face of each corner
    std::vector<int> next;           ///< next corner of the same face
    std::vector<int> prev;           ///< previous corner of the same face
    std::vector<int> twin;           ///< corner of the opposite half-edge (it leaves next's vertex); -1 on a boundary
    std::vector<int> corner_edge;    ///< edge of the half-edge leaving each corner
    std::vector<int> edge_corner;    ///< one corner of each edge (the boundary edge's only one)
    std::vector<std::array<int, 2>> edge_vertices;  ///< endpoints, from edge_corner's vertex
    /// Start of each vertex's one-ring walk: on a boundary the corner whose incoming
    /// half-edge is on the boundary, inside any corner, -1 for an isolated vertex.
    std::vector<int> vertex_corner;

    int num_edges() const { return static_cast<int>(edge_corner.size()); }
    int num_corners() const { return static_cast<int>(corner_vertex.size()); }
    bool is_boundary_edge(int e) const { return twin[edge_corner[e]] < 0; }
    /// True for a vertex on the boundary (false for isolated vertices).
    bool is_boundary_vertex(int v) const {
        const int c = vertex_corner[v];
        return c >= 0 && twin[prev[c]] < 0;
    }
    /// The vertex the half-edge of corner c points to.
    int head(int c) const { return corner_vertex[next[c]]; }
    /// Next corner at the same vertex, across the outgoing half-edge of c; -1 at a boundary.
    /// From vertex_corner[v] until -1 or back at the start it visits every face around v once.
    int next_around_vertex(int c) const { return twin[c] < 0 ? -1 : next[twin[c]]; }

    /// The faces around a vertex: how many, and the walk's last corner (on a boundary, the
    /// corner whose outgoing half-edge is on the boundary). {0, -1} for an isolated vertex.
    struct Fan {
        int faces, last;
    };
    Fan fan(int v) const {
        Fan f{0, -1};
        const int start = vertex_corner[v];
        for (int c = start; c >= 0;) {
            ++f.faces;
            f.last = c;
            c = next_around_vertex(c);
            if (c == start) break;
        }
        return f;
    }

    /// The two boundary neighbours of boundary vertex v, in the faces' orientation: the
    /// boundary comes in from `before` (before -> v is a boundary half-edge) and goes on to
    /// `after`. `f` is fan(v), for callers that have it already.
    struct BoundaryNeighbors {
        int before, after;
    };
    BoundaryNeighbors boundary_neighbors(int v, const Fan& f) const {
        return {corner_vertex[prev[vertex_corner[v]]], head(f.last)};
    }
    BoundaryNeighbors boundary_neighbors(int v) const { return boundary_neighbors(v, fan(v)); }
};

/// Builds the tables with flat arrays (no edge map) in O(corners), whatever the valences
/// (detail::find_twins).
/// @throws InputError naming the element when the mesh is not a manifold, consistently
///         oriented polygon mesh with valid indices: a face with fewer than 3 corners, an
///         index out of range, a repeated vertex in a face, an edge shared by more than two
///         faces, two faces that disagree on orientation, a non-manifold (bowtie) vertex, or
///         a non-finite coordinate. Isolated vertices are allowed.
PolyConnectivity build_poly_connectivity(const PolyMesh& mesh);

}  // namespace crossdiv
