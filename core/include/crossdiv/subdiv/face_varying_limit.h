#pragma once
/// @file
/// Limit values of a face-varying channel (texture coordinates): where each value lands after
/// infinitely many levels, as OpenSubdiv's PrimvarRefiner::LimitFaceVarying computes them, from
/// the last level of a refinement (face_varying_refinement.h) with its sharpness.
///
/// The face-varying topology of that level decides each value's mask (as it decides its
/// refinement):
/// - under `all`, and for bilinear, every value is linear: it stays;
/// - a vertex whose values match its vertex (one value, no seam, no rule making it linear)
///   takes the vertex's own limit mask on the values around it, by the vertex's rule at that
///   level: smooth or dart -- Catmull-Clark (n^2 v + 4 sum e_i + sum f_i) / (n (n + 5)) over the
///   ring's edge and opposite values (Halstead et al. 1993; valence 2 stays, as in Sdc), Loop
///   (1 - n chi) v + chi sum e_i, chi = 1 / (n + 3 / (8 beta(n))) with Loop's beta; crease
///   (2/3 v + 1/6 at each end of its two sharp edges: the cubic B-spline's limit); corner (a
///   sharp vertex, or three or more sharp edges): stays;
/// - a value of a vertex that does not match is a corner, kept, or a crease: 2/3 itself and
///   1/6 at each end of its span's bounding edges; a crease value still semi-sharp at that
///   level is a corner decaying to a crease (OpenSubdiv's ValueTag: _semiSharp, not _crease),
///   kept.
///
/// The limit masks are Sdc's (sdc/catmarkScheme.h, loopScheme.h: assignSmoothLimitMask,
/// assignCreaseLimitMask, assignCornerLimitMask).

#include "crossdiv/mesh/face_varying.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/face_varying_refinement.h"

namespace crossdiv {

/// The limit values of `channel` on `mesh` (its corners indexed like `channel`'s; the values
/// replaced by their limits). `mesh` carries its level's sharpness (CreaseTags), as the levels
/// of subdivide_levels_with_face_varying do; `semi` the channel's semi-sharp tags carried to
/// that level (its `semi_tags`), or null at level 0, where they are read off the sharpness.
/// @throws InputError as build_poly_connectivity (a mesh that is not a manifold included) and
///         for a channel that does not fit the mesh; for Catmull-Clark, naming the vertex, a
///         smooth vertex with a face that is not a quad around it (refine once first: every face
///         is then a quad), and for Loop a face that is not a triangle; for values whose limits
///         overflow double; under Hbr's face-varying rules (FaceVaryingOptions::rules), which
///         have no limit masks here, unless the values are linear.
FaceVaryingChannel face_varying_limit(const PolyMesh& mesh, const FaceVaryingChannel& channel, FaceVaryingScheme scheme,
                                      const FaceVaryingOptions& options, const FaceVaryingSemiSharp* semi = nullptr);

}  // namespace crossdiv
