#pragma once
/// @file
/// The typed record of one suite job and of each run in it: what the summary, results.csv,
/// JUnit and the progress lines are made from. JSON appears only at the edges: to_json writes
/// a case into results.json (and into a worker's pipe file), case_record_from_json reads it
/// back (the parent from its workers, `crossdiv merge` from shard folders). The field names
/// are documented in reports/results-schema.md.

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// One run of a case: a reference run of a comparison, or one measured check.
struct RunRecord {
    std::string reference;       ///< the implementation or kind of reference it is compared with
    std::string subject, check;  ///< checks: what was checked and which property (empty for comparisons)
    Outcome outcome;
    std::optional<RunStatus> status;  ///< comparisons: how the reference run ended (none for a check)
    double measured = NAN;       ///< comparisons: max distance / diagonal; checks: the measured value
    double rms = NAN;            ///< comparisons: RMS distance / diagonal
    double hausdorff = NAN;      ///< comparisons, geometric tier: vertex-set Hausdorff / diagonal
    double tolerance = NAN;      ///< checks: the bar `measured` must meet
    std::string unit;            ///< checks
    int worst_valence = -1;      ///< comparisons: the valence of the worst vertex (-1: none)
    int worst_boundary = -1;     ///< ... and whether it is on the boundary (1), interior (0), none (-1)
    double seconds = NAN;        ///< the reference's wall time (NaN: not timed)
    std::string explanation;
    /// The rest of the run as the operation reports it (a comparison's match, topology and
    /// positions); to_json writes it with the fields above.
    nlohmann::json detail = nlohmann::json::object();

    bool is_check() const { return !check.empty(); }
    /// "opensubdiv", or for a check "SUBJECT CHECK vs REFERENCE".
    std::string label() const;
};

/// One job of a suite.
struct CaseRecord {
    int job = 0;            ///< index in the whole suite (the same on every machine with the same data)
    std::string id;         ///< "input | operation and its keys"
    int manifest_line = 0;
    std::string input, operation;
    /// The keys of a refinement comparison case (empty / 0 / NaN otherwise): Loop's weights
    /// and boundary rule, or another scheme's rule (its boundary option's name) in `boundary`.
    std::string weights, boundary, tier;
    int levels = 0;
    double tolerance = NAN;
    double core_seconds = NAN;
    /// Wall time of the whole job in its worker (reading the input, every run, isolation,
    /// correspondence, classification, writing its files): what the suite spends beyond the
    /// implementations' own seconds (core_seconds, each run's) is read off it.
    double job_seconds = NAN;
    std::string core_error;    ///< core refused the input (the message)
    bool ours_failed = false;  ///< core crashed or threw internally: a failure of ours
    /// For a case without runs whose input core refused: the input handling the case declares
    /// that refusal as (refuses=invalid-input-handling), else Unexplained, a failure: a file
    /// core used to take, and now refuses, must not pass with its checks gone.
    DivergenceClass refusal = DivergenceClass::Unexplained;
    std::vector<RunRecord> runs;
    /// The rest of the record as the operation reports it (tables, topology, worst vertex).
    nlohmann::json detail = nlohmann::json::object();
};

/// The label the summary counts a run under: "ours-failed" when core failed, else its outcome.
/// The whole number at `key` of `j`, `fallback` when absent. A JSON number that is not whole or
/// does not fit [lo, hi] (1e300 where an int is meant: its conversion would be undefined) is an
/// InputError naming the key, as is a value that is no number.
long long whole_number_field(const nlohmann::json& j, const char* key, long long fallback, long long lo, long long hi);

std::string outcome_label(const CaseRecord& c, const RunRecord& r);
/// The label of a case without runs: "ours-failed" or "ours-rejected (<refusal class>)".
std::string outcome_label(const CaseRecord& c);
/// Whether a run counts as a failure (JUnit, exit status): core failed, or it diverges unexplained.
bool is_failure(const CaseRecord& c, const RunRecord& r);
/// Whether a case without runs counts as a failure: core failed, or refused an input the case
/// does not declare refused.
bool is_failure(const CaseRecord& c);

/// A comparison as a case under the operation named after its scheme (the job's identity is
/// filled in by the runner).
CaseRecord case_record(const RefinementComparison& comparison);
/// The checks of one input (curves, surfaces, a study) as a case.
CaseRecord case_record(const CheckReport& report);
/// A job that made no result: core refused the input (`ours_failed` false) or failed.
CaseRecord failed_case(const std::string& input, const std::string& operation, const std::string& why, bool ours_failed);

/// The case as results.json holds it.
nlohmann::json to_json(const CaseRecord& c);
/// Reads a case written by to_json. @throws InputError when a field has the wrong type.
CaseRecord case_record_from_json(const nlohmann::json& j);

}  // namespace crossdiv::verification
