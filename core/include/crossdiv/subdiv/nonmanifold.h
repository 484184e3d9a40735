#pragma once
/// @file
/// Topology that is not a manifold, refined as OpenSubdiv refines it, for Loop and
/// Catmull-Clark: a named rule (NonManifoldRule::OpenSubdiv, the default) beside refusing
/// the mesh (NonManifoldRule::Refuse). The manifold refinements (loop.h, catmull_clark.h)
/// throw NonManifoldInput on such a mesh; under the OpenSubdiv rule they refine it here.
///
/// The rules, each from the OpenSubdiv function it mirrors:
/// - Vtr::internal::Level::completeTopologyFromFaceVertices: edges are the vertex pairs the
///   faces name, corners taken in face order, except that a degenerate pair (a face naming a
///   vertex twice in a row) is a new edge at every corner, and so is a pair that the edge's
///   last face already uses (a face naming the pair twice). An edge is non-manifold when it
///   is one of those, when more than two faces use it, or two faces traverse it in the same
///   direction (a duplicate face's edges); a vertex is non-manifold when it ends a
///   non-manifold edge, or its faces form more than one fan (a bowtie).
/// - Vtr::internal::Refinement (child topology and tags): a refined level's edges are
///   derived per face, never from vertex pairs: two halves per edge, and the edges inside each
///   face. The steps state them in PolyMesh::derived, so that the edges inside two copies of a
///   face stay two edges, as in Far; and with them the tags a child inherits rather than
///   takes from its own faces: an edge's halves are non-manifold (so infinitely sharp) when
///   it is, a vertex's child is infinitely sharp when it is. A child can look manifold where
///   its parent was not -- the vertex a face names twice has a child in one quad, a plain
///   corner; the edge a face names twice has halves that a neighbour shares the manifold
///   way -- and keeps its parent's rule there, as in Far.
/// - Far::TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness: boundary and
///   non-manifold edges are infinitely sharp; a non-manifold vertex is infinitely sharp,
///   except on an interior non-manifold crease (exactly two non-manifold edges, no boundary
///   edge, more faces than edges: a fin along a seam), which keeps the crease rule; a
///   topological corner (one face, two edges) is sharp under the edge-and-corner rule.
/// - Sdc::Crease::DetermineVertexVertexRule (vertex_rule, crease_mask.h): a sharp vertex or
///   more than two sharp edges is a corner (it stays), two sharp edges a crease (3/4 on the
///   vertex, 1/8 on the other ends of the two), none or one the smooth mask.
/// - The masks of the schemes (Sdc::Scheme<...>): a sharp edge's point is its midpoint; a
///   smooth edge has two faces and the scheme's smooth edge mask.
/// - Loop's tuned weight families (Barthe-Kobbelt, loop_mask.h), which OpenSubdiv does not
///   have: a rule of crossdiv's, the one that keeps every manifold refinement as it is. The
///   vertex rules above are the same; a smooth edge's tuned mask reads at each end the
///   valence of the end's fan that holds the edge (its corners, joined across manifold
///   edges), as tuned_edge_valence reads a manifold vertex: interior when the fan closes,
///   VCG's boundary reading when it ends at a sharp edge. On a manifold mesh a vertex has one
///   fan and the reading is the manifold one; at a bowtie each fan is refined as if alone,
///   which is also what VCG's walk around a vertex sees.
/// The base level's tags come from its topology as above; every refined level's from its
/// parent (PolyMesh::derived). OpenSubdiv agrees to 1e-16 on every non-manifold case of the
/// edge-case catalog, and on the Sweet Home 3D corpus but where its walk around a vertex
/// departs from these rules (opensubdiv_walk_accepted_vertices). Semi-sharp crease tags on a
/// non-manifold mesh are refused (InputError).

#include <array>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// One Loop level of a triangle mesh under the rules above: vertex points first, then one
/// edge point per edge (numbered at its first corner in face order), four triangles per
/// triangle in loop_step's order; hole tags carried to the children.
/// @throws InputError for a face that is not a triangle and for semi-sharp tags.
RefinementStep loop_nonmanifold_step(const PolyMesh& mesh, const LoopOptions& options);

/// One Catmull-Clark level likewise: vertex points, face points, edge points; one quad per
/// corner. Under the midpoint-average boundary rule (OpenMesh's, which OpenSubdiv lacks) a
/// manifold boundary vertex takes that rule's mask, and the non-manifold vertices OpenSubdiv's
/// rules above. @throws InputError as loop_nonmanifold_step.
RefinementStep catmull_clark_nonmanifold_step(const PolyMesh& mesh, const CatmullClarkOptions& options);

/// The faces of one level that splits each face into quads around a face point, as Far
/// derives them under the rules above (Catmull-Clark's topology, and bilinear's, on any mesh):
/// vertex points first, then face points, then edge points; one quad per corner (v_c, E(c),
/// F(f), E(prev c)) added to `step`, its edges stated per corner. The stencils are the
/// scheme's. Returns the ends of each edge, in edge-point order. @throws InputError as the steps.
std::vector<std::array<int, 2>> add_quad_split(const PolyMesh& mesh, RefinementStep& step);

/// The faces of one level that splits each triangle into four at its edge points, as Far
/// derives them under the rules above (Loop's topology, and the midpoint scheme's, on any
/// triangle mesh): vertex points first, then edge points; four triangles per triangle in
/// loop_step's order added to `step`, their edges stated per corner. Every face must be a
/// triangle (the caller checks). Returns the ends of each edge, in edge-point order.
std::vector<std::array<int, 2>> add_triangle_split(const PolyMesh& mesh, RefinementStep& step);

/// The ends of each edge of `mesh`, in the order the steps number their edge points (the
/// provenance of a refined level's edge points). @throws InputError as the steps.
std::vector<std::array<int, 2>> nonmanifold_edges(const PolyMesh& mesh);

/// The vertices of `mesh` that are not manifold (they end a non-manifold edge, or their faces
/// form several fans), ascending: where the rules above differ from a manifold refinement.
/// @throws InputError as the steps.
std::vector<int> nonmanifold_vertices(const PolyMesh& mesh);

/// Where OpenSubdiv's implementation departs from the rules above: the vertices of a base
/// level whose faces form more than one fan (and that end no non-manifold edge) but that Far's
/// walk around a vertex (Vtr::internal::Level::orderVertexFacesAndEdges, which tags the vertex
/// non-manifold when it fails) takes for manifold, ascending. The walk steps from a boundary
/// edge (the vertex's last with one face, unless one leaves the vertex along its face) or from
/// the first face to the previous edge of the face at the vertex and across it, and fails only
/// when it comes back to its first or last edge early; it enters a face at the vertex's first
/// corner in it, whichever corner it came in by. Around a vertex that a face names twice, not
/// in a row, it can so count the right number of edges by taking one twice and missing
/// another: Far keeps that vertex manifold with that ring (a dart when the missed edge was
/// sharp), where the rules above make it a corner. Empty for a refined level.
/// @throws InputError as the steps.
std::vector<int> opensubdiv_walk_accepted_vertices(const PolyMesh& mesh);

/// `levels` levels of either; each refined level states its edges per corner.
PolyMesh loop_subdivide_nonmanifold(const PolyMesh& mesh, const LoopOptions& options, int levels);
PolyMesh catmull_clark_subdivide_nonmanifold(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels);

}  // namespace crossdiv
