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
