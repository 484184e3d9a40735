#pragma once
/// @file
/// Midpoint subdivision of a triangle mesh, manifold or not (VTK's vtkLinearSubdivisionFilter,
/// Open3D's subdivide_midpoint, "linear" or "simple" triangle subdivision): each triangle split
/// into four at its edge midpoints, every old vertex kept where it is. The limit surface is
/// the control mesh itself. The traversal states one level as a RefinementStep (refinement.h);
/// the masks are bilinear subdivision's (bilinear_mask.h): a vertex stays, an edge point is
/// the midpoint of its ends.
///
/// Refined vertex order, every level: old vertices keep their indices (0 .. nv-1), then one
/// edge point per edge (nv + e), edges numbered as Far completes them from the faces
/// (nonmanifold.h), so a non-manifold edge still has one midpoint and a degenerate side one of
/// its own. Triangle (v0, v1, v2) becomes (v_k, E(v_k v_k+1), E(v_k-1 v_k)) for k = 0, 1, 2,
/// then (E01, E12, E20): Loop's 1-to-4 split, the topology of OpenSubdiv's Loop scheme.

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// One midpoint level of the triangle mesh `mesh` as data.
/// @throws InputError naming the face for a face that is not a triangle, or a level whose
///         indices would not fit 32 bits.
RefinementStep midpoint_step(const PolyMesh& mesh);

/// `levels` levels of midpoint subdivision (colors refined alike).
/// @throws InputError as midpoint_step, for crease, corner or hole tags (the scheme has no
///         such rules: every point already lies where a crease would put it), hierarchical
///         edits, or a negative level count.
PolyMesh midpoint_subdivide(const PolyMesh& mesh, int levels);

}  // namespace crossdiv
