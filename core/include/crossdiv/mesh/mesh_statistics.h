#pragma once
/// @file
/// What a mesh is made of, counted as Thingi10K's statistics count a corpus (Zhou and Jacobson
/// 2016): elements, face sizes, components, boundaries, the non-manifold and isolated elements,
/// and the genus where it is defined. For any polygon soup whose indices are in range: nothing
/// here refuses a mesh (mesh_checks.h names the problems; this counts them).

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

struct MeshStatistics {
    int vertices = 0, faces = 0;
    int edges = 0;                  ///< distinct vertex pairs joined by a face side
    int triangles = 0, quads = 0, larger_faces = 0;
    int degenerate_faces = 0;       ///< fewer than 3 corners, or a vertex named twice
    int isolated_vertices = 0;      ///< no face uses them
    int boundary_edges = 0;         ///< one face side
    int non_manifold_edges = 0;     ///< three or more face sides
    int inconsistent_edges = 0;     ///< two face sides in the same direction
    int non_manifold_vertices = 0;  ///< faces around them in more than one fan (edge-connected group)
    int components = 0;             ///< groups of faces connected through shared vertices
    /// Euler characteristic V - E + F over the vertices faces use.
    int euler_characteristic = 0;
    /// Sum over components of (2 - chi - boundary loops) / 2, where every edge and vertex is
    /// manifold and every face is proper (else -1: a genus is not defined).
    int genus = -1;
    int boundary_loops = 0;         ///< closed loops of boundary edges, where they are manifold
};

/// The statistics of `mesh`, in O(corners log corners) with flat arrays.
/// @throws InputError for a face index out of range (naming the face).
MeshStatistics mesh_statistics(const PolyMesh& mesh);

}  // namespace crossdiv
