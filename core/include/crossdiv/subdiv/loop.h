#pragma once
/// @file
/// Loop subdivision: the generic one-level driver (traversal) that applies the masks of
/// loop_mask.h, N levels, the subdivision matrix S with V' = S V, and vertex provenance.
///
/// Output order, every level: old vertices keep their indices (0 .. nv-1), then one new
/// vertex per edge, nv + e for edge e of TriConnectivity's numbering. Triangle i becomes
/// 4i .. 4i+3: (v0, m0, m2), (v1, m1, m0), (v2, m2, m1), (m0, m1, m2), where mj is the new
/// vertex on edge j of triangle i. The refined connectivity is derived from the coarse one
/// in O(F) (no rebuild, no search), as OpenSubdiv's Vtr refinement does; its edges are the
/// halves of coarse edge e (2e at edge_vertices[e][0], 2e+1 at the other end), then the
/// three interior edges of triangle i (2E + 3i + k, edge k of the centre triangle).

#include <Eigen/SparseCore>
#include <vector>

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// Where a refined vertex came from: the vertex point of old vertex `a` (b < 0), or the
/// edge point of the old edge (a, b).
struct VertexOrigin {
    int a;
    int b;
    bool is_edge_point() const { return b >= 0; }
};

/// Loop subdivision, level by level, keeping every level (mesh, connectivity, provenance).
/// Positions and, when present, colors are refined with the same stencils.
class LoopRefiner {
public:
    /// @throws InputError (naming the element) if `base` is not a manifold, consistently
    ///         oriented triangle mesh or has a non-finite coordinate.
    LoopRefiner(TriMesh base, LoopOptions options);

    /// Refines the finest level `levels` more times.
    void refine(int levels = 1);

    /// Number of levels held, the base included.
    int num_levels() const { return static_cast<int>(levels_.size()); }
    const TriMesh& mesh(int level) const { return levels_[level].mesh; }
    const TriConnectivity& connectivity(int level) const { return levels_[level].conn; }
    /// Provenance of each vertex of `level` (>= 1) in terms of the vertices of level - 1.
    std::vector<VertexOrigin> origins(int level) const;
    const LoopOptions& options() const { return options_; }

private:
    struct Level {
        TriMesh mesh;
        TriConnectivity conn;
    };
    std::vector<Level> levels_;
    LoopOptions options_;
};

/// Checks that Loop refines `mesh` under `options`: a manifold triangle mesh
/// (loop_input_connectivity), or, under NonManifoldRule::OpenSubdiv, one whose non-manifold
/// edges and vertices OpenSubdiv's rules refine (nonmanifold.h).
/// @throws InputError naming the element otherwise.
void check_loop_input(const TriMesh& mesh, const LoopOptions& options);

/// `levels` levels of Loop subdivision, keeping only the last one (the fast path).
/// @throws InputError as LoopRefiner.
TriMesh loop_subdivide(const TriMesh& mesh, const LoopOptions& options, int levels);

/// The one-level subdivision matrix S (rows: refined vertices in output order, columns:
/// old vertices) with V' = S V. Each row sums to 1.
/// @throws InputError as LoopRefiner.
Eigen::SparseMatrix<double> loop_subdivision_matrix(const TriMesh& mesh, const LoopOptions& options);
/// The same on known connectivity: rows in the order of loop_refine_once(mesh, conn, ...),
/// as LoopRefiner numbers each level.
Eigen::SparseMatrix<double> loop_subdivision_matrix(const TriMesh& mesh, const TriConnectivity& conn,
                                                    const LoopOptions& options);

/// Refines positions (and colors when present) one level on known connectivity.
TriMesh loop_refine_once(const TriMesh& mesh, const TriConnectivity& conn, const LoopOptions& options);

/// The connectivity of the level loop_refine_once produces, derived from the coarse one.
TriConnectivity refine_tri_connectivity(const TriMesh& coarse, const TriConnectivity& conn);

/// One Loop level of a polygon mesh whose faces are triangles, as a RefinementStep of the
/// generic driver (loop_step.cpp), honouring the mesh's crease tags with OpenSubdiv's sharp
/// rules (crease_mask.h); the refined tags are in the step. Vertex and face order are those of
/// loop_refine_once on the same mesh (both connectivities number edges in scan order); over
/// several levels the orders part, as the fast driver numbers the halves of coarse edges
/// first while this one rebuilds the connectivity in scan order. Positions agree.
/// @throws InputError naming the first face that is not a triangle, or a bad tag.
RefinementStep loop_step(const PolyMesh& mesh, const PolyConnectivity& conn, const LoopOptions& options);

/// `levels` Loop levels of a polygon mesh of triangles, crease tags honoured (the result
/// carries the decayed tags). Untagged meshes take the fast driver; tagged ones loop_step.
/// @throws InputError as loop_step or LoopRefiner.
PolyMesh loop_subdivide(const PolyMesh& mesh, const LoopOptions& options, int levels);

/// Checks what Loop needs (finite coordinates; the rest is checked by building the
/// connectivity) and returns the connectivity. @throws InputError naming the element.
TriConnectivity loop_input_connectivity(const TriMesh& mesh);

}  // namespace crossdiv
