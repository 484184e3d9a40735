#pragma once
/// @file
/// The fans of faces around each vertex, and a mesh with one vertex per fan: what a library
/// that stores a manifold half-edge structure makes of a non-manifold vertex (a bowtie) when
/// it does not refuse it (OpenSubdiv's Hbr splits such a vertex in HbrMesh::Finish).

#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// `mesh` with every vertex whose faces form more than one fan split into one vertex per fan.
/// Two faces at a vertex are in one fan when a chain of edges, each with exactly two faces
/// running it in opposite directions, joins them around the vertex; any other edge (a
/// boundary, an edge of three faces, two faces running it the same way) separates fans.
/// The first fan, in corner order, keeps the vertex's number; each further fan gets a new
/// vertex appended at the same position, in the order the fans are met. Face order, corner
/// order and face-varying channels are kept; crease tags keep naming the first copy.
/// O(corners log corners). `original`, when given, receives each vertex's vertex in `mesh`.
PolyMesh split_vertex_fans(const PolyMesh& mesh, std::vector<int>* original = nullptr);

}  // namespace crossdiv
