#pragma once
/// @file
/// Loop subdivision written for speed: the refinement of loop_subdivide (loop.h) with the same
/// masks, the same vertex and triangle numbering and the same edge numbering, but with each
/// level's traversal turned into streams over flat arrays:
///
/// - a vertex point sums its neighbours along a list of its edges in edge order, kept per
///   vertex and carried from level to level (an old vertex's edges become the halves at it; an
///   edge's new vertex takes the two halves and the interior edges of its two triangles); the
///   valence and boundary flag of every vertex are carried too (an edge's new vertex has 6
///   faces inside, 3 on a boundary) instead of counted;
/// - an edge point reads the edge's two ends and two opposite vertices, kept per edge;
/// - the next level's topology (triangles, their edges, each edge's ends and opposite
///   vertices) is written in one pass over the triangles, and for the last level only the
///   triangles: nothing is built that the output does not need.
///
/// Every pass writes each element of the next level from one place, so the passes are split
/// among `threads` threads (std::thread) and give the same bits on any number of them.
///
/// Edge points are bit-identical to loop_subdivide's (the same sums in the same order). A vertex
/// point sums its ring in edge order rather than ring order, so inside, at valence n, it may
/// differ from loop_subdivide's in the last bits (a few ulps of the coordinates); on a
/// boundary (two neighbours) and at a corner it is bit-identical. Used by `crossdiv subdivide`
/// and timed by `crossdiv bench`; the harness compares loop_subdivide, whose ring order the
/// split-and-flip method reproduces bit for bit.

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {

/// `levels` levels of Loop subdivision of a manifold, consistently oriented triangle mesh
/// (positions and, when present, colors), numbered as loop_subdivide numbers them, on
/// `threads` threads (the result does not depend on their number).
/// @throws InputError as loop_subdivide: a mesh that is not a manifold (naming the element),
///         a non-finite coordinate, a level past 32-bit indices, a result that overflows;
///         and when `threads` < 1.
TriMesh loop_subdivide_streaming(const TriMesh& mesh, const LoopOptions& options, int levels, int threads = 1);

}  // namespace crossdiv
