#pragma once
/// @file composed_stencils.h
/// Refinement at fixed topology, the animation use of subdivision: the topology is refined
/// once, and every frame the last level's positions are re-evaluated from the base mesh's
/// moved vertices. The levels' subdivision matrices are composed into one, S = S_L ... S_1,
/// stored as one stencil per refined vertex (its base vertices and weights, compressed rows),
/// as OpenSubdiv's Far::StencilTableFactory does with factorized intermediate levels; a frame
/// is then one pass over the stencils, with no intermediate level.

#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {

class ComposedStencils {
public:
    /// `levels` Loop levels of `base` under `options`: the refined triangles, and the stencils
    /// whose rows are the vertices of loop_subdivide(base, options, levels), in its order.
    /// @throws InputError as loop_subdivide.
    static ComposedStencils loop(const TriMesh& base, const LoopOptions& options, int levels);

    int num_base_vertices() const { return num_base_; }
    int num_rows() const { return static_cast<int>(row_start_.size()) - 1; }
    /// Stored weights, summed over the rows.
    size_t num_terms() const { return source_.size(); }
    /// The refined mesh's triangles (its topology, fixed).
    const std::vector<Triangle>& triangles() const { return triangles_; }

    /// The refined positions from base positions (num_base_vertices() of them) into `out`
    /// (resized to num_rows()). Each row is summed in stored order, from zero.
    void apply(const std::vector<Vec3>& base, std::vector<Vec3>& out) const;

private:
    int num_base_ = 0;
    std::vector<int> row_start_{0};
    std::vector<int> source_;
    std::vector<double> weight_;
    std::vector<Triangle> triangles_;
};

}  // namespace crossdiv
