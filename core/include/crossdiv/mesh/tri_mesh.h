#pragma once
/// @file
/// The indexed triangle mesh the Loop family works on: double positions, optional
/// per-vertex colors, three vertex indices per triangle (flat arrays, no per-face objects).

#include <array>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

using Triangle = std::array<int, 3>;

/// Indexed triangle mesh. Triangle corners are in the file's order; edge j of a triangle
/// runs from corner j to corner (j+1)%3 (the seed's convention).
struct TriMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> colors;  ///< empty, or one RGB per vertex
    std::vector<Triangle> triangles;
    MeshSource source;

    int num_vertices() const { return static_cast<int>(positions.size()); }
    int num_faces() const { return static_cast<int>(triangles.size()); }
};

/// Converts a polygon mesh to triangles, keeping vertex and face order.
/// @throws InputError naming the first face (and its file line) that is not a triangle;
///         `scheme` names who needs triangles ("Loop subdivision needs triangles").
TriMesh to_tri_mesh(const PolyMesh& mesh, const char* scheme = "this operation");

/// The same mesh as a polygon mesh (every face a triangle).
PolyMesh to_poly_mesh(const TriMesh& mesh);

/// Length of the diagonal of the axis-aligned bounding box (0 for an empty mesh). Scales
/// every relative tolerance in the project. Computed without overflow: inf only when the
/// diagonal itself exceeds the range of double.
double bounding_box_diagonal(const std::vector<Vec3>& positions);

}  // namespace crossdiv
