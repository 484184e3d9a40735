#pragma once
/// @file
/// The analytic primitives (primitives.h) flattened within a distance by the rule the splines
/// follow (tessellate_distance, tessellation.h): greedy farthest reach, each edge's far end put
/// as far along the curve as a certified bound of the arc's distance to its chord allows.
///
/// The bound over [s0, s1], h = s1 - s0, chord direction u: the arc's offset from the chord,
/// (I - u u^T)(P(s) - P(s0)), vanishes at both ends, so it is at most h^2 / 8 times the largest
/// |(I - u u^T) P''| over the interval (the linear interpolation error); when the arc runs
/// monotonically along the chord (P' . u > 0 throughout) that offset is its distance to the
/// chord segment. Otherwise |P(s) - L(s)| <= h^2 / 8 max |P''|, L the parameter-linear point of
/// the chord. The maxima and the minimum of P' . u come from 16 samples per edge widened by the
/// primitive's closed-form bound of the next derivative (max |P'''| and max |P''| over all s),
/// so the bound holds between the samples too. As for the splines, every chord point then has
/// an arc point within tol: the Hausdorff distance between curve and polyline is at most tol.

#include "crossdiv/curves/primitives.h"

namespace crossdiv {

/// Bounds over every s of a primitive's second and third derivatives (closed form: the
/// circle's and helix's are its radius; the trefoil's the sum of its terms' amplitudes).
struct PrimitiveDerivativeBounds {
    double second = 0;  ///< max |P''(s)|
    double third = 0;   ///< max |P'''(s)|
};
PrimitiveDerivativeBounds derivative_bounds(const Primitive& p);

/// Samples of `p` within `tol` of it, by the rule above; the last sample of a closed
/// primitive is its first again, bitwise (as sample_primitive's). Exact unit tangents, normals
/// by curve_normals. @throws InputError if tol is not finite or below kMinDistanceTolRelative of
/// the primitive's size, or if the samples would exceed kMaxCurveSamples.
Polyline tessellate_primitive_distance(const Primitive& p, double tol);

/// N* for a primitive: the integral of sqrt(kappa) over its arc length, / sqrt(8 tol) (as
/// flattening_estimate for a spline: about the fewest edges of any polyline within tol, for
/// small tol), by the trapezoid rule on 4096 samples per turn. @throws InputError if tol <= 0.
double primitive_flattening_estimate(const Primitive& p, double tol);

}  // namespace crossdiv
