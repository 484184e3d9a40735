#pragma once
/// @file
/// The eigenvalues, and on request the eigenvectors, of a small dense real matrix: the local
/// subdivision matrices whose spectra say how a scheme converges at a vertex (Loop 1987,
/// Ball and Storry 1988), and the left eigenvectors that give limit masks.
///
/// Eigen's EigenSolver (real Schur form) does the work. It is instantiated in one translation
/// unit, eigendecomposition.cpp, and nowhere else: each instantiation costs more compile time
/// than most files of the project.

#include <Eigen/Core>

namespace crossdiv {

struct Eigendecomposition {
    Eigen::VectorXcd values;   ///< in the solver's order (not sorted)
    Eigen::MatrixXcd vectors;  ///< column k belongs to values[k]; empty unless asked for
};

/// The eigendecomposition of the square matrix `m`.
/// @param with_vectors compute the eigenvectors too (the values alone are cheaper).
Eigendecomposition eigendecomposition(const Eigen::MatrixXd& m, bool with_vectors);

}  // namespace crossdiv
