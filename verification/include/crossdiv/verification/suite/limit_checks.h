#pragma once
/// @file
/// The suite's `limits` operation: the schemes and limit behaviour of issue 6 as lists of
/// measured checks (the record format of curve_checks.h), one input per study:
///   limits:catmull-clark  core against OpenSubdiv, OpenMesh, CGAL on the bundled and polygon
///                         meshes, both OpenSubdiv boundary rules, 2 levels; each divergence classified
///   limits:schemes        Doo-Sabin (CGAL), sqrt3 (OpenMesh, CGAL; per level and in one call, 3
///                         levels) and the modified Butterfly (OpenMesh) on the same meshes, and the
///                         Butterfly properties (interpolation, planes, published stencil), both variants
///   limits:opensubdiv     limit positions and interior normals against OpenSubdiv's Limit()
///                         (Loop on bundled:all, Catmull-Clark on polygons:all and bundled:all), and
///                         Bfr's (u, v) evaluation against core's exact limit (bfr_comparison.h)
///   limits:spectrum       the eigen table, valence 3..20, Loop, Warren, Catmull-Clark
///   limits:convergence    the convergence table, valence 3..12, levels 1..8

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace crossdiv::tolerances {
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
}  // namespace crossdiv::tolerances

namespace crossdiv::verification {

/// @throws InputError for a name other than the five above (or "limits:all").
std::vector<std::string> expand_limit_inputs(const std::vector<std::string>& specs);

/// Runs one study; the record has "input", "scheme" ("limits"), "runs" (one measured check
/// each, verdict agree/diverge with divergence_class) and "tables" (the full rows).
nlohmann::json check_limits(const std::string& input);

}  // namespace crossdiv::verification
