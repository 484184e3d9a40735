#pragma once
/// @file
/// The curvature study (suite operation "curvature", over the catalog): discrete curvature
/// (mesh/discrete_curvature.h) measured against exact answers and against CGAL.

#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// Discrete curvature against the analytic sphere and torus over 5 refinements (core and
/// each reference that estimates curvature, CGAL's jet fitting), the discrete Gauss-Bonnet
/// theorem on every bundled mesh, edge case and CGAL mesh, and Loop's Gaussian curvature at a
/// vertex of valence 3..12 over 10 levels against the growth its eigenvalues predict.
CheckReport curvature_study();

}  // namespace crossdiv::verification
