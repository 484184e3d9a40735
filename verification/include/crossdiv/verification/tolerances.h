#pragma once
/// @file
/// Every tolerance of the harness, each with its reason. Distances are relative to the
/// bounding-box diagonal of the refined mesh, so they mean the same on any mesh scale.

namespace crossdiv::tolerances {

/// Two Loop refinements agree when the largest vertex distance is at most this times the
/// bounding-box diagonal. Each level forms sums of up to n+1 terms with weights below 1, so
/// rounding grows by a few ulps per level; 1e-12 leaves a margin of ~4500 ulps of the diagonal
/// for three levels and orders of magnitude above what a different rule would move
/// (a weight-family or boundary-rule difference moves vertices by 1e-3 of the diagonal and up).
inline constexpr double kAgreementRelative = 1e-12;

}  // namespace crossdiv::tolerances
