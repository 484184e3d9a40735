#pragma once
/// @file
/// The time of our curve evaluation (de Casteljau: position, first and second derivative in
/// one pass) against the spline reference's (Eigen's Cox-de Boor) at the same parameters.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "crossdiv/curves/curve_record.h"

namespace crossdiv::verification {

struct CurveTiming {
    std::string curve, reference;
    int degree = 0;
    size_t evaluations = 0;
    double core_ms = 0, reference_ms = 0;  ///< medians of `repeats` runs after one warm-up
    double checksum = 0;                   ///< of the values, so that no evaluation is optimised away
};

/// Times a uniform B-spline or Bezier record at 1000 parameters per segment; nothing for
/// other records or when this build has no spline reference.
std::optional<CurveTiming> time_curve_evaluation(const CurveRecord& record, const std::string& label, int repeats);

nlohmann::json to_json(const CurveTiming& t);

}  // namespace crossdiv::verification
