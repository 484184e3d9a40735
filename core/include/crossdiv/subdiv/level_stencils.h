#pragma once
/// @file level_stencils.h
/// Refinement at fixed topology, level by level: the topology is refined once, and every frame
/// each level's subdivision matrix S_l is applied in turn to the moved base vertices. Against
/// the composed table (composed_stencils.h) this stores fewer terms (a Loop level row has 4
/// terms for an edge point and valence + 1 for a vertex point, where a row of S_3 ... S_1 has
/// a dozen or more) at the price of writing the intermediate levels, which are a quarter and a
/// sixteenth of the last one and stay in cache.
///
/// Rows repeat their weights: every edge point of an interior edge has 3/8, 3/8, 1/8, 1/8, and
/// every vertex point of valence n the same n + 1 weights. Each distinct weight sequence is
/// stored once (a pattern) and a row names its pattern, so a term costs its 4-byte source
/// index instead of 12 bytes: re-evaluation is bound by memory traffic, not arithmetic.

#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {

class LevelStencils {
public:
    /// `levels` Loop levels of `base` under `options`: the refined triangles, and one stencil
    /// table per level whose last rows are the vertices of loop_subdivide(base, options,
    /// levels), in its order.
    /// @throws InputError as loop_subdivide.
    static LevelStencils loop(const TriMesh& base, const LoopOptions& options, int levels);

    int num_base_vertices() const { return num_base_; }
    int num_levels() const { return static_cast<int>(levels_.size()); }
    /// Vertices of the last level.
    int num_rows() const { return levels_.empty() ? num_base_ : levels_.back().rows(); }
    /// Source indices stored, summed over the levels (one per term).
    size_t num_terms() const;
    /// Distinct weight sequences stored, summed over the levels.
    size_t num_patterns() const;
    /// The refined mesh's triangles (its topology, fixed).
    const std::vector<Triangle>& triangles() const { return triangles_; }

    /// The refined positions from base positions (num_base_vertices() of them) into `out`
    /// (resized to num_rows()); `scratch` holds the intermediate levels (reused between
    /// frames, so that a frame allocates nothing once both have their size). Each row is
    /// summed in stored order, from zero.
    /// @throws InputError when `base` has the wrong size.
    void apply(const std::vector<Vec3>& base, std::vector<Vec3>& out, std::vector<Vec3>& scratch) const;

private:
    /// One level's matrix: compressed rows whose weights are named through a pattern.
    struct Level {
        std::vector<int> row_start{0};      ///< terms of row r: [row_start[r], row_start[r + 1])
        std::vector<int> source;            ///< previous level's vertex of each term
        std::vector<int> row_pattern;       ///< the weight sequence of each row
        std::vector<int> pattern_start{0};  ///< weights of pattern p: from pattern_start[p]
        std::vector<double> pattern_weight;
        int rows() const { return static_cast<int>(row_start.size()) - 1; }
    };
    static void apply_level(const Level& level, const Vec3* in, Vec3* out);

    int num_base_ = 0;
    std::vector<Level> levels_;
    std::vector<Triangle> triangles_;
};

}  // namespace crossdiv
