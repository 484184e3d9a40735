#pragma once
/// @file
/// One Loop comparison end to end: refine with core, run each reference isolated, match
/// vertices, compare every level, and classify each divergence by measurement.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/verification/compare.h"
#include "crossdiv/verification/correspondence.h"
#include "crossdiv/verification/isolate.h"

namespace crossdiv::verification {

struct LoopComparisonRequest {
    LoopOptions options;
    int levels = 1;
    std::vector<std::string> references;  ///< names; all built ones when empty
    double timeout_seconds = 120;
    bool isolate = true;
};

/// The outcome of one reference on one input.
struct ReferenceRun {
    std::string reference, version;
    LoopOptions ran_with;  ///< the options the reference was run with (closest it has)
    RunOutcome outcome;
    Correspondence correspondence;
    MeshComparison comparison;             ///< last level
    std::vector<double> level_max_rel;     ///< max relative error at levels 1..N
    /// "agree", "diverge", "ref-rejected", "ref-crashed" (also threw and timeout).
    std::string verdict;
    /// For "diverge": "weight-family", "boundary-rule", "weight-family+boundary-rule",
    /// "topology" or "unexplained". Empty otherwise.
    std::string divergence_class;
    std::string explanation;  ///< one sentence with the measured figures
};

struct LoopComparison {
    std::string input;
    int input_vertices = 0, input_faces = 0;
    LoopOptions options;
    int levels = 0;
    double core_seconds = 0;
    std::vector<ReferenceRun> runs;
    bool all_agree() const;
};

/// Runs the comparison. @throws InputError if core cannot refine the input (bad mesh) or a
/// reference name is unknown; reference failures are recorded, never thrown.
LoopComparison compare_loop(const TriMesh& input, const std::string& name, const LoopComparisonRequest& request);

/// The comparison as JSON (schema in reports/results-schema.md).
nlohmann::json to_json(const LoopComparison& c);

}  // namespace crossdiv::verification
