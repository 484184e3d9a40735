#pragma once
/// @file
/// One Loop comparison end to end: refine with core, run each reference isolated, match
/// vertices, compare every level, and classify each divergence by measurement.

#include <nlohmann/json.hpp>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/comparisons/divergence_view.h"
#include "crossdiv/verification/harness/tier.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/comparisons/rule_identification.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {


struct LoopComparisonRequest {
    LoopOptions options{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    int levels = 1;
    std::vector<std::string> references;  ///< names; all built ones when empty
    bool without_references = false;      ///< run none (a subject measured against core's named rules alone)
    double timeout_seconds = 120;
    bool isolate = true;
    Tier tier = Tier::Weak;
    double tolerance = tolerances::kAgreementRelative;  ///< relative to the diagonal (Weak, Geometric)
    /// The implementation under test: core when null, else (a program, result files) its
    /// refinement is matched to core's, renumbered into core's numbering, and compared with
    /// each reference in core's place; its rule is identified (rule_identification.h).
    const Implementation* subject = nullptr;
    /// Keep, when some reference diverges, every level of the implementation under test with
    /// each reference's positions (the report's 3D view), if the last level has at most this
    /// many faces.
    int view_max_faces = 0;
};

/// The outcome of one reference on one input.
struct ReferenceRun {
    std::string reference, version;
    LoopOptions ran_with{LoopWeights::Loop, LoopBoundary::EdgeOnly};  ///< the options the reference was run with (closest it has)
    RunOutcome outcome;
    Correspondence correspondence;
    MeshComparison comparison;             ///< last level
    std::vector<double> level_max_rel;     ///< max relative error at levels 1..N
    /// "agree", "diverge", "ref-rejected", "ref-crashed" (also threw and timeout).
    Verdict verdict = Verdict::Agree;
    /// For "diverge", from measurement: "weight-family", "corner-rule",
    /// "weight-family+corner-rule" (core rerun with the reference's rule agrees), "rounding"
    /// (within tolerances::kRoundingUlps of the coordinates), "topology" (refined
    /// connectivity differs), "isolated-vertex-handling" (only vertices without faces
    /// differ), "ambiguous-correspondence" (same counts, but vertices cannot be
    /// matched one to one), or "unexplained". For "ours-rejected": the input-handling class
    /// ("non-manifold-handling", "orientation-handling", "degenerate-face-handling").
    DivergenceClass divergence_class = DivergenceClass::None;
    std::string explanation;  ///< one sentence with the measured figures
    double hausdorff_rel = NAN;  ///< vertex-set Hausdorff distance / diagonal (Geometric tier)
};

/// The vertex where some reference parts most from core, with every implementation's value
/// there (a reference without a vertex correspondence has none).
struct CaseWorstVertex {
    int ours_index = -1;
    int valence = 0;
    bool boundary = false;
    Vec3 core;  ///< the implementation under test's value (core's, or the subject's)
    std::optional<Vec3> core_with_requested_rule;  ///< core's value there, when a subject is under test
    std::map<std::string, Vec3> reference_positions;
};

struct LoopComparison {
    std::string input;
    int input_vertices = 0, input_faces = 0;
    LoopOptions options{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    int levels = 0;
    double core_seconds = 0;
    Tier tier = Tier::Weak;
    double tolerance = tolerances::kAgreementRelative;
    std::string core_error;  ///< non-empty: core refused the input (the message)
    /// The implementation under test ("core", or the subject's name) and, for a subject, how
    /// its run ended (no runs against references when it failed), how its vertices were
    /// matched to core's, and the rules it follows.
    std::string subject = "core";
    RunOutcome subject_outcome;
    Correspondence subject_match;
    std::optional<RuleIdentification> rules;
    std::vector<ReferenceRun> runs;
    std::optional<CaseWorstVertex> worst_vertex;  ///< when some reference diverges
    std::optional<DivergenceView> view;           ///< when some reference diverges (LoopComparisonRequest::view_max_faces)
    bool all_agree() const;
    /// The subject failed (crashed, hung, wrote nothing or something that is not a Loop mesh)
    /// or cannot be matched to core's refinement.
    bool subject_failed() const { return subject_outcome.status != RunStatus::Ok || !subject_unmatched.empty(); }
    std::string subject_unmatched;  ///< why the subject's vertices match none of core's, when they do not
};

/// Runs the comparison. @throws InputError if core cannot refine the input (bad mesh) or a
/// reference name is unknown; reference failures are recorded, never thrown.
LoopComparison compare_loop(const TriMesh& input, const std::string& name, const LoopComparisonRequest& request);

/// For an input core refuses (`core_error`, its message): runs each reference anyway and
/// records what it does (verdict "ours-rejected", with the class of input handling when the
/// reference made a mesh of it, or its own failure).
LoopComparison compare_loop_refused(const TriMesh& input, const std::string& name, const LoopComparisonRequest& request,
                                    const std::string& core_error);

/// The comparison as JSON (schema in reports/results-schema.md).
nlohmann::json to_json(const LoopComparison& c);

}  // namespace crossdiv::verification
