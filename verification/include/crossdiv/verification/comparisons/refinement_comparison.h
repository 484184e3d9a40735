#pragma once
/// @file
/// The one comparison of refinements, for every scheme: refine the input with the
/// implementation under test (core, or a subject in core's place), run each reference that
/// has the scheme isolated, match their vertices, compare every level that can be matched,
/// and classify each divergence by measurement on the one ladder of classification.h.
///
/// What differs per scheme is read from its traits (scheme_traits.h): a primal scheme's
/// levels are matched level by level through provenance, so that positions play no part in
/// the match and every level's error is measured; a dual scheme's (Doo-Sabin, sqrt3) last
/// level by position and faces. The rule a reference applies comes from its declared
/// capabilities (closest_rule), and the ladder re-runs core with it to measure what it
/// explains.

#include <nlohmann/json.hpp>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/mesh_statistics.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/comparisons/divergence_view.h"
#include "crossdiv/verification/comparisons/rule_identification.h"
#include "crossdiv/verification/comparisons/face_varying_rule_identification.h"
#include "crossdiv/verification/harness/corner_values.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/tier.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/implementations/implementation.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// Core's refinement of `mesh` by `scheme` under `rule` (its last level), through core's
/// implementation. @throws InputError as the scheme's *_subdivide (naming the element).
PolyMesh subdivide(Scheme scheme, const SchemeRule& rule, const PolyMesh& mesh, int levels);

struct RefinementRequest {
    Scheme scheme = Scheme::Loop;
    SchemeRule rule;
    int levels = 1;
    /// Names; when empty, every one that has the scheme (those with crease rules, for an
    /// input with crease, corner or hole tags).
    std::vector<std::string> references;
    bool without_references = false;  ///< run none (a subject measured against core's named rules alone)
    double timeout_seconds = 120;
    bool isolate = true;
    /// How close is close enough. The tolerance is the weak and geometric tiers' bar, and the
    /// bar of the classification ladder in every tier (a rule explains a divergence when core
    /// with that rule agrees within it); a reference that computes in float is held to the
    /// float tier (weak, tolerances::kFloatAgreementUlps) whatever the tier.
    Tier tier = Tier::Weak;
    double tolerance = tolerances::kAgreementRelative;  ///< relative to the diagonal
    /// The implementation under test: core when null, else (a program, result files, a
    /// callback) its refinement is matched to core's, renumbered into core's numbering, and
    /// compared with each reference in core's place; its Loop rule is identified
    /// (rule_identification.h), for every scheme.
    const Implementation* subject = nullptr;
    /// Keep, when some reference diverges, every level of the implementation under test with
    /// each matched reference's positions (the report's 3D view), if its last level has at
    /// most this many faces.
    int view_max_faces = 0;
    /// Core's refusals the case declares expected, by the input handling they show
    /// (input_handling_class: a manifest's refuses=non-manifold-handling,...): a refusal of an
    /// input a reference refines is ours-rejected of its class when declared, and a failure
    /// (ours-rejected, class unexplained) when not: core refusing what it used to take is a
    /// regression like any other.
    std::vector<DivergenceClass> expected_refusals;
    /// Refine and compare the input's face-varying channels (texture coordinates) under this
    /// rule, beside the positions (RefinementRun::uv); unset: positions only.
    std::optional<FaceVaryingRule> face_varying;
};

/// The face-varying values (texture coordinates) of one run against the implementation under
/// test's, corner by corner (harness/corner_values.h), in the request's tier: a verdict of its
/// own beside the positions'.
struct FaceVaryingRun {
    /// Why nothing was compared ("" when compared): the reference refines no face-varying
    /// data, the positions could not be matched, a side gave no values.
    std::string not_compared;
    CornerValueComparison comparison;
    /// agree, or diverge with class fvar-rule (one side follows another of the six rules:
    /// core re-run with that rule agrees with it) or unexplained (a failure).
    Outcome outcome;
    std::optional<FaceVaryingRule> follows;  ///< for fvar-rule: the rule that side follows
    std::string who_follows;                 ///< that side: the reference's name or the implementation under test's
    std::string worst_class;                 ///< the UV-vertex class of the worst corner (to_string(UvVertexClass))
    std::string explanation;                 ///< one sentence with the measured figures
    bool compared() const { return not_compared.empty(); }
};

