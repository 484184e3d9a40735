#pragma once
/// @file
/// CGAL 5.5 adapter: Subdivision_method_3 (Loop, Catmull-Clark, Doo-Sabin, sqrt3) on
/// Surface_mesh<Simple_cartesian<double>::Point_3>; closed-mesh checks, vertex normals,
/// jet-fitted curvatures, the Hausdorff distance, edge-collapse simplification and the Euler
/// operations flip_edge, split_edge and split_face. CGAL is included by two translation units
/// (subdivision; everything else).

#include <memory>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::cgal {

using adapters::ClosedMeshReport;  // reference.h

/// Loop_mask_3 has Loop's weights, the midpoint border edge and the 1-6-1 border vertex
/// (our EdgeOnly); it has no corner rule.
bool supports(const LoopOptions& options);

/// `levels` Loop_subdivision calls of one iteration each, so that every level can be read.
/// @throws Rejected for options it lacks, or when Surface_mesh refuses a face (non-manifold
///         or inconsistently oriented), naming the face.
LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels);

/// The same refinement in the library's own structures, with nothing converted back: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as loop().
size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels);

/// CatmullClark_subdivision, one call of one iteration per level. CatmullClark_mask_3's border
/// rule is the midpoint edge and the 1-6-1 vertex (our EdgeOnly); it has no corner rule.
/// @throws Rejected when Surface_mesh refuses a face, naming it.
LevelTrace catmull_clark(const PolyMesh& mesh, int levels);

/// The same refinement in one call of `levels` iterations, kept in CGAL's Surface_mesh: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as catmull_clark().
size_t catmull_clark_native(const PolyMesh& mesh, int levels);

/// DooSabin_subdivision, one call of one iteration per level (DooSabin_mask_3). CGAL's DQQ
/// refinement makes faces for the interior only: at a border it drops the faces of border
/// edges and vertices, which the harness classifies. @throws as catmull_clark().
LevelTrace doo_sabin(const PolyMesh& mesh, int levels);

/// Sqrt3_subdivision. CGAL refines the border only on every second step *of one call*
/// (Sqrt3_mask_3::border_node), so the trace is made of fresh calls of k = 1 .. levels
/// iterations when `one_call` is true, and of `levels` calls of one iteration (the border
/// never refined) when false. @throws as catmull_clark(), and for a non-triangle face.
LevelTrace sqrt3(const TriMesh& mesh, int levels, bool one_call);

/// Builds a Surface_mesh and asks is_valid_polygon_mesh, is_closed, and, for a closed mesh,
/// PMP::is_outward_oriented and PMP::volume. Never throws for a bad mesh: a face Surface_mesh
/// refuses is reported in `error`.
ClosedMeshReport closed_mesh_report(const TriMesh& mesh);

/// PMP::compute_vertex_normals, one per input vertex in input order. Its weighting is none of
/// the sums: it takes the "most visible" direction, the centre of the smallest cap of the unit
/// sphere holding every incident unit face normal (it maximizes the smallest dot product with
/// them), and only when that fails the sine-weighted sum of face normals.
/// @throws Rejected naming the face Surface_mesh refuses.
std::vector<Vec3> vertex_normals(const TriMesh& mesh);

/// Principal curvatures by CGAL's Monge_via_jet_fitting (Cazals and Pouget 2005): at each
/// vertex a degree-`degree` bivariate polynomial (a jet) is fitted by least squares to the
/// vertex and its `rings`-ring of neighbours in a frame from their principal component
/// analysis, and the Monge form of the jet gives the curvatures at the vertex. Returned in
/// crossdiv's convention (discrete_curvature.h): CGAL's surface z = (k1 x^2 + k2 y^2) / 2 curves
/// towards +n for positive k, so its curvatures are negated against the outward `orientation`
/// normal we pass, and k1 >= k2 after that.
struct MongeCurvatures {
    std::vector<unsigned char> fitted;  ///< 0 where the neighbourhood holds too few points for the jet
    std::vector<double> k1, k2;
    std::vector<Vec3> direction1;  ///< unit direction of k1
    std::vector<Vec3> normal;      ///< the fitted normal, turned to agree with `orientation`
    std::vector<double> condition_number;  ///< of the least-squares system (CGAL's)
};
/// @param orientation one normal per vertex that says which side is out (ours, angle weighted)
/// @throws Rejected naming the face Surface_mesh refuses, or for degree outside 1..4 or rings < 1.
MongeCurvatures monge_curvatures(const TriMesh& mesh, const std::vector<Vec3>& orientation, int rings, int degree);

/// PMP::approximate_symmetric_Hausdorff_distance: the larger of the two one-sided distances,
/// each the farthest of a sampling of one mesh (its vertices, points on its edges, and
/// `face_samples` points uniformly at random on its faces, from `seed`) from the other mesh
/// (exact point-to-mesh distances by an AABB tree). A lower bound of the true distance.
/// @throws Rejected for a mesh without triangles or one Surface_mesh refuses, naming the face.
double hausdorff_distance(const TriMesh& a, const TriMesh& b, int face_samples, unsigned seed);

/// Surface_mesh_simplification::edge_collapse with its default Lindstrom-Turk cost and
/// placement until fewer than `edges` edges remain (or no collapse keeps the mesh a valid
/// manifold of the same topology); the result renumbered densely.
/// @throws Rejected naming the face Surface_mesh refuses.
TriMesh simplify(const TriMesh& mesh, int edges);

/// A triangle mesh held and edited by CGAL itself: Euler::flip_edge, and Euler::split_edge
/// followed by Euler::split_face on each side with a face. Edges are named by endpoints;
/// Surface_mesh appends each new vertex, so indices match ours. flip_edge has no refusal: its
/// conditions (two faces, the new edge absent) are preconditions the caller must check.
class EditableMesh {
public:
    /// @throws Rejected naming the face Surface_mesh refuses.
    explicit EditableMesh(const TriMesh& mesh);
    ~EditableMesh();
    EditableMesh(EditableMesh&&) noexcept;
    EditableMesh& operator=(EditableMesh&&) noexcept;

    /// @throws Rejected if CGAL has no edge a-b, or it is a border edge.
    void flip(int a, int b);
    /// Returns the new vertex's index, at the midpoint. @throws Rejected if CGAL has no edge a-b.
    int split(int a, int b);
    /// What Surface_mesh::is_valid, is_valid_polygon_mesh and is_triangle_mesh say, one line
    /// per failed check (empty when all hold).
    std::vector<std::string> check() const;
    /// Faces as vertex triples, in Surface_mesh's face order.
    std::vector<Triangle> faces() const;
    std::vector<Vec3> positions() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// "CGAL 5.5.1".
std::string version();

}  // namespace crossdiv::adapters::cgal
