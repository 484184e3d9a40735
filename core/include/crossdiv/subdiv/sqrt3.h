#pragma once
/// @file
/// sqrt3 subdivision (Kobbelt 2000) of a manifold triangle mesh: the traversal that states
/// one step as a RefinementStep (refinement.h) with the masks of sqrt3_mask.h.
///
/// Refined vertex order: old vertices keep their indices, then each face's new points in
/// face order -- its centroid, or, for a face split at its boundary edge on a boundary step,
/// the two trisection points of that edge (the one nearer the edge's first vertex first).
/// Faces: two per interior edge -- the old edge flipped, joining the new points on its two
/// sides -- then one per boundary edge: (a, b, centroid) on a step that keeps the boundary,
/// and the middle triangle (t1, t2, opposite vertex) on a boundary step, whose outer thirds
/// come from the flips of the face's two other edges.

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/refinement.h"
#include "crossdiv/subdiv/sqrt3_mask.h"

namespace crossdiv {

/// One sqrt3 step of the triangle mesh `mesh`; `refine_boundary` for an odd generation.
/// @throws InputError naming the face for a face that is not a triangle, or, on a boundary
///         step, a face with more than one boundary edge (a step that keeps the boundary
///         always comes first, and it leaves one boundary edge per face).
RefinementStep sqrt3_step(const PolyMesh& mesh, const PolyConnectivity& conn, bool refine_boundary);

/// `levels` sqrt3 steps, generations counted as `options.parity` says (colors refined alike).
/// @throws InputError naming the element for a mesh build_poly_connectivity refuses, a face
///         that is not a triangle, or a negative level count.
PolyMesh sqrt3_subdivide(const PolyMesh& mesh, const Sqrt3Options& options, int levels);

}  // namespace crossdiv
