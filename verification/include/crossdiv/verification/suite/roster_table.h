#pragma once
/// @file
/// The class table of a suite run with subjects (a manifest's `subject` or `subjects`
/// statements): one row per subject and scheme, its verdict over every case it ran, the rule it
/// follows, its failures by outcome and its first failing case shrunk to a minimal input. Made
/// from the case records, so a merged run's table is the same as a whole one's.

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/verification/suite/case_record.h"

namespace crossdiv::verification {

/// What a subject is over the cases of one scheme.
enum class RosterVerdict {
    Pass,       ///< ran on every case and follows the rule each case names
    OtherRule,  ///< ran on every case and follows a named rule on each, another than the case names
    Fail,       ///< failed to run on a case, or follows no named rule on one
};
/// "pass", "other-rule", "fail".
const char* to_string(RosterVerdict verdict);

struct RosterRow {
    std::string roster;   ///< the `subjects` statement's name ("" for a `subject` statement)
    std::string subject;  ///< the subject's name (a roster's: its folder's)
    std::string scheme;
    int cases = 0;        ///< cases of this scheme it was put in
    int ran = 0;          ///< cases where it ran and was matched to core
    /// How it failed, by the run status or "unmatched", with the cases of each.
    std::map<std::string, int> failures;
    std::string first_failure;  ///< the first failure's message
    /// The named rules it follows (the case's own first), each with the cases where it does.
    std::vector<std::pair<std::string, int>> rules;
    int no_rule = 0;                        ///< cases where it ran and no named rule fits
    std::vector<std::string> unfit_classes; ///< vertex classes no named rule fits, where none does
    std::string other_scheme;               ///< what it is at level 1 where no rule of its scheme fits
    std::string match;                      ///< how its vertices were matched (the last case's method)
    std::string asked;                      ///< the rule the cases name
    int unexplained = 0;                    ///< reference runs that diverge from it unexplained
    std::string failing_case;               ///< the id of the first case it fails
    std::string failing_input;              ///< that case's input
    /// That case shrunk with the subject alone (suite/failure_shrink.h): the minimal mesh's
    /// path in the output folder, its faces and the symptom it keeps; or why it was not shrunk.
    std::string minimal_input, minimal_symptom, minimal_note;
    int minimal_faces = 0;
    RosterVerdict verdict = RosterVerdict::Pass;
    /// The named rule it follows where it follows one: another than asked when it has one, else
    /// the asked one; "" when it follows none.
    std::string followed_rule() const;
    /// One line: "crashed on 4 of 4 inputs: signal 11 ...", "weights=warren boundary=edge-only
    /// on 4 of 4 inputs (the cases name weights=loop boundary=edge-only)".
    std::string diagnosis() const;
};

/// The rows of every subject in the records (cases without a subject are skipped), in the
/// order the subjects first appear.
std::vector<RosterRow> roster_table(const std::vector<CaseRecord>& cases);

/// The rows as results.json's "roster" holds them (roster.csv and junit.xml: outputs.h).
nlohmann::json to_json(const std::vector<RosterRow>& rows);

}  // namespace crossdiv::verification
