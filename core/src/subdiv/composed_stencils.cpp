#include "crossdiv/subdiv/composed_stencils.h"

#include <Eigen/SparseCore>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"

namespace crossdiv {

ComposedStencils ComposedStencils::loop(const TriMesh& base, const LoopOptions& options, int levels) {
    if (levels < 1) throw InputError("number of levels must be >= 1, got " + std::to_string(levels));
    LoopRefiner refiner(base, options);
    refiner.refine(levels);
    // Each level's matrix on the refiner's own connectivity, so that the rows follow the
    // vertex order of the level the refiner (and loop_subdivide) makes.
    using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor>;
    RowMajor S = loop_subdivision_matrix(refiner.mesh(0), refiner.connectivity(0), options);
    for (int l = 1; l < levels; ++l)
        S = RowMajor(loop_subdivision_matrix(refiner.mesh(l), refiner.connectivity(l), options) * S);
    S.makeCompressed();
    ComposedStencils out;
    out.num_base_ = base.num_vertices();
    out.row_start_.assign(S.outerIndexPtr(), S.outerIndexPtr() + S.rows() + 1);
    out.source_.assign(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
    out.weight_.assign(S.valuePtr(), S.valuePtr() + S.nonZeros());
    out.triangles_ = refiner.mesh(levels).triangles;
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
