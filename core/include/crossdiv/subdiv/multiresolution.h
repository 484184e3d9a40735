#pragma once
/// @file
/// Multiresolution editing of Loop surfaces (Zorin, Schroeder and Sweldens, "Interactive
/// multiresolution mesh editing", SIGGRAPH 1997): a mesh with subdivision connectivity -- the
/// connectivity of `levels` Loop levels of a base mesh, with any positions -- is decomposed
/// into base positions and one detail vector per vertex of every finer level; a designer edits
/// the base (or any level) and recomposes, and the details ride along.
///
/// Analysis, from the finest level down: the coarser positions are the least-squares solution
/// of S P_(l-1) = P_l (S the Loop subdivision matrix, least_squares.h), and the detail of each
/// vertex is d = P_l - (S P_(l-1)), stored as its coordinates in a local frame of the smooth
/// prediction S P_(l-1): the unit angle-weighted vertex normal n, the unit tangent t1 towards the
/// vertex's first neighbour (the next corner of the first triangle naming it) projected off n,
/// and t2 = n x t1. Synthesis, from the base up: P_l = S P_(l-1) + F(S P_(l-1)) d.
///
/// Properties the tests measure: recomposing what was decomposed gives the input back to
/// rounding; a rigid motion commutes with both (frames are built from the geometry alone); an
/// edit of a base vertex moves, at level l, the vertices its subdivision stencils reach plus one
/// ring (the frames of those vertices' neighbours turn), predicted by edit_reach(). With zero
/// details the frames do not matter and the edit moves exactly the subdivision support.

#include <Eigen/SparseCore>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {

/// Base positions and the details of every finer level (index 0: level 1), each detail as
/// (t1, t2, n) frame coordinates.
struct MultiresolutionDecomposition {
    std::vector<Vec3> base;
    std::vector<std::vector<Vec3>> details;
};

class LoopMultiresolution {
public:
    /// The hierarchy of `levels` Loop levels of `base`'s connectivity (its positions are not used).
    /// @throws InputError as loop_subdivide, or for a level count outside 1..8.
    LoopMultiresolution(const TriMesh& base, const LoopOptions& options, int levels);

    int num_levels() const { return static_cast<int>(subdivision_.size()); }
    int num_vertices(int level) const { return level == 0 ? num_base_ : static_cast<int>(subdivision_[level - 1].rows()); }
    /// The triangles of level l (0 .. num_levels()).
    const std::vector<Triangle>& triangles(int level) const { return triangles_[level]; }

    /// The finest level of pure subdivision of base positions: the vertices of
    /// triangles(num_levels()), refined one level at a time (loop_subdivide with several
    /// levels numbers its vertices otherwise). @throws InputError for a wrong count.
    std::vector<Vec3> subdivide(const std::vector<Vec3>& base) const;

    /// Decomposes positions of the finest level (the vertices of triangles(num_levels())).
    /// @throws InputError for a wrong count, a non-finite position, a singular analysis, or a
    ///         vertex whose frame is undefined (its normal 0, or all its edges along it).
    MultiresolutionDecomposition decompose(const std::vector<Vec3>& finest) const;
    /// The finest positions from a decomposition (whose base may have been edited).
    /// @throws InputError for wrong counts or a vertex whose frame is undefined.
    std::vector<Vec3> recompose(const MultiresolutionDecomposition& d) const;

    /// The finest-level vertices an edit of the base vertices `edited` can move: at each level,
    /// the vertices whose stencils read a moved vertex, and their neighbours (whose frames turn).
    /// With `with_frames` false, the stencils alone: the subdivision support.
    std::vector<char> edit_reach(const std::vector<int>& edited, bool with_frames) const;

private:
    /// The (t1, t2, n) frame of every vertex of level `level` at `positions`.
    std::vector<Eigen::Matrix3d> frames(int level, const std::vector<Vec3>& positions) const;

    int num_base_ = 0;
    std::vector<Eigen::SparseMatrix<double, Eigen::RowMajor>> subdivision_;  ///< S_l, l = 1 .. L
    std::vector<std::vector<Triangle>> triangles_;                         ///< levels 0 .. L
};

}  // namespace crossdiv
