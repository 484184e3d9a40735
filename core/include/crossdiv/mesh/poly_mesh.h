#pragma once
/// @file
/// A polygon mesh exactly as read: vertex order and face order and each face's corner
/// order are those of the file. Schemes that need triangles convert it with to_tri_mesh(),
/// which refuses (does not triangulate) a polygon that is not a triangle.

#include <Eigen/Core>
#include <vector>

#include "crossdiv/mesh/crease_tags.h"
#include "crossdiv/mesh/face_varying.h"
#include "crossdiv/mesh/source.h"

namespace crossdiv {

using Vec3 = Eigen::Vector3d;

/// A refined level's topology where its faces alone do not tell it: OpenSubdiv derives each
/// level's edges and tags from its parent (Vtr::internal::Refinement), not from the level's
/// face-vertices. Only the non-manifold refinement (subdiv/nonmanifold.h) makes and reads it;
/// a mesh renumbered or rewritten in any way forgets it (it is then a base level again).
struct DerivedTopology {
    /// The edge each corner's half-edge lies on (corner c: the one leaving face_vertices[c]
    /// along its face), so that edges not told apart by their end vertices (the children of a
    /// duplicate face, of a face that names a vertex twice) stay apart; any label values,
    /// equal labels meaning one edge. Empty: the mesh is a base level.
    std::vector<int> corner_edges;
    /// Per edge label (the largest label + 1 entries): the edge is a child of a non-manifold
    /// edge, and non-manifold like it (Far's ETag::_nonManifold, inherited), whether or not
    /// the level's faces still show it (a face naming its edge twice has children that two
    /// faces share the manifold way).
    std::vector<char> nonmanifold_edges;
    /// Per vertex: infinitely sharp, as the base level made a non-manifold vertex or (under
    /// the edge-and-corner rule) a topological corner, inherited by its child vertex (Far's
    /// vertex sharpness: SHARPNESS_INFINITE decays to itself) even where the child's faces
    /// look like a manifold's.
    std::vector<char> sharp_vertices;

    bool empty() const { return corner_edges.empty(); }
};

/// Indexed polygon mesh in compressed-row form: face f has the corners
/// face_vertices[face_start[f] .. face_start[f+1]).
struct PolyMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> colors;           ///< empty, or one RGB per vertex
    std::vector<int> face_start{0};     ///< size num_faces()+1, face_start[0] == 0
    std::vector<int> face_vertices;
    /// Crease and corner sharpness (Loop and Catmull-Clark honour them; the schemes without
    /// crease rules refuse a tagged mesh rather than drop the tags).
    CreaseTags creases;
    /// Empty, or what a refined level inherits from its parent beyond its faces (the
    /// non-manifold refinement's levels).
    DerivedTopology derived;
    /// Face-varying channels (texture coordinates): values per face corner, with their own
    /// indexing (face_varying.h). Refinements that do not refine them drop them.
    std::vector<FaceVaryingChannel> face_varying;
    MeshSource source;

    int num_vertices() const { return static_cast<int>(positions.size()); }
    int num_faces() const { return static_cast<int>(face_start.size()) - 1; }
    int face_size(int f) const { return face_start[f + 1] - face_start[f]; }
    const int* face(int f) const { return face_vertices.data() + face_start[f]; }
    /// Whether every face is a triangle (the input of Loop, sqrt3 and the Butterflies).
    bool all_triangles() const {
        for (int f = 0; f < num_faces(); ++f)
            if (face_size(f) != 3) return false;
        return true;
    }

    /// Appends a face given by its corner vertex indices.
    template <class Range>
    void add_face(const Range& corners) {
        for (int v : corners) face_vertices.push_back(v);
        face_start.push_back(static_cast<int>(face_vertices.size()));
    }
    void add_face(std::initializer_list<int> corners) { add_face<std::initializer_list<int>>(corners); }
};

}  // namespace crossdiv
