#pragma once
/// @file
/// The Butterfly schemes (classic and modified) on a manifold triangle mesh: the traversal
/// that states one level as a RefinementStep (refinement.h) with the masks of
/// butterfly_mask.h.
///
/// Refined vertex order: old vertices keep their indices and positions, then one edge point
/// per edge (nv + e, edges numbered as PolyConnectivity numbers them). Triangle (v0, v1, v2)
/// becomes (v_k, E(v_k v_k+1), E(v_k-1 v_k)) for k = 0, 1, 2, then the middle triangle
/// (E01, E12, E20): Loop's 1-to-4 split.

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/butterfly_mask.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// One level of `variant` on the triangle mesh `mesh` as data, with `wings` for the wing
/// points the boundary removes.
/// @throws InputError naming the face for a face that is not a triangle.
RefinementStep butterfly_step(const PolyMesh& mesh, const PolyConnectivity& conn, ButterflyVariant variant,
                              ButterflyWings wings = ButterflyWings::Reflected);

/// `levels` levels of `variant` (colors refined alike).
/// @throws InputError naming the element for a mesh build_poly_connectivity refuses, a face
///         that is not a triangle, or a negative level count.
PolyMesh butterfly_subdivide(const PolyMesh& mesh, ButterflyVariant variant, int levels,
                             ButterflyWings wings = ButterflyWings::Reflected);

}  // namespace crossdiv
