#pragma once
/// @file
/// Eigen 3.4 `unsupported/Eigen/Splines` adapter: the reference for our curve evaluation.
/// Eigen evaluates B-splines from a knot vector by the Cox-de Boor recurrence (Piegl and
/// Tiller, "The NURBS Book", A2.2 and A2.3), a different algorithm from our de Casteljau on
/// Bezier segments, so agreement is evidence, not a tautology.

#include <span>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::adapters::eigen_splines {

using adapters::SplineSamples;  // reference.h


/// The uniform cubic B-spline of `control` (n >= 4 points) as Eigen::Spline with the
/// uniform knot vector 0, 1, ..., n + 3, evaluated at our global parameters u in [0, n - 3]
/// (Eigen's parameter u + 3: its valid span starts at knot 3). Unit knot spacing makes the
/// derivatives directly comparable with ours. @throws InputError for n < 4.
SplineSamples uniform_cubic_bspline(std::span<const Vec3> control, std::span<const double> u);

/// The Bezier curve of degree d = control.size() - 1 as the clamped B-spline with knots
/// [0^(d+1), 1^(d+1)], evaluated at t in [0, 1]. @throws InputError if control is empty.
SplineSamples clamped_bezier(std::span<const Vec3> control, std::span<const double> t);

/// "Eigen 3.4.0" (from Eigen/Core's version macros).
std::string version();

}  // namespace crossdiv::adapters::eigen_splines
