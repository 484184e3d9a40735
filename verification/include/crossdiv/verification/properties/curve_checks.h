#pragma once
/// @file
/// The curve checks: each spline of a curve file against Eigen's Splines and against a second
/// algorithm of our own, the analytic properties it must have, continuity at its joints, its
/// frames, and the quality of each tessellation mode; plus the synthetic studies (degrees
/// 1..20, the helix frame convergence). Everything measured lands in results.json through
/// to_json; the suite runs these as its `curves` operation.

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "crossdiv/curves/curve_record.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// One row of the tessellation study: for a distance tolerance, the edge count and measured
/// deviation of each mode (uniform: the fewest equal steps per segment that meet tol, found
/// by search; angle: the largest angle tolerance that meets it; distance: the adaptive mode;
/// wang: the per-segment counts of Wang's formula).
struct TessellationRow {
    std::string curve;
    double tol = 0;  ///< absolute
    int uniform_edges = 0, angle_edges = 0, distance_edges = 0, wang_edges = 0;
    double uniform_dev = 0, angle_dev = 0, distance_dev = 0, wang_dev = 0;
    int uniform_steps = 0;       ///< per segment
    double angle_tol_deg = 0;    ///< the angle tolerance found; 0 when the 10-level cap stops it first
    bool angle_reached = false;
    double optimal_edges = 0;    ///< N*, flattening_estimate: about the fewest edges any polyline on the curve needs
    bool has_wang = false;       ///< Wang's counts were measured (splines: a bound on Bezier control points)
};

/// The study for one curve at each tolerance (absolute): a spline's, or a primitive's against
/// its closed form (primitive_tessellation.h; no Wang counts).
std::vector<TessellationRow> tessellation_study(const CurveRecord& record, const std::string& label,
                                                std::span<const double> tols);

/// A row as results.json and bench.json hold it (wang_edges and wang_dev null without them).
nlohmann::json to_json(const TessellationRow& row);

/// A primitive's size: the bounding-box diagonal of 256 samples.
double primitive_size(const Primitive& p);

/// Frame error against the exact rotation-minimizing frame of a helix.
struct HelixFrameRow {
    int steps = 0;
    double h = 0;  ///< parameter step
    double recursive_error = 0, rmf_error = 0;  ///< max angle (rad) between computed and exact N
};
struct HelixFrameStudy {
    std::vector<HelixFrameRow> rows;
    double recursive_order = 0, rmf_order = 0;  ///< least-squares slope of log error vs log h
};
/// Helix (cos s, sin s, b s), b = 1 / (2 pi), two turns, at 16 .. 1024 steps. The exact RMF
/// normal is the Frenet normal rotated by -tau * arc length (tau = b / (1 + b^2)) toward B.
HelixFrameStudy helix_frame_study();

/// Checks every curve of a file.
CheckReport check_curve_file(const CurveFile& file, const std::string& input);

/// The synthetic studies: de Casteljau vs Bernstein for degrees 1..20, vs Eigen for degrees
/// 1..10 (position, first and second derivative), endpoint interpolation and partition of
/// unity, and the helix frame convergence.
CheckReport check_synthetic();

/// Curve input names: a .swp or .bzc file, `curve:NAME` (bundled), or the collections
/// `curves:bundled`, `curves:course` (../shared/data), `curves:synthetic`.
std::vector<std::string> expand_curve_inputs(const std::vector<std::string>& specs);
/// @throws InputError / ParseError naming file and line. Not for curves:synthetic.
CurveFile load_curve_input(const std::string& spec);

}  // namespace crossdiv::verification
