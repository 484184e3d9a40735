#pragma once
/// @file
/// Every tolerance of the harness, each with its reason. Distances are relative to the
/// bounding-box diagonal of the refined mesh, so they mean the same on any mesh scale.

#include <limits>

namespace crossdiv::tolerances {

/// The unit the ulp-counted bounds below are multiplied by: the spacing of doubles at 1.
inline constexpr double kEps = std::numeric_limits<double>::epsilon();

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

/// The float tier: a reference that computes in float (precision=float; MeshLab's VCG) agrees
/// when the largest distance is at most B float ulps of the refined mesh's largest coordinate
/// magnitude, B = kFloatAgreementUlps + (n + 2) / 2 * L for the input's largest valence n (or,
/// where a face is larger, its size less one: a face point sums every corner of its face; a
/// Blender run on a 180-sided face parted by 84 ulps at one level, past the valence's 66.5) and
/// L levels. It reads the input rounded to float (half an ulp), and each level forms float sums
/// of up to n + 1 weighted terms, each rounding by at most half an ulp of a partial sum no
/// larger than the largest coordinate: (n + 2) / 2 ulps a level; its result is read back
/// exactly (binary PLY) or to 7 digits (another half ulp). The constant term bounds the rest
/// (the input's rounding carried through the levels) with margin; at valence 12 and 3 levels
/// B is 85 ulps, at valence 360 and 2 levels 426, 1e2 to 1e4 times below what a rule
/// difference moves (1e-3 of the diagonal and up).
inline constexpr double kFloatAgreementUlps = 64;

/// An isosurface vertex of a reference that rounds the samples to float (scikit-image) matches
/// ours when within kIsosurfaceFloatRoundings * u * (I + 4) * h, u = 2^-24 float's unit roundoff,
/// I the grid's largest index, h its largest spacing. The vertex is (i + t) h: the index
/// coordinate i + t rounds by u (I + 1); t = s0 / (s0 - s1) of samples rounded by u each (s0 and
/// s1 have opposite signs, so no cancellation) by about 3 u; the product with h by u (I + 1) h.
/// 8 bounds those with margin; measured: 1.9e-7 against the bound 3.5e-6 (gyroid, 33 samples,
/// h 0.2). Assumes the level is 0 or the samples integers: float(value) - float(level) would
/// otherwise round by u |level| / |s0 - s1| cells more.
inline constexpr double kIsosurfaceFloatRoundings = 8;

/// Control points recovered from samples of their own limit surface (limit_fitting.h) equal
/// the true ones to this, relative to the control mesh's bounding-box diagonal. The normal
/// equations square the condition number of the limit stencils A (measured 2 to 40 on the
/// catalog), and one step of iterative refinement takes the error back to a few roundings of
/// the coordinates; 1e-10 is the bound the method is asked to meet, measured 1e-15 and below.
inline constexpr double kFittingRecovery = 1e-10;

/// Fitting's distance energy never increases from one iteration to the next (each step
/// minimizes it over the correspondences or over the control points): the next is at most
/// the last times 1 + kFittingEnergyRounding, plus N (kFittingDistanceUlps eps D)^2 for N
/// squared distances on a mesh of diagonal D. The relative part: two sums of squares in
/// different orders, a few ulps apart. The absolute part: a surface that fits exactly still
/// has distances of a few ulps of the coordinates (solving and evaluating round), which may
/// come out larger on the next step than on this one; 64 ulps bounds the stencil sums.
inline constexpr double kFittingEnergyRounding = 1e-12;
inline constexpr double kFittingDistanceUlps = 64;

/// Multiresolution: recomposing a decomposition gives the input back to this, relative to the
/// diagonal. Each level adds back a detail rotated into and out of an orthonormal frame (a
/// few ulps of the detail) to the prediction it was taken from; the bound the method is asked
/// to meet.
inline constexpr double kMultiresolutionRoundTrip = 1e-14;

/// A rigid motion commutes with decompose and recompose to this, relative to the diagonal:
/// the moved mesh's analysis solves a system whose right side is rotated and rounded, and its
/// frames come from normals of rounded positions; each a few ulps of the coordinates, which
/// the motion's shift makes up to twice the diagonal.
inline constexpr double kMultiresolutionRigidMotion = 1e-12;

/// A point's distance to a triangle mesh computed by two exact methods (ours: Ericson's
/// Voronoi regions, closest_point.h; CGAL's AABB tree and squared_distance) agrees to this,
/// relative to the mesh's diagonal: both round the coordinates' differences and a square root,
/// a few ulps of the diagonal.
inline constexpr double kPointMeshDistanceAgreement = 1e-12;


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

/// Two slerps of the same unit quaternions (ours: the half-angle atan2; Eigen's: acos of the dot
/// product) agree to this (absolute, in R^4): both weigh two unit vectors by sines of about
/// unit size, a few ulps each; a wrong weight or arc is off by the angle, 1e10 times more.
inline constexpr double kSlerpAgreement = 1e-15;

/// A quaternion de Casteljau of degree d stays on the unit sphere to kQuaternionNormUlps * d
/// ulps: each of its d levels of slerps rounds the norm by an ulp or two.
inline constexpr double kQuaternionNormUlps = 4;

/// A mitred corner ring keeps the tube's wall: each point's distance from either tube's axis
/// equals its profile radius to this (relative to the largest radius). The mitre moves a point
/// by one division and a dot product, and the frames are orthonormal to kFrameOrthonormality.
inline constexpr double kCornerThickness = 1e-12;

/// A kappa-curve passes through each point at the parameter of the last solve to this
/// (relative to the points' diagonal): the pivoted sparse LU's backward error on rows of
/// nonnegative weights summing to 1, a few ulps (measured below 1e-15 on the bundled curves),
/// with two decades for the condition of the system where a t_i nears 0 or 1.
inline constexpr double kKappaInterpolation = 1e-13;

/// Each point of a kappa-curve is where its piece is slowest (largest |curvature|) to this,
/// relative to the diagonal: the converged middle points are within kKappaConvergence of
/// the fixed point, and the speed minimum moves by that times its sensitivity, which grows
/// as a turn sharpens (about 1e-10 at a 1-degree spike; the hard-case study tables it).
inline constexpr double kKappaCurvatureMaximum = 1e-9;

/// |curvature| agrees on both sides of a kappa-curve's joint to this (relative): the joint
/// weights come from the previous iterate, within kKappaConvergence of the fixed point, and
/// the end curvature of a quadratic is a ratio of an area and a cubed length (a few times
/// more sensitive). Measured at most 4e-11 on the bundled curves.
inline constexpr double kKappaCurvatureContinuity = 1e-9;

/// The tangents at a kappa-curve's joint are parallel to this angle (radians): both are
/// multiples of c_{i+1,1} - c_{i,1}, one through the joint's rounding, which is relative to
/// the middle points and so grows as l_i (or 1 - l_i) shrinks: 1e-12 holds for l down to
/// about 1e-4 (the bundled star's l is 0.007).
inline constexpr double kKappaTangentAngle = 1e-12;

/// After the closure mismatch of a closed curve's frames is distributed along its arc length,
/// the frames close to this angle (radians): the distribution rotates each frame by a share of
/// the measured angle, so what is left is the rounding of those rotations.
inline constexpr double kFrameClosureRad = 1e-12;

/// The order of convergence the double-reflection frame must show on the helix as the step
/// halves: its global error is O(h^4) (Wang et al. 2008, sec. 4); 3.5 tolerates the
/// pre-asymptotic steps of the coarsest sampling.
inline constexpr double kDoubleReflectionMinOrder = 3.5;

/// The order the recursive (projection) frame must show on the helix: first, each step's
/// projection turns the normal by an O(h^2) angle off the rotation-minimizing one, over
/// O(1/h) steps (measured: 1.09 fitted over six doublings, 1.02 over the last). 0.9 tells
/// first order from a frame that does not converge (order 0).
inline constexpr double kRecursiveFrameMinOrder = 0.9;

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


// ---- Discrete curvature.

/// The discrete Gauss-Bonnet sum is an identity (every triangle's angles sum to pi): what is
/// left is rounding. Each corner's angle is an atan2 within 2 ulps of pi; summing them per
/// vertex and then over vertices adds at most a few more ulps of 2 pi per corner. Linear in the
/// corners, so it holds on the largest mesh without being loose on the smallest.
inline constexpr double kGaussBonnetPerCorner = 8 * 2.220446049250313e-16 * 3.141592653589793;
/// The bound for a mesh of `faces` triangles (three corners each).
inline double gauss_bonnet_bound(int faces) { return kGaussBonnetPerCorner * 3.0 * faces; }

/// Two consistent curvature estimators converge to the same surface, so their difference falls
/// at least as fast as the slower one's error: CGAL's degree-2 jet has first-order curvature
/// (Cazals and Pouget 2005, theorem 2). 0.9 tells first order from none.
inline constexpr double kCurvatureAgreementOrderMin = 0.9;

/// The distance-mode tessellation's edge count over N*, the flattening estimate of the fewest
/// edges any polyline within the tolerance needs (tessellation.h): one split of a piece into
/// ceil(sqrt(flatness / tol)) equal pieces lands within a few percent of N* on every
/// bundled and course spline (measured at most 1.12); 1.15 leaves room for rounding up piece counts,
/// while splitting by flatness / tol (forgetting that flatness falls as 1/k^2) doubles it or more.
inline constexpr double kDistanceModeEdgesOverOptimal = 1.15;

/// Principal directions converge at least at first order where the surface is not umbilic
/// (Cazals and Pouget 2005, theorem 2, for a degree-2 jet; measured 2.0 for both estimators on
/// the regular torus). 0.9 tells first order from none: a direction off by a fixed angle, such
/// as the other eigenvector's, has order 0.
inline constexpr double kPrincipalDirectionOrderMin = 0.9;

/// Loop's Gaussian curvature at a vertex of valence n changes by (nu / lambda^2)^2 per level
/// (curvature_study.cpp); the measured ratio approaches it as the next eigenvalue's share
/// dies out, geometrically, slowest at valence 5 where the two are closest (measured after 10
/// levels: 0.65% off at valence 5, 0.47% at 3, below 0.02% elsewhere).
inline constexpr double kCurvatureGrowthRelative = 0.02;

// ---- Limit behaviour: spectra and convergence rates.

/// A published spectrum and the eigenvalues of core's local matrix agree to this (absolute;
/// eigenvalues lie in [0, 1]): an eigen-solve of a matrix of size at most 41 with O(1)
/// entries is accurate to ~1e-15, a wrong weight moves an eigenvalue by 1e-3 and more.
inline constexpr double kSpectrumAgreement = 1e-12;
/// The centre of a fan converges at the rate of the largest rotation-invariant eigenvalue
/// below 1. For Loop that block has one such eigenvalue and the fit is exact; Catmull-Clark's
/// has two (lambda_v and a smaller one), whose mixture moves the 7-step geometric mean by
/// up to (lambda_3 / lambda_v)^k-weighted terms: measured below 0.3% for n = 3..12. 1% tells
/// the governing eigenvalue from the next one (they differ by 20% and more).
inline constexpr double kConvergenceRateRelative = 0.01;
/// Two eigenvalues of a local subdivision matrix count as one (a multiplicity) within this:
/// the matrix has size at most 2n+1 with O(1) weights, so the solver's error is ~1e-15, while
/// distinct eigenvalues of the published spectra lie 1e-3 and more apart.
inline constexpr double kEigenvalueMultiplicity = 1e-9;

// ---- Limit positions and normals against OpenSubdiv.

/// Core's limit positions agree with OpenSubdiv's when they differ by at most this times the
/// bounding-box diagonal: both apply one mask of up to 2n+1 terms to positions that already
/// agree to ~1e-16 of the diagonal after the levels; 1e-12 is the bar and 1e4 times
/// above what rounding makes.
inline constexpr double kLimitAgreementRelative = 1e-12;
/// Interior limit normals agree to this angle (radians): both are cross products of tangent
/// masks that differ by a scale per tangent (OpenSubdiv normalizes its masks differently),
/// which moves the direction by rounding only, a few ulps of the tangents' conditioning.
inline constexpr double kLimitNormalRad = 1e-10;
/// OpenSubdiv's LimitFaceVarying weighs a value of a vertex whose face-varying topology does
/// not match its vertex (a seam's crease value) with float constants, 1.0f/6.0f and 2.0f/3.0f
/// (PrimvarRefinerReal::limitFVar), even when it computes in double: each weight is off by up
/// to 2^-25 of itself, so such a limit value by up to 2^-25 of the largest |value| it sums
/// (the weights sum to 1; measured 4.4e-8 on values of magnitude 3). Limit texture coordinates
/// agree within this times the channel's largest |value|, or within kLimitAgreementRelative
/// of the UV box, whichever is larger: twice the bound, and 1e4 times below what a rule moves.
inline constexpr double kFarFloatLimitWeight = 0x1p-24;

// ---- Limit surface evaluation (Bfr).

/// Bfr on a regular face (one bicubic or quartic box-spline patch) against core's limit
/// masks: both are exact, a patch evaluation of 16 or 12 points and a mask of up to 2n+1
/// terms; 1e-12 of the diagonal is the limit comparison's bar (kLimitAgreementRelative).
inline constexpr double kBfrRegularRelative = 1e-12;

// ---- Butterfly properties.

/// Plane residual relative to the diagonal: each level sums at most ~2K+2 terms of O(1)
/// weights (K the largest valence), a few ulps each; 1e-13 leaves room for three levels of
/// pole-64 and is ten orders below what a non-affine stencil would leave.
inline constexpr double kPlaneReproduction = 1e-13;

// ---- Vertex normals.

/// Two unit normals "match" below this angle. Both are normalized sums of at most a few dozen
/// products, each a few ulps off, so rounding alone stays near 1e-14 rad; 1e-9 rad leaves room
/// for sums that nearly cancel, and is still 1e6 times below any weighting difference that
/// a real mesh shows (those start near 1e-3 rad).
inline constexpr double kNormalMatchRad = 1e-9;

}  // namespace crossdiv::tolerances
