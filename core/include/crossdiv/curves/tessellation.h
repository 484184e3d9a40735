#pragma once
/// @file
/// Curve tessellation: uniform in the parameter, adaptive by angle (the CS4620 seed's
/// recursive de Casteljau split), adaptive by distance (a guaranteed bound), and Wang's
/// formula for the uniform step count that guarantees a distance.
///
/// Every mode emits only points exactly on the curve (de Casteljau points, never chord
/// midpoints), each with its global parameter u (segment k + local t) and the unit tangent
/// there, and always emits the ends of every segment, so no polyline edge straddles two
/// segments.

#include <algorithm>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "crossdiv/curves/cubic_spline.h"
#include "crossdiv/curves/frames.h"

namespace crossdiv {

/// A tessellated curve: positions on the curve with their parameters and unit tangents, and
/// normals as curve_normals gives them.
struct Polyline {
    std::vector<Vec3> positions;
    std::vector<Vec3> tangents;
    std::vector<Vec3> normals;
    std::vector<double> params;  ///< global u in [0, num_segments]
    int size() const { return static_cast<int>(positions.size()); }
};

/// The tessellation strategies, named as the CLI's --mode.
enum class TessellationMode { Uniform, Angle, Distance };
std::string_view to_string(TessellationMode m);

/// The most samples one tessellated curve may have: 3 vectors of 24 bytes and a parameter
/// each, about 2.6 GB, a tenth of a 24 GB machine, so that the surfaces built from two such
/// curves are bounded by their own face limit first.
inline constexpr long long kMaxCurveSamples = 32'000'000;

/// `intervals` equal parameter steps per segment (the SWP file's STEPS): t = i / intervals,
/// the end of each segment emitted once. @throws InputError if intervals < 1, or if the
/// samples would exceed kMaxCurveSamples.
Polyline tessellate_uniform(const BezierChain& chain, int intervals);

/// Per-segment step counts (e.g. from wang_intervals). @throws InputError on a count < 1 or
/// a size that is not the segment count.
Polyline tessellate_uniform(const BezierChain& chain, std::span<const int> intervals);

/// The maximum recursion depth of the angle mode (the CS4620 seed's advice: 10 levels, so a
/// degenerate segment yields at most 1024 edges).
inline constexpr int kAngleMaxLevels = 10;

/// Adaptive by angle (CS4620 seed): a piece is emitted as one edge when every turning angle
/// of its control polygon (between consecutive edges of nonzero length) is at most
/// angle_tol / 2, since the tangent cannot swing more than the polygon's total turn; else
/// it is split at t = 1/2 and both halves are treated the same way, at most `max_levels` deep.
/// It bounds the turn of the tangent per edge, not the distance to the curve.
/// @throws InputError if angle_tol is not in (0, pi].
Polyline tessellate_angle(const BezierChain& chain, double angle_tol, int max_levels = kAngleMaxLevels);

/// The smallest distance tolerance accepted, relative to the bounding-box diagonal of the
/// control points: below about 1e4 ulps the flatness test itself is rounding noise, and the
/// recursion would split to the bottom of the parameter's precision.
inline constexpr double kMinDistanceTolRelative = 1e-12;

/// Bisection steps that place an edge's far end in the distance mode (splines and primitives):
/// the end found lies within 2^-24 of the bracket's width below the farthest feasible one, far
/// below what would save an edge.
inline constexpr int kDistanceReachBisections = 24;

/// The distance mode's greedy step (splines and primitives): the farthest parameter in
/// (from, end] at which an edge from `from` still fits (`fits(from, to)`), bracketed from
/// `guess` (clamped into (from, end]; grown by half while it fits) and then bisected
/// kDistanceReachBisections times. Returns `from` when not even the first bracket's lower end
/// fits.
template <class Fits>
double farthest_reach(double from, double end, double guess, const Fits& fits) {
    double lo = from, hi = end;
    for (double g = std::clamp(guess, from + (end - from) * 1e-9, end);;) {
        if (!fits(from, g)) {
            hi = g;
            break;
        }
        lo = g;
        if (g == end) break;
        g = std::min(end, from + 1.5 * (g - from));
    }
    for (int i = 0; i < kDistanceReachBisections && lo < end; ++i) {
        const double mid = 0.5 * (lo + hi);
        (fits(from, mid) ? lo : hi) = mid;
    }
    return lo;
}

/// Adaptive by distance, with a guarantee, and near the fewest edges: greedy farthest reach.
/// From each vertex the next is put as far along the chain as an upper bound of the arc's
/// distance to the chord between them allows (the arc may run across the chain's joints):
/// bracketed from where the flattening integral (of sqrt(kappa) ds, see flattening_estimate)
/// says an edge within tol ends, grown by half while it fits, then bisected. For a convex arc
/// a shorter arc's chord is no farther, so the greedy choice is the fewest edges (interval
/// covering); measured on the bundled curves it stays within 1.12 N* at 1e-3 and 1e-4 of the
/// curve's size. The bound on one segment's piece is the smallest of: the control points'
/// largest distance from the chord (the piece lies in their convex hull); (1 - 2^(1-d))
/// max_i |p_i - l_i| against the uniformly parametrized chord; and, for a piece running
/// monotonically along its chord, its distance to the chord's line by branch and bound on the
/// Bezier coefficients of the perpendicular components, tight to 1e-9. Across joints, the
/// largest over the pieces of the first and the last of those against the shared chord. Since
/// the arc runs continuously from one end of the chord to the other, every chord point has an
/// arc point within tol (project the arc onto the chord): the Hausdorff distance between curve
/// and polyline is at most tol.
/// @throws InputError if tol is not finite or below kMinDistanceTolRelative of the curve.
Polyline tessellate_distance(const BezierChain& chain, double tol);

/// A distance tolerance that shrinks away from the y axis: an edge whose control points reach
/// |x| = r may deviate by tol - radial r. The profile of a surface of revolution about the y
/// axis takes it when its slices already sag r (1 - cos(pi / n)) at radius r: the profile
/// spends there what the slices leave, more near the axis than at the rim.
struct DistanceBudget {
    double tol = 0;
    double radial = 0;
};

/// The distance mode under `budget` (tessellate_distance(chain, tol) is {tol, 0}).
/// @throws InputError as tessellate_distance, for a negative or non-finite radial share, or
///         for a segment the budget leaves no tolerance on.
Polyline tessellate_distance(const BezierChain& chain, const DistanceBudget& budget);

/// N* = (integral of sqrt(kappa) ds) / sqrt(8 tol): about the fewest edges of any polyline
/// with its vertices on the curve within tol of it, for small tol (a chord of length h on
/// curvature kappa sags kappa h^2 / 8). The integral is summed by trapezoids on 128 samples
/// per segment. @throws InputError if tol <= 0.
double flattening_estimate(const BezierChain& chain, double tol);

/// Wang's formula (G. Wang, 1984; as in D. Filip, R. Magedson, R. Markot, "Surface
/// algorithms using bounds on derivatives", CAGD 3, 1986): n equal parameter steps keep a
/// degree-d Bezier segment within tol of its polyline when
/// n >= sqrt( d (d - 1) M / (8 tol) ),  M = max_i | p_{i+2} - 2 p_{i+1} + p_i |.
/// Returns that n (at least 1) for each segment. @throws InputError if tol <= 0.
std::vector<int> wang_intervals(const BezierChain& chain, double tol);

/// Normals for a tessellated curve: the planar left-side rule when every point has z = 0
/// (CS-C3100), otherwise N of the rotation-minimizing frame started from initial_binormal.
std::vector<Vec3> curve_normals(std::span<const Vec3> positions, std::span<const Vec3> tangents);

/// Measured deviation of a polyline from its curve.
struct Deviation {
    double max = 0;        ///< largest distance from a curve point to its edge's chord
    double at_param = 0;   ///< where (global u)
};

/// For each edge (consecutive samples u_a < u_b, on one segment), the largest distance from
/// the curve on [u_a, u_b] to the edge: dense samples (kDeviationSamples per edge) and a
/// golden-section refinement around the largest. By the projection argument above this is
/// also the Hausdorff distance bound the distance mode guarantees; dense sampling can only
/// under-estimate it, by far less than the refinement's 1e-9 relative bracket.
Deviation chordal_deviation(const BezierChain& chain, const Polyline& polyline);
inline constexpr int kDeviationSamples = 32;

/// The largest value of f on [a, b] (open): kDeviationSamples equally spaced samples, then a
/// golden-section search in the bracket around the largest (40 steps: the bracket shrinks
/// to 1e-8 of its width). Exact for the unimodal distance profiles of one polyline edge.
Deviation sampled_maximum(const std::function<double(double)>& f, double a, double b);

/// Distance from p to the segment [a, b].
double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b);

}  // namespace crossdiv
