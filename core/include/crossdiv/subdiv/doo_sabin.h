#pragma once
/// @file
/// Doo-Sabin subdivision of any manifold polygon mesh: the traversal that states one level
/// as a RefinementStep (refinement.h) with the masks of doo_sabin_mask.h.
///
/// Refined vertex order: one corner point per coarse corner, in corner order (corner c is
/// entry c of face_vertices), then, with DooSabinBoundary::ChaikinBoundary, two Chaikin points
/// per boundary edge in edge order (the one near the edge's first vertex first).
/// Faces: the F-face of each face (its corner points), then the E-face of each edge (a quad),
/// then the V-face of each vertex (one side per incident face), all consistently oriented.

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/doo_sabin_mask.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// One Doo-Sabin level of `mesh` (whose connectivity is `conn`) as data.
RefinementStep doo_sabin_step(const PolyMesh& mesh, const PolyConnectivity& conn, const DooSabinOptions& options);

/// `levels` levels of Doo-Sabin subdivision (colors refined alike). Old vertices are not
/// kept: a Doo-Sabin mesh is the dual-like mesh of corner points.
/// @throws InputError naming the element for a mesh build_poly_connectivity refuses, or a
///         negative level count.
PolyMesh doo_sabin_subdivide(const PolyMesh& mesh, const DooSabinOptions& options, int levels);

}  // namespace crossdiv
