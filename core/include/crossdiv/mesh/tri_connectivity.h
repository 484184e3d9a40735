#pragma once
/// @file
/// The seed's index-based connectivity (CS-C3100 assignment 2, section 4.2), plus the
/// edge numbering and one-ring entry points a refinement needs. Flat arrays only.
///
/// Conventions (the seed's): edge j of triangle i runs from corner j to corner (j+1)%3;
/// neighbor_tris[i][j] is the triangle across that edge and neighbor_edges[i][j] the index of
/// the same edge inside it, both -1 on a boundary. A *corner* c = 3*i + j names vertex j of
/// triangle i and, equally, the directed edge (half-edge) j of triangle i leaving it.

#include <array>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

/// Connectivity of a manifold, consistently oriented triangle mesh.
struct TriConnectivity {
    std::vector<std::array<int, 3>> neighbor_tris;   ///< seed's table; -1 on a boundary
    std::vector<std::array<int, 3>> neighbor_edges;  ///< seed's table; -1 on a boundary
    std::vector<std::array<int, 3>> tri_edges;       ///< edge id of edge j of triangle i
    /// One corner of each edge; for a boundary edge its only corner. Edges are numbered in
    /// the order their first corner appears when scanning triangles, then corners.
    std::vector<int> edge_corner;
    /// Endpoints of each edge, in the direction of edge_corner (from its corner's vertex).
    std::vector<std::array<int, 2>> edge_vertices;
    /// Where the one-ring walk of each vertex starts: for a boundary vertex the corner whose
    /// incoming edge is on the boundary, for an interior vertex any corner, -1 if isolated.
    std::vector<int> vertex_corner;

    int num_edges() const { return static_cast<int>(edge_corner.size()); }
    bool is_boundary_edge(int e) const {
        const int c = edge_corner[e];
        return neighbor_tris[c / 3][c % 3] < 0;
    }
    /// True for a vertex on the boundary (false for isolated vertices).
    bool is_boundary_vertex(int v) const {
        const int c = vertex_corner[v];
        return c >= 0 && neighbor_tris[c / 3][(c % 3 + 2) % 3] < 0;
    }

    /// Next corner at the same vertex, across the outgoing edge of `c`; -1 at a boundary.
    /// Starting at vertex_corner[v] and stepping until -1 or back at the start visits every
    /// triangle around v exactly once (the seed's "single loop" one-ring walk).
    int next_around_vertex(int c) const {
        const int i = c / 3, j = c % 3;
        const int nt = neighbor_tris[i][j];
        return nt < 0 ? -1 : 3 * nt + (neighbor_edges[i][j] + 1) % 3;
    }
};

/// Builds the connectivity tables with flat arrays (no edge map) in O(corners), whatever the
/// valences (detail::find_twins).
/// @throws InputError naming the element when the mesh is not a manifold, consistently
///         oriented triangle mesh with valid indices: index out of range, repeated vertex in a
///         triangle, edge shared by more than two triangles, two triangles that disagree on
///         orientation, non-manifold (bowtie) vertex. Isolated vertices are allowed.
TriConnectivity build_tri_connectivity(const TriMesh& mesh);

}  // namespace crossdiv
