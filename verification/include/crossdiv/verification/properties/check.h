#pragma once
/// @file
/// One measured property check and the checks of one input: the record shape of the curve,
/// surface and limit-behaviour operations (a value measured against a named tolerance, or a
/// count that must be zero).

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/verification/harness/verdict.h"

namespace crossdiv::verification {

/// One measured check: `measured` must not exceed `tolerance` (both in the unit `unit`).
struct Check {
    Check(std::string subject, std::string check, std::string reference, double measured, double tolerance,
          std::string unit, std::string note, std::optional<Outcome> decided = std::nullopt)
        : subject(std::move(subject)), check(std::move(check)), reference(std::move(reference)), measured(measured),
          tolerance(tolerance), unit(std::move(unit)), note(std::move(note)), decided(decided) {}

    std::string subject;    ///< what was checked: a curve's label, a surface, a study's row
    std::string check;      ///< which property: "position", "d1", "continuity-c1", "watertight", ...
    std::string reference;  ///< what it is compared with: "eigen", "bernstein", "analytic", "cgal", ...
    double measured = 0;
    double tolerance = 0;
    std::string unit;  ///< "rel" (of the relevant diagonal), "abs", "rad", "order", "count"
    std::string note;  ///< one line: how it was measured
    /// Set when the outcome is not the measurement's pass or fail: a reference that refused,
    /// a divergence whose class was measured (a comparison run recorded as a check).
    std::optional<Outcome> decided;

    bool pass() const { return measured <= tolerance; }  // NaN fails
    /// `decided`, else agree when it passes and an unexplained divergence when it does not.
    Outcome outcome() const {
        if (decided) return *decided;
        return pass() ? Outcome{Verdict::Agree, DivergenceClass::None} : Outcome{Verdict::Diverge, DivergenceClass::Unexplained};
    }
};

/// A check of a count that must be zero (unit "count").
inline Check count_check(const std::string& subject, const std::string& check, const std::string& reference, double count,
                         const std::string& note) {
    return {subject, check, reference, count, 0, "count", note};
}

/// A measured check, reference first: `measured` against `tolerance` in `unit`.
inline Check measured_check(const std::string& reference, const std::string& name, const std::string& subject,
                            double measured, double tolerance, const std::string& unit, const std::string& note) {
    return {subject, name, reference, measured, tolerance, unit, note, std::nullopt};
}

/// A check whose outcome was decided by a comparison (a refusal, a classified divergence).
inline Check decided_check(const std::string& reference, const std::string& name, const std::string& subject,
                           double measured, double tolerance, const std::string& unit, const std::string& note,
                           Outcome outcome) {
    return {subject, name, reference, measured, tolerance, unit, note, outcome};
}

/// All checks of one input, and the tables of figures they came from.
struct CheckReport {
    std::string input;
    std::string operation = "curves";   ///< the suite operation: "curves", "surfaces" or a study
    std::vector<std::string> subjects;  ///< curve labels or surface names, in input order
    std::vector<Check> checks;
    nlohmann::json tables = nlohmann::json::object();
};

}  // namespace crossdiv::verification
