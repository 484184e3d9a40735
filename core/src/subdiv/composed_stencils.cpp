#include "crossdiv/subdiv/composed_stencils.h"

#include <string>

#include "crossdiv/error.h"
#include "loop_level_matrices.h"

namespace crossdiv {

ComposedStencils ComposedStencils::loop(const TriMesh& base, const LoopOptions& options, int levels) {
    detail::LoopLevelMatrices levels_of = detail::loop_level_matrices(base, options, levels);
    using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    RowMajor S = std::move(levels_of.matrices.front());
    for (size_t l = 1; l < levels_of.matrices.size(); ++l) S = RowMajor(levels_of.matrices[l] * S);
    S.makeCompressed();
    ComposedStencils out;
    out.num_base_ = base.num_vertices();
    out.row_start_.assign(S.outerIndexPtr(), S.outerIndexPtr() + S.rows() + 1);
    out.source_.assign(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
    out.weight_.assign(S.valuePtr(), S.valuePtr() + S.nonZeros());
    out.triangles_ = std::move(levels_of.triangles);
    return out;
}

void ComposedStencils::apply(const std::vector<Vec3>& base, std::vector<Vec3>& out) const {
    if (static_cast<int>(base.size()) != num_base_)
        throw InputError("the stencils read " + std::to_string(num_base_) + " base vertices, given " +
                         std::to_string(base.size()));
    out.resize(static_cast<size_t>(num_rows()));
    const int* source = source_.data();
    const double* weight = weight_.data();
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are packed triples");
    const double* p = reinterpret_cast<const double*>(base.data());
    for (int r = 0; r < num_rows(); ++r) {
        double x = 0, y = 0, z = 0;
        for (int k = row_start_[r]; k < row_start_[r + 1]; ++k) {
            const double* q = p + 3 * static_cast<size_t>(source[k]);
            x += weight[k] * q[0];
            y += weight[k] * q[1];
            z += weight[k] * q[2];
        }
        out[static_cast<size_t>(r)] = Vec3(x, y, z);
    }
}

}  // namespace crossdiv
