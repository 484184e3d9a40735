#pragma once
/// @file
/// A half-edge mesh of triangles: connectivity only, with typed index handles (pmp-library's
/// surface_mesh.h, geometry-central's ManifoldSurfaceMesh); positions live beside it in a
/// plain std::vector<Vec3> indexed by VertexId. Local operations (flip, split) are members;
/// they create elements only at the end of each array and delete nothing, so every handle
/// stays valid and a TriMesh made from it keeps the input's vertex and face order.
///
/// Layout: edge e owns the half-edges 2e and 2e+1 (twin(h) = h ^ 1). Each half-edge knows its
/// origin, next, prev and face. Boundary half-edges have no face; they belong to a *boundary
/// loop* (the meshedit primer's virtual boundary face) and their next/prev run around it, so
/// every half-edge lies on a closed next-cycle.

#include <compare>
#include <string_view>
#include <vector>

#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

/// An index into one of the mesh's element arrays; -1 is "none". The tag keeps a vertex
/// index from being passed where a face index is expected.
template <class Tag>
struct Handle {
    int idx = -1;
    constexpr Handle() = default;
    constexpr explicit Handle(int i) : idx(i) {}
    constexpr bool valid() const { return idx >= 0; }
    friend constexpr auto operator<=>(Handle, Handle) = default;
};
using VertexId = Handle<struct VertexTag>;
using HalfedgeId = Handle<struct HalfedgeTag>;
using EdgeId = Handle<struct EdgeTag>;
using FaceId = Handle<struct FaceTag>;

/// Why flip() left the mesh unchanged.
enum class FlipRefusal {
    None,                      ///< the edge was flipped
    BoundaryEdge,              ///< only one face: there is no quad to re-triangulate
    OppositeVerticesCoincide,  ///< both faces have the same third vertex (a doubled triangle)
    EdgeExists,                ///< the flipped edge already joins the two opposite vertices
};
/// One sentence naming the reason ("boundary edge", ...).
std::string_view to_string(FlipRefusal r);

/// Connectivity of a triangle mesh with boundary, as half-edges.
class HalfedgeMesh {
public:
    /// Builds the half-edges of a manifold, consistently oriented triangle mesh. Edge e is
    /// TriConnectivity's edge e (2e runs along its edge_corner), face f is triangle f, and
    /// each vertex's half-edge is the one of its TriConnectivity::vertex_corner, so one-ring
    /// walks visit neighbours in the order the index-based Loop driver does.
    /// @throws InputError naming the element when build_tri_connectivity refuses the mesh.
    static HalfedgeMesh from_triangles(const TriMesh& mesh);
    /// As from_triangles, on connectivity already built for `mesh`.
    static HalfedgeMesh from_connectivity(const TriMesh& mesh, const TriConnectivity& conn);

    /// The faces as vertex triples in face order, each starting at the origin of the face's
    /// half-edge (an unchanged face keeps its input corner order).
    std::vector<Triangle> triangles() const;

    int num_vertices() const { return static_cast<int>(vertex_he_.size()); }
    int num_halfedges() const { return static_cast<int>(origin_.size()); }
    int num_edges() const { return num_halfedges() / 2; }
    int num_faces() const { return static_cast<int>(face_he_.size()); }
    int num_boundary_loops() const { return static_cast<int>(loop_he_.size()); }

