#pragma once
/// @file
/// kappa-curves (Z. Yan, S. Schiller, G. Wilensky, N. Carr, S. Schaefer, "k-Curves:
/// Interpolation at Local Maximum Curvature", SIGGRAPH 2017), closed variant: a closed chain
/// of quadratic Bezier pieces, one per given point p_i, where piece i passes through p_i at
/// the parameter t_i at which its |curvature| is largest.
///
/// Piece i is c_{i,0}, c_{i,1}, c_{i,2}. Neighbouring pieces share their joint on the segment
/// between their middle points,
///
///     c_{i,2} = c_{i+1,0} = (1 - l_i) c_{i,1} + l_i c_{i+1,1},
///
/// which makes the chain G1; with l_i = sqrt(A_i) / (sqrt(A_i) + sqrt(A'_i)), where A_i is the
/// area of triangle (c_{i,0}, c_{i,1}, c_{i+1,1}) and A'_i of (c_{i,1}, c_{i+1,1}, c_{i+1,2}),
/// the two pieces' |curvature| agree at the joint (G2, except that the signed curvature
/// flips at an inflection). A quadratic's |curvature| is largest where its speed is
/// smallest; a piece with ends c_{i,0}, c_{i,2} has that maximum at p_i when t_i is the root
/// in [0, 1] of the cubic
///
///     |c2 - c0|^2 t^3 + 3 (c2 - c0).(c0 - p) t^2 + (3 c0 - 2 p - c2).(c0 - p) t - |c0 - p|^2,
///
/// whose value runs from -|c0 - p|^2 at 0 to |c2 - p|^2 at 1 (one root there, the paper's
/// lemma). With the t_i and l_i fixed, p_i = c_i(t_i) is linear in the middle points: one
/// cyclic tridiagonal system. The paper alternates the three steps a fixed number of times;
/// here the iteration runs until the middle points are within kKappaConvergence of the fixed
/// point and reports every iteration's move, so a case that converges slowly or not at all
/// is seen.
/// A quadratic piece has no loop or cusp unless its control points are collinear.
///
/// The construction is planar: the points lie in the xy-plane (z = 0).

#include <span>
#include <vector>

#include "crossdiv/curves/cubic_spline.h"

namespace crossdiv {

/// The iteration stops when the middle points are estimated to be within this fraction of
/// the points' bounding-box diagonal from the fixed point: the last move times rho / (1 - rho),
/// with the contraction rho measured over the last moves. That is a few hundred ulps of the
/// coordinates, where the iterates of well-conditioned cases stop improving, and 4 orders of
/// magnitude below the 1e-9 at which the suite measures the curvature-maximum property (whose
/// error is the distance times the sensitivity of the speed minimum, large at sharp turns).
inline constexpr double kKappaConvergence = 1e-13;
/// The iteration gives up after this many steps: the bundled curves need at most a few
/// hundred (the measured table is in the report); a case beyond is reported as not converged.
inline constexpr int kKappaMaxIterations = 5000;

/// The most points a kappa-curve takes: an iteration costs about 0.6 us per point, so a case
/// that does not converge stops after 5000 iterations within half a minute; a designed curve
/// has tens of points.
inline constexpr size_t kKappaMaxPoints = 10'000;

/// When to stop iterating.
struct KappaOptions {
    double tolerance = kKappaConvergence;  ///< estimated distance to the fixed point / diagonal
    int max_iterations = kKappaMaxIterations;
};

/// The result of the iteration, converged or not.
struct KappaCurve {
    /// Degree 2, closed, one piece per point: piece i is (c_{i,0}, c_{i,1}, c_{i,2}).
    BezierChain chain;
    std::vector<double> params;     ///< t_i: piece i passes through p_i at t_i
    std::vector<double> lambdas;    ///< l_i: where joint i divides c_{i,1} c_{i+1,1}
    std::vector<double> residuals;  ///< per iteration: largest middle-point move / diagonal
    /// The contraction per iteration, rho, measured over the last (up to 10) moves: 0 when the
    /// last move is 0, NaN after a single iteration.
    double contraction = 0;
    double error_estimate = 0;      ///< the last move times rho / (1 - rho); infinity while rho >= 1
    bool converged = false;         ///< error_estimate is within the tolerance

    int iterations() const { return static_cast<int>(residuals.size()); }
    double residual() const { return residuals.empty() ? 0.0 : residuals.back(); }
};

/// The t in [0, 1] at which the quadratic with ends c0, c2 passing through p has its largest
/// |curvature| at p: the cubic's root, found by Newton steps safeguarded by bisection to the
/// last representable bracket.
double kappa_parameter(const Vec3& c0, const Vec3& p, const Vec3& c2);

/// l for the joint between pieces (c0, c1, .) and (., c1_next, c2_next): sqrt(A) / (sqrt(A) +
/// sqrt(A')), with the triangle areas A of (c0, c1, c1_next) and A' of (c1, c1_next, c2_next);
/// 1/2 when both vanish (a straight joint, where any l keeps both curvatures 0).
double kappa_lambda(const Vec3& c0, const Vec3& c1, const Vec3& c1_next, const Vec3& c2_next);

/// Where on [0, 1] the quadratic Bezier (c0, c1, c2) has its largest |curvature|: where its
/// speed is smallest (c' x c'' is constant), clamped to [0, 1]. Independent of the cubic.
double quadratic_max_curvature_param(std::span<const Vec3> piece);

/// Signed curvature of a planar quadratic Bezier piece at t (z of c' x c'' over |c'|^3).
double quadratic_signed_curvature(std::span<const Vec3> piece, double t);

/// Runs the kappa-curve iteration through `points` (closed, in order), from the paper's start
/// (middle points at the points, joints at the chords' midpoints), until `options` says stop.
/// @throws InputError for fewer than 3 or more than kKappaMaxPoints points, a point off the
/// xy-plane or not finite, two consecutive points that coincide (naming them), or a singular
/// system (naming the iteration).
KappaCurve kappa_curve(std::span<const Vec3> points, const KappaOptions& options = {});

/// kappa_curve with the default options, required to converge. @throws InputError as
/// kappa_curve, and when the iteration did not converge (naming the iterations, the last move
/// and the estimate).
KappaCurve converged_kappa_curve(std::span<const Vec3> points);

}  // namespace crossdiv
