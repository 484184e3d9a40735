#pragma once
/// @file
/// Catmull-Clark subdivision of any manifold polygon mesh: the traversal that states one
/// level as a RefinementStep (refinement.h) with the masks of catmull_clark_mask.h.
///
/// Refined vertex order, every level: old vertices keep their indices (0 .. nv-1), then one
/// face point per face (nv + f), then one edge point per edge (nv + nf + e, edges numbered
/// as PolyConnectivity numbers them) -- OpenSubdiv's default order (vertices, faces, edges).
/// Face f with corners c_0 .. c_{n-1} becomes n quads, quad k = (v_k, E(v_k v_{k+1}), F(f),
/// E(v_{k-1} v_k)), numbered after the corners of all earlier faces (quad = corner index).

#include <Eigen/SparseCore>

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// One Catmull-Clark level of `mesh` (whose connectivity is `conn`) as data.
RefinementStep catmull_clark_step(const PolyMesh& mesh, const PolyConnectivity& conn, const CatmullClarkOptions& options);

/// `levels` levels of Catmull-Clark subdivision (colors refined alike), with the mesh's
/// hierarchical edits applied (catmull_clark_levels).
/// @throws InputError naming the element for a mesh build_poly_connectivity refuses, or a
///         negative level count.
PolyMesh catmull_clark_subdivide(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels);

/// Levels 0..`levels` of catmull_clark_subdivide, the hierarchical edits of `mesh` applied
/// to each (hierarchical_edit_walk.h; level 0 is `mesh` with its level-0 edits), the edits
/// themselves not carried into the levels.
/// @throws InputError as catmull_clark_subdivide; for an edit whose path leaves the mesh.
std::vector<PolyMesh> catmull_clark_levels(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels);

/// The one-level subdivision matrix S with V' = S V, rows in the refined vertex order.
/// @throws InputError as catmull_clark_subdivide.
Eigen::SparseMatrix<double> catmull_clark_subdivision_matrix(const PolyMesh& mesh, const CatmullClarkOptions& options);

}  // namespace crossdiv
