#pragma once
// The Loop levels' subdivision matrices on the refiner's own connectivity, for the two forms
// of re-evaluation at fixed topology (composed_stencils.cpp, level_stencils.cpp).

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"

namespace crossdiv::detail {

/// The matrices S_1 .. S_levels (compressed rows) and the last level's triangles.
struct LoopLevelMatrices {
    std::vector<Eigen::SparseMatrix<double, Eigen::RowMajor>> matrices;
    std::vector<Triangle> triangles;
};

/// `levels` Loop levels of `base` under `options`. Each matrix is taken on the refiner's own
/// connectivity, so that its rows follow the vertex order of the level the refiner (and
/// loop_subdivide) makes.
/// @throws InputError as loop_subdivide, or for levels < 1.
inline LoopLevelMatrices loop_level_matrices(const TriMesh& base, const LoopOptions& options, int levels) {
    if (levels < 1) throw InputError("number of levels must be >= 1, got " + std::to_string(levels));
    LoopRefiner refiner(base, options);
    refiner.refine(levels);
    LoopLevelMatrices out;
    for (int l = 0; l < levels; ++l) {
        out.matrices.emplace_back(loop_subdivision_matrix(refiner.mesh(l), refiner.connectivity(l), options));
        out.matrices.back().makeCompressed();
    }
    out.triangles = refiner.mesh(levels).triangles;
    return out;
}

}  // namespace crossdiv::detail
