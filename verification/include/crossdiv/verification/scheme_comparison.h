#pragma once
/// @file
/// The comparison of the polygon schemes (Catmull-Clark, Doo-Sabin, sqrt3, the Butterflies) with
/// every reference that has them: refine with core, run each reference isolated, match
/// vertices by position, compare the last level, and classify a divergence by re-running core
/// with the rule the reference is documented to use. Loop keeps its own, richer comparison
/// (loop_comparison.h), which matches vertices level by level through provenance.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/doo_sabin_mask.h"
#include "crossdiv/subdiv/sqrt3_mask.h"
#include "crossdiv/verification/compare.h"
#include "crossdiv/verification/correspondence.h"
#include "crossdiv/verification/isolate.h"
#include "crossdiv/verification/tolerances.h"

namespace crossdiv::verification {

/// The polygon schemes compared here (Loop has loop_comparison.h).
enum class Scheme { CatmullClark, DooSabin, Sqrt3, Butterfly, ModifiedButterfly };

/// "catmull-clark", "doo-sabin", "sqrt3", "butterfly", "modified-butterfly".
const char* to_string(Scheme scheme);
/// @throws InputError naming the unknown scheme and the known ones.
Scheme scheme_from_string(const std::string& name);
/// Every scheme, in the order above.
std::vector<Scheme> all_schemes();

/// The named variant of each scheme; only the member of the scheme at hand is read. The
/// Butterflies have none (the variant is the scheme).
struct SchemeRule {
    CatmullClarkOptions catmull_clark{CatmullClarkBoundary::EdgeOnly};
    DooSabinOptions doo_sabin{DooSabinBoundary::ChaikinBoundary};
    Sqrt3Options sqrt3{Sqrt3Parity::CountFromInput};
};
/// The rule's name for `scheme` ("edge-only", "chaikin-boundary", "count-from-input"; "-"
/// for the Butterflies).
std::string rule_name(Scheme scheme, const SchemeRule& rule);
/// Whether the two rules are the same variant of `scheme`.
bool same_rule(Scheme scheme, const SchemeRule& a, const SchemeRule& b);

/// Core's refinement of `mesh` by `scheme` under `rule`.
/// @throws InputError as the scheme's *_subdivide (naming the element).
PolyMesh subdivide(Scheme scheme, const SchemeRule& rule, const PolyMesh& mesh, int levels);

/// The references that have `scheme` in this build (names as `--against` takes them).
std::vector<std::string> scheme_reference_names(Scheme scheme);

struct SchemeRequest {
    Scheme scheme = Scheme::CatmullClark;
    SchemeRule rule;
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
    /// For "diverge", by measurement: "rounding" (same faces, within tolerances::kRoundingUlps
    /// of the coordinates); the rule the reference applies, when core re-run with it agrees
    /// within the tolerance in faces and positions: "boundary-rule", "corner-rule" (both
    /// Catmull-Clark), "border-faces-dropped" (Doo-Sabin), "parity" (sqrt3's boundary
    /// generations); "valence-limit" (the reference's weight table is shorter than the input's
    /// largest valence, and at level 1 exactly the vertices beyond it differ); "topology" (no
    /// vertex bijection or different faces), or "unexplained".
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