/// One reference on one input.
struct RefinementRun {
    std::string reference, version;
    SchemeRule ran_with;  ///< the rule the reference applied (the closest it has to the request)
    std::string rule;     ///< its name (rule_name): "weights=loop boundary=edge-only", "midpoint-average", ...
    RunOutcome outcome;
    Correspondence correspondence;
    MeshComparison comparison;          ///< the requested rule against the reference, last level
    std::vector<double> level_max_rel;  ///< max relative error at each level matched (all of 1..N through provenance)
    Verdict verdict = Verdict::Agree;
    /// For "diverge", the first rung of the ladder that holds (classification.h); for
    /// "ours-rejected", the input handling the reference shows (input_handling_class).
    DivergenceClass divergence_class = DivergenceClass::None;
    std::string explanation;                   ///< one sentence with the measured figures
    double max_rel_with_reference_rule = NAN;  ///< core re-run with the reference's rule, last level
    double hausdorff_rel = NAN;                ///< geometric tier: vertex-set Hausdorff distance / diagonal
    std::optional<FaceVaryingRun> uv;          ///< when the request refines face-varying data
};

/// The vertex where some reference parts most from the implementation under test, with every
/// implementation's value there (a reference without a vertex correspondence has none).
struct CaseWorstVertex {
    int ours_index = -1;
    int valence = 0;
    bool boundary = false;
    Vec3 core;  ///< the implementation under test's value (core's, or the subject's)
    std::optional<Vec3> core_with_requested_rule;  ///< core's value there, when a subject is under test
    std::map<std::string, Vec3> reference_positions;
};

struct RefinementComparison {
    std::string input;
    Scheme scheme = Scheme::Loop;
    SchemeRule rule;        ///< the requested rule
    std::string rule_name;  ///< its name
    int levels = 0;
    Tier tier = Tier::Weak;
    double tolerance = NAN;
    int input_vertices = 0, input_faces = 0;
    /// What the input is made of (mesh_statistics.h): the corpus statistics beside the
    /// robustness table.
    MeshStatistics input_statistics;
    double core_seconds = 0;
    std::string core_error;          ///< non-empty: core refused the input (the message)
    std::vector<std::string> notes;  ///< how the references were chosen, when not as asked
    /// The implementation under test ("core", or the subject's name) and, for a subject, how
    /// its run ended (no runs against references when it failed), how its vertices were
    /// matched to core's, and the rules it follows.
    std::string subject = "core";
    RunOutcome subject_outcome;
    Correspondence subject_match;
    std::string subject_unmatched;  ///< why the subject's vertices match none of core's, when they do not
    /// How the subject's faces differ from core's (its vertices matched), naming the first face
    /// only in each, when they do: a failure, as a crash is.
    std::string subject_topology;
    std::optional<RuleIdentification> rules;
    /// The face-varying rule the subject's texture coordinates follow, class by class of UV
    /// vertex, when the request compares them and the subject gave them.
    std::optional<FaceVaryingIdentification> uv_rules;
    std::vector<RefinementRun> runs;
    std::optional<CaseWorstVertex> worst_vertex;  ///< when some reference diverges
    std::optional<DivergenceView> view;           ///< see RefinementRequest::view_max_faces
    std::optional<FaceVaryingRule> face_varying;  ///< the face-varying rule asked for, when the input has channels
    /// Some reference ran, and every one agrees, in positions and, where compared, in
    /// face-varying values (false when core refused the input).
    bool all_agree() const;
    /// The subject failed (crashed, hung, wrote nothing or something that is not a mesh of
    /// the scheme) or cannot be matched to core's refinement.
    bool subject_failed() const {
        return subject_outcome.status != RunStatus::Ok || !subject_unmatched.empty() || !subject_topology.empty();
    }
};

/// Runs the comparison. Core's refusal is recorded in core_error (the references still run,
/// with verdicts about what they did); reference failures are recorded, never thrown.
/// @throws InputError for an unknown reference name.
RefinementComparison compare_refinement(const PolyMesh& input, const std::string& name, const RefinementRequest& request);

/// The comparison as JSON (schema in reports/results-schema.md).
nlohmann::json to_json(const RefinementComparison& c);

}  // namespace crossdiv::verification
