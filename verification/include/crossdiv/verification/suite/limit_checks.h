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

#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {

/// @throws InputError for a name other than the five above (or "limits:all").
std::vector<std::string> expand_limit_inputs(const std::vector<std::string>& specs);

/// Runs one study; the record has "input", "scheme" ("limits"), "runs" (one measured check
/// each, verdict agree/diverge with divergence_class) and "tables" (the full rows).
nlohmann::json check_limits(const std::string& input);

}  // namespace crossdiv::verification
