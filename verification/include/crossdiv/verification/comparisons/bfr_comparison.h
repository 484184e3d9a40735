#pragma once
/// @file
/// OpenSubdiv's Bfr limit-surface evaluation at (u, v) against exact limit positions. Bfr
/// represents a face next to an extraordinary vertex approximately (its documentation: an
/// irregular face is a piecewise patch approximation, exact only at the corners' limit
/// points). The exact limit at dyadic parameters is known without Bfr: the point (u, v) =
/// (i/2, j/2) of a face is a vertex of core's level 1, whose limit position core computes
/// with the limit masks (limit.h). So the approximation is measured, not assumed.
///
/// Points per face: Loop (triangles) the 3 corners and 3 edge midpoints; Catmull-Clark (quads
/// only: Bfr parameterizes other polygons by sub-faces) the 4 corners, 4 edge midpoints and
/// the centre. Boundary rule edge-only, Loop's weights.

#include <nlohmann/json.hpp>
#include <string>

#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

struct BfrComparison {
    std::string input, scheme;  ///< scheme: "loop" or "catmull-clark"
    std::string error;          ///< non-empty: core or Bfr refused the input
    int regular_faces = 0, irregular_faces = 0, skipped_faces = 0;  ///< skipped: not a quad (Catmull-Clark)
    /// Largest distance from Bfr to the exact limit, relative to the diagonal: on regular
    /// faces; on irregular faces at the corners (Bfr's documented exact points) and at the
    /// edge midpoints and centre (its approximation).
    double max_regular = 0, max_irregular_corner = 0, max_irregular_inner = 0;
};

/// Compares Bfr with core's exact limit at the dyadic points of level 1 of every face.
BfrComparison compare_bfr_limit(const PolyMesh& input, const std::string& name, const std::string& scheme);

nlohmann::json to_json(const BfrComparison& c);

}  // namespace crossdiv::verification
