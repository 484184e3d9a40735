#pragma once
/// @file
/// The comparison of the polygon schemes (Catmull-Clark; more as they land in core) with
/// every reference that has them: refine with core, run each reference isolated, match
/// vertices by position, compare the last level, and classify a divergence by re-running core
/// with the rule the reference is documented to use. Loop keeps its own, richer comparison
/// (loop_comparison.h), which matches vertices level by level through provenance.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/verification/compare.h"
#include "crossdiv/verification/correspondence.h"
#include "crossdiv/verification/isolate.h"
#include "crossdiv/verification/tolerances.h"

namespace crossdiv::verification {

/// The schemes compared here.
enum class Scheme { CatmullClark };

/// "catmull-clark". 
const char* to_string(Scheme scheme);
/// @throws InputError naming the unknown scheme and the known ones.
Scheme scheme_from_string(const std::string& name);

struct SchemeRequest {
    Scheme scheme = Scheme::CatmullClark;
    CatmullClarkOptions catmull_clark{CatmullClarkBoundary::EdgeOnly};
    int levels = 1;
    std::vector<std::string> references;  ///< names; every one that has the scheme when empty
    double timeout_seconds = 120;
    bool isolate = true;
    double tolerance = tolerances::kAgreementRelative;  ///< relative to our diagonal
};

/// One reference on one input.
struct SchemeReferenceRun {
    std::string reference, version;
    std::string rule;  ///< the rule the reference applies, in our names ("edge-only", ...)
    RunOutcome outcome;
    Correspondence correspondence;
    MeshComparison comparison;  ///< our requested rule against the reference, last level
    /// "agree", "diverge", "ref-rejected", "ref-crashed" (also threw and timeout).
    std::string verdict;
    /// For "diverge", by measurement: "boundary-rule" or "corner-rule" (core re-run with the
    /// reference's rule agrees within the tolerance), "rounding" (within
    /// tolerances::kRoundingUlps of the coordinates), "topology" (no vertex bijection or
    /// different faces), or "unexplained".
    std::string divergence_class;
    std::string explanation;  ///< one sentence with the measured figures
    double max_rel_with_reference_rule = NAN;  ///< core re-run with the reference's rule
};

struct SchemeComparison {
    std::string input;
    Scheme scheme = Scheme::CatmullClark;
    std::string rule;  ///< our requested rule
    int levels = 0;
    int input_vertices = 0, input_faces = 0;
    double core_seconds = 0;
    std::string core_error;  ///< non-empty: core refused the input (the message)
    std::vector<SchemeReferenceRun> runs;
    bool all_agree() const;
};

/// Runs the comparison. Core's refusal is recorded in core_error (the references still run,
/// with verdicts about what they did); reference failures are recorded, never thrown.
/// @throws InputError for an unknown reference name.
SchemeComparison compare_scheme(const PolyMesh& input, const std::string& name, const SchemeRequest& request);

/// One reference's refinement of `mesh` under `request` (scheme, rule, levels), through the same
/// table compare_scheme uses; `rule` receives the rule the reference applies (its closest).
/// @throws InputError when `name` is not built or lacks the scheme; adapters::Rejected as the adapter.
adapters::LevelTrace run_scheme_reference(const std::string& name, const SchemeRequest& request, const PolyMesh& mesh,
                                          std::string& rule);

nlohmann::json to_json(const SchemeComparison& c);

}  // namespace crossdiv::verification
