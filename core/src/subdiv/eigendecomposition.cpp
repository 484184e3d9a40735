#include "crossdiv/subdiv/eigendecomposition.h"

#include <Eigen/Eigenvalues>

namespace crossdiv {

Eigendecomposition eigendecomposition(const Eigen::MatrixXd& m, bool with_vectors) {
    const Eigen::EigenSolver<Eigen::MatrixXd> solver(m, with_vectors);
    Eigendecomposition out;
    out.values = solver.eigenvalues();
    if (with_vectors) out.vectors = solver.eigenvectors();
    return out;
}

}  // namespace crossdiv
