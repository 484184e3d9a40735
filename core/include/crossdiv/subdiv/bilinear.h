#pragma once
/// @file
/// Bilinear subdivision of any polygon mesh, manifold or not: the traversal that states one
/// level as a RefinementStep (refinement.h) with the masks of bilinear_mask.h. It is the
/// reference point of the smooth schemes: Catmull-Clark's topology with every weight linear.
///
/// Refined vertex order, every level: old vertices keep their indices (0 .. nv-1), then one
/// face point per face (nv + f), then one edge point per edge (nv + nf + e) -- Catmull-Clark's
/// order (vertices, faces, edges). Face f with corners c_0 .. c_{n-1} becomes n quads, quad
/// k = (v_k, E(v_k v_{k+1}), F(f), E(v_{k-1} v_k)), in corner order. The edges are the ones
/// Far completes from the faces (nonmanifold.h: a side shared by three faces is one edge, a
/// degenerate side a new one), so any mesh, manifold or not, is refined as OpenSubdiv's
/// SCHEME_BILINEAR refines it, and needs no rule of its own.

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// One bilinear level of `mesh` as data.
/// @throws InputError naming the face for a face of fewer than three corners, or a level whose
///         indices would not fit 32 bits.
RefinementStep bilinear_step(const PolyMesh& mesh);

/// `levels` levels of bilinear subdivision (colors refined alike).
/// @throws InputError as bilinear_step, for crease, corner or hole tags (bilinear has no such
///         rules: every point is already where a crease would put it), or a negative level count.
PolyMesh bilinear_subdivide(const PolyMesh& mesh, int levels);

}  // namespace crossdiv
