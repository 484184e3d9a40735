#pragma once
/// @file
/// Topology facts of any polygon mesh that the comparisons report: edges, Euler
/// characteristic, boundary loops, and each vertex's valence and boundary flag.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

struct MeshTopology {
    int vertices = 0, edges = 0, faces = 0;
    int euler = 0;           ///< V - E + F
    int boundary_edges = 0;  ///< edges with exactly one face
    int boundary_loops = 0;  ///< connected components of the boundary edges
    std::vector<int> valence;           ///< distinct edge neighbours per vertex
    std::vector<char> boundary_vertex;  ///< 1 when the vertex touches a boundary edge
    std::vector<std::array<int, 2>> edge_list;  ///< sorted endpoint pairs, sorted
};

/// Computes the topology by a counting sort of the edges (no maps), in time linear in the corners.
/// @throws std::invalid_argument naming the face when a face names a vertex the mesh lacks.
MeshTopology mesh_topology(const PolyMesh& mesh);

/// Where a face's canonical listing starts: its lexicographically least rotation, orientation
/// kept, so the same oriented face listed from any corner has one key (also when it names its
/// least vertex twice). Linear unless the least vertex repeats.
size_t least_rotation(std::span<const int> cycle);

}  // namespace crossdiv::verification