    // --- navigation (no checks: the validity checker reads through these too) ---------------
    static HalfedgeId twin(HalfedgeId h) { return HalfedgeId(h.idx ^ 1); }
    static EdgeId edge(HalfedgeId h) { return EdgeId(h.idx >> 1); }
    static HalfedgeId halfedge(EdgeId e, int side = 0) { return HalfedgeId(2 * e.idx + side); }
    HalfedgeId next(HalfedgeId h) const { return HalfedgeId(next_[h.idx]); }
    HalfedgeId prev(HalfedgeId h) const { return HalfedgeId(prev_[h.idx]); }
    VertexId origin(HalfedgeId h) const { return VertexId(origin_[h.idx]); }
    /// The vertex h points to: origin(twin(h)).
    VertexId target(HalfedgeId h) const { return origin(twin(h)); }
    /// The face left of h, or invalid for a boundary half-edge.
    FaceId face(HalfedgeId h) const { return FaceId(face_[h.idx] >= 0 ? face_[h.idx] : -1); }
    bool is_boundary(HalfedgeId h) const { return face_[h.idx] < 0; }
    /// The boundary loop of a boundary half-edge (-1 for an interior one).
    int boundary_loop(HalfedgeId h) const { return face_[h.idx] < 0 ? -1 - face_[h.idx] : -1; }
    bool is_boundary(EdgeId e) const { return is_boundary(halfedge(e, 0)) || is_boundary(halfedge(e, 1)); }
    /// A half-edge leaving v, or invalid for an isolated vertex.
    HalfedgeId halfedge(VertexId v) const { return HalfedgeId(vertex_he_[v.idx]); }
    HalfedgeId halfedge(FaceId f) const { return HalfedgeId(face_he_[f.idx]); }
    /// One half-edge of each boundary loop.
    HalfedgeId loop_halfedge(int loop) const { return HalfedgeId(loop_he_[loop]); }
    /// The next half-edge leaving origin(h), counterclockwise: next(twin(h)).
    HalfedgeId next_around_origin(HalfedgeId h) const { return next(twin(h)); }

    /// The half-edge from a to b, or invalid when no edge joins them. O(valence of a).
    HalfedgeId find_halfedge(VertexId a, VertexId b) const;
    /// Number of edges at v (its valence); 0 for an isolated vertex.
    int valence(VertexId v) const;
    bool is_boundary(VertexId v) const;

    // --- local operations -------------------------------------------------------------------
    /// Replaces edge e, the diagonal of the quad its two faces form, by the other diagonal.
    /// Creates and deletes nothing; e, its half-edges and the two faces are reused. Time is
    /// constant apart from the EdgeExists test, which walks one vertex's ring.
    /// @return FlipRefusal::None on success; otherwise the reason, with the mesh unchanged.
    FlipRefusal flip(EdgeId e);

    /// Splits edge e at a new vertex: an interior edge's 2 faces become 4, a boundary edge's
    /// face becomes 2. Creates exactly one vertex (index num_vertices()), one edge per face
    /// around e plus one for the second half of e, and one face per face around e; e keeps
    /// the half that starts at the origin of its half-edge 2e. The new edges are numbered
    /// in this order: the other half of e, then the edge from the new vertex to the third
    /// vertex of the face of half-edge 2e (if any), then that of 2e+1 (if any); the new
    /// faces follow the same side order. Constant time.
    /// @return the new vertex.
    VertexId split(EdgeId e);

    // --- low-level access for tools and tests that repair or break a mesh on purpose --------
    void set_vertex_halfedge(VertexId v, HalfedgeId h) { vertex_he_[v.idx] = h.idx; }

private:
    void link(int h, int next) {
        next_[h] = next;
        prev_[next] = h;
    }
    int new_edge(int origin_a, int origin_b);

    std::vector<int> next_, prev_, origin_, face_;  ///< per half-edge; face_ < 0: -1 - loop
    std::vector<int> vertex_he_;                    ///< per vertex, -1 if isolated
    std::vector<int> face_he_;                      ///< per face
    std::vector<int> loop_he_;                      ///< per boundary loop
};

/// The midpoint split: splits e and appends the midpoint of its endpoints to `positions`
/// (one entry per vertex before the call). @return the new vertex.
VertexId split_at_midpoint(HalfedgeMesh& mesh, std::vector<Vec3>& positions, EdgeId e);

/// A TriMesh of the half-edge mesh's faces with these positions (one per vertex).
TriMesh to_tri_mesh(const HalfedgeMesh& mesh, const std::vector<Vec3>& positions);

}  // namespace crossdiv
