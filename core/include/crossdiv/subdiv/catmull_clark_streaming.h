#pragma once
/// @file
/// Catmull-Clark subdivision written for speed: the refinement of catmull_clark_subdivide
/// (catmull_clark.h) with the same masks, the same numbering of vertices, edges and faces and
/// the same sums in the same order -- so the result is bit-identical -- but with the levels'
/// traversal turned into passes over flat arrays:
///
/// - the input level's connectivity is built once (build_poly_connectivity, which also checks
///   the mesh); every later level's is written from its parent's by the rules of the split, in
///   one pass over the corners: no half-edge is looked up, no table of edges is built;
///   - a quad of corner c is (v_c, E(c), F(f), E(prev c)), so a child corner's twin is one of
///     four closed forms in the parent's next, prev and twin;
///   - edges are numbered in one scan over the child corners (an edge at its first corner, as
///     build_poly_connectivity numbers it), and each vertex's one-ring walk starts where that
///     builder starts it (the corner whose incoming half-edge is on the boundary, else the
///     lowest corner), so edge and vertex points sum their terms in catmull_clark_step's order;
/// - the points are computed directly (face points, then edge points, then vertex points, which
///   read the new face points), with no stencil table; the number of faces around each vertex
///   is carried from level to level (a face point has its face's size, an edge point 4, 2 on a
///   boundary) instead of counted;
/// - for the last level only the quads are written.
///
/// Every pass writes each element from one place (the edges of a level are numbered block by
/// block from the counts of the blocks before), so the passes are split among `threads`
/// threads (std::thread) with the same result on any number of them.
///
/// Meshes outside its reach are refined by catmull_clark_subdivide itself: crease, corner or
/// hole tags, per-corner edges (a level of the non-manifold rules), a mesh that is not a
/// manifold (under NonManifoldRule::OpenSubdiv), a non-finite coordinate, 0 levels. Used by the
/// core implementation for every Catmull-Clark refinement and timed by `crossdiv bench`.

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"

namespace crossdiv {

/// `levels` levels of Catmull-Clark subdivision (positions and, when present, colors),
/// bit-identical to catmull_clark_subdivide(mesh, options, levels), on `threads` threads (a
/// mesh it hands to catmull_clark_subdivide is refined on one). `streamed`, when given, is set
/// to whether this driver refined the mesh itself.
/// @throws InputError as catmull_clark_subdivide, and when `threads` < 1.
PolyMesh catmull_clark_subdivide_streaming(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels,
                                           int threads = 1, bool* streamed = nullptr);

}  // namespace crossdiv
