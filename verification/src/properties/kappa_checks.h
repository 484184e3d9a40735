#pragma once
/// @file
/// The checks of a kappa-curve record and the study of its hard cases, for the curves
/// operation. Each property the construction promises is measured on the converged curve,
/// independently of the iteration that built it: the point on its piece, the speed minimum
/// (|curvature| maximum) of the piece at the point, parallel tangents at the joints, and
/// equal |curvature| on both sides of every joint (signed curvature flips at inflections).

#include <nlohmann/json.hpp>
#include <string>

#include "crossdiv/curves/curve_record.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// Appends the checks of a kpc record to `report` and returns its row of the report's
/// kappa-curve table: the points, the pieces, the curve (`uniform`, its tessellation) and its
/// signed curvature along the parameter, the residual of every iteration and each measured
/// property. Reads the reader's solution (CurveRecord::kappa) when there is one.
/// @throws InputError as converged_kappa_curve.
nlohmann::json check_kappa_record(const CurveRecord& record, const std::string& label, const Polyline& uniform,
                                  CheckReport& report);

/// The iteration on families of hard cases (spikes of decreasing angle, points closer and
/// closer to a line, a spike with a close back point): iterations, convergence, contraction
/// and the measured properties per case, converged or not. A table, not checks: it shows
/// where the iteration becomes slow or ill-conditioned.
nlohmann::json kappa_hard_case_study();

}  // namespace crossdiv::verification
