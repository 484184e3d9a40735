#pragma once
/// @file
/// Every tolerance of the harness, each with its reason. Distances are relative to the
/// bounding-box diagonal of the refined mesh, so they mean the same on any mesh scale.

namespace crossdiv::tolerances {

/// Two Loop refinements agree when the largest vertex distance is at most this times the
/// bounding-box diagonal. Each level forms sums of up to n+1 terms with weights below 1, so
/// rounding grows by a few ulps per level; 1e-12 leaves a margin of ~4500 ulps of the diagonal
/// for three levels and orders of magnitude above what a different rule would move
/// (a weight-family or corner-rule difference moves vertices by 1e-3 of the diagonal and up).
inline constexpr double kAgreementRelative = 1e-12;

/// A divergence is classified `rounding` when the largest distance is at most this many ulps
/// of the largest coordinate magnitude: far from the origin (coordinates near 1e8, ulp 1.5e-8)
/// two summation orders of the same stencil part by a few ulps of the coordinates, which can
/// exceed kAgreementRelative of a small diagonal. Three levels of sums of up to n+1 terms give
/// a few ulps each; 16 bounds that and is 1e4 times below any rule difference measured.
inline constexpr double kRoundingUlps = 16;

}  // namespace crossdiv::tolerances

namespace crossdiv::tolerances {

/// Two evaluations of the same polynomial curve (de Casteljau, the Bernstein sum, Eigen's
/// Cox-de Boor, the seed's matrix form) agree when they differ by at most
/// kCurveRoundingUlps * (d + 1) * eps * S, S the bounding-box diagonal of the control points,
/// d the degree: each algorithm forms convex combinations of d + 1 points through up to d
/// levels, so each rounds by a few ulps of S per level. Derivatives carry the factor d
/// (first) and d (d - 1) (second) of their formulas. 64 leaves a wide margin over what is
/// measured (reported in results.json) and is 1e8 times below a wrong weight or basis.
inline constexpr double kCurveRoundingUlps = 64;

/// Frames are orthonormal to this (absolute): each is built by a cross product and one
/// normalization of unit vectors, a few ulps of 1.
inline constexpr double kFrameOrthonormality = 1e-13;

/// The order of convergence the double-reflection frame must show on the helix as the step
/// halves: its global error is O(h^4) (Wang et al. 2008, sec. 4); 3.5 tolerates the
/// pre-asymptotic steps of the coarsest sampling.
inline constexpr double kDoubleReflectionMinOrder = 3.5;

/// Our signed volume and CGAL's PMP::volume sum the same determinants of the same triangles
/// in different orders and groupings: they agree to this, relative to the volume.
inline constexpr double kVolumeAgreementRelative = 1e-12;

/// Bfr evaluates a regular Catmull-Clark face as the bicubic B-spline patch of its 16
/// control points, as we do after converting to Bezier form; the two differ by rounding
/// only. Relative to the control grid's bounding-box diagonal (derivatives: times 3).
inline constexpr double kLimitSurfaceAgreement = 1e-12;

/// A chord of length h sags h^2 / 8R below a circle, so the distance of a swept mesh from an
/// exact sphere or torus falls as h^2: the slope fitted over five doublings of the
/// resolution is 2 within a few hundredths once past the coarsest level; 1.8 still tells
/// second order from first.
inline constexpr double kSecondOrderMin = 1.8;

/// Vertex normals of a surface swept from an exact profile are exact directions, rotated:
/// they agree with the analytic normal to a few ulps of pi (radians).
inline constexpr double kExactNormalRad = 1e-12;

/// The cubic Bezier quarter circle (inner control points at 4/3 tan(pi/8) of the radius)
/// bulges out by at most 2.7253e-4 of the radius (Dokken et al. 1990). A sphere swept from it
/// stops converging at that value; the finest level's measured error lies within 10% of it
/// (the rest is the chord sag of the finest level and where the samples fall).
inline constexpr double kBezierCircleError = 2.7253e-4;
inline constexpr double kBezierCirclePlateauRelative = 0.1;

}  // namespace crossdiv::tolerances
