#pragma once
/// @file
/// Loop subdivision by local operations, the meshedit method (CS184 assignment 2,
/// "Loop subdivision via edge operations"): compute the new positions on the coarse mesh,
/// split every old edge, flip every new edge that joins an old and a new vertex, move the
/// vertices to their new positions. It is the same subdivision as the index-based driver of
/// loop.h, reached through a half-edge mesh; the harness checks that both give the same mesh.

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {

/// One level of Loop subdivision by split and flip, with the masks of loop_mask.h.
/// Vertices are numbered as loop_subdivide numbers them (old vertices first, then the new
/// vertex of coarse edge e at nv + e, edges in TriConnectivity's order); faces are the same
/// set of triangles in a different order. Colors, when present, are refined alike.
/// @throws InputError (naming the element) as LoopRefiner: a non-manifold or inconsistently
///         oriented mesh, or a non-finite coordinate; and where the method itself cannot
///         follow: two faces on the same three vertices refine to two edges between the same
///         two new vertices, which no flip makes (the message names the vertices).
TriMesh loop_by_split_and_flip(const TriMesh& mesh, const LoopOptions& options);

}  // namespace crossdiv
