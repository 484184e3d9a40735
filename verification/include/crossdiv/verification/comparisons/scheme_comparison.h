#pragma once
/// @file
/// The comparison of the polygon schemes (Catmull-Clark, Doo-Sabin, sqrt3, the Butterflies) with
/// every reference that has them: refine with core, run each reference isolated, match
/// vertices by position, compare the last level, and classify a divergence by re-running core
/// with the rule the reference is documented to use. Loop keeps its own, richer comparison
/// (loop_comparison.h), which matches vertices level by level through provenance.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/comparisons/divergence_view.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/tier.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// Core's refinement of `mesh` by `scheme` under `rule` (its last level).
/// @throws InputError as the scheme's *_subdivide (naming the element).
PolyMesh subdivide(Scheme scheme, const SchemeRule& rule, const PolyMesh& mesh, int levels);

struct SchemeRequest {
    Scheme scheme = Scheme::CatmullClark;
    SchemeRule rule;
    int levels = 1;
    /// Names; when empty, every one that has the scheme (those with crease rules, for an
    /// input with crease, corner or hole tags).
    std::vector<std::string> references;
    double timeout_seconds = 120;
    bool isolate = true;
    /// How close is close enough. The tolerance is the weak and geometric tiers' bar, and the
    /// bar of the classification ladder in every tier (a rule explains a divergence when core
    /// with that rule agrees within it); a reference that computes in float is held to the
    /// float tier (weak, tolerances::kFloatAgreementUlps) whatever the tier.
    Tier tier = Tier::Weak;
    double tolerance = tolerances::kAgreementRelative;  ///< relative to our diagonal
    /// Keep, when some reference diverges, core's levels with each matched reference's last
    /// level (the report's 3D view), if core's last level has at most this many faces.
    int view_max_faces = 0;
};

/// One reference on one input.
struct SchemeReferenceRun {
    std::string reference, version;
    std::string rule;  ///< the rule the reference applies, in our names ("edge-only", ...)
    RunOutcome outcome;
    Correspondence correspondence;
    MeshComparison comparison;  ///< our requested rule against the reference, last level
    /// "agree", "diverge", "ref-rejected", "ref-crashed" (also threw and timeout).
    Verdict verdict = Verdict::Agree;
    /// For "diverge", by measurement: "rounding" (same faces, within tolerances::kRoundingUlps
    /// of the coordinates); the rule the reference applies, when core re-run with it agrees
    /// within the tolerance in faces and positions: "boundary-rule", "corner-rule" (both
    /// Catmull-Clark), "border-faces-dropped" (Doo-Sabin), "parity" (sqrt3's boundary
    /// generations), "wing-rule" (the Butterflies' wing points beyond the boundary);
    /// "valence-limit" (the reference's weight table is shorter than the input's
    /// largest valence, and at level 1 exactly the vertices beyond it differ); "topology" (no
    /// vertex bijection or different faces), or "unexplained".
    DivergenceClass divergence_class = DivergenceClass::None;
    std::string explanation;  ///< one sentence with the measured figures
    double max_rel_with_reference_rule = NAN;  ///< core re-run with the reference's rule
    double hausdorff_rel = NAN;  ///< geometric tier: vertex-set Hausdorff distance / our diagonal
};

struct SchemeComparison {
    std::string input;
    Scheme scheme = Scheme::CatmullClark;
    std::string rule;  ///< our requested rule
    int levels = 0;
    Tier tier = Tier::Weak;
    double tolerance = NAN;
    int input_vertices = 0, input_faces = 0;
    double core_seconds = 0;
    std::string core_error;  ///< non-empty: core refused the input (the message)
    std::vector<std::string> notes;  ///< how the references were chosen, when not as asked
    std::vector<SchemeReferenceRun> runs;
    std::optional<DivergenceView> view;  ///< see SchemeRequest::view_max_faces
    bool all_agree() const;
};

/// Runs the comparison. Core's refusal is recorded in core_error (the references still run,
/// with verdicts about what they did); reference failures are recorded, never thrown.
/// @throws InputError for an unknown reference name.
SchemeComparison compare_scheme(const PolyMesh& input, const std::string& name, const SchemeRequest& request);

nlohmann::json to_json(const SchemeComparison& c);

}  // namespace crossdiv::verification
