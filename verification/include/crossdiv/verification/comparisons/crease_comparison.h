#pragma once
/// @file
/// Creases (Loop and Catmull-Clark) against OpenSubdiv, the only reference with crease
/// rules: the one comparison (refinement_comparison.h) of core and Far on the same tagged
/// mesh under the same creasing method, every level matched through provenance and measured,
/// and how far the tags move the surface (so that agreement tests the sharp rules, not the
/// smooth ones). OpenMesh and CGAL refuse a tagged mesh (adapters::reject_crease_tags) rather
/// than answer a smooth question.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

struct CreaseRequest {
    Scheme scheme = Scheme::CatmullClark;  ///< Loop or Catmull-Clark, the schemes with crease rules
    CreaseMethod method = CreaseMethod::Uniform;
    bool edge_and_corner = false;  ///< the boundary rule: edge-and-corner, else edge-only
    int levels = 3;
    double timeout_seconds = 60;
    bool isolate = true;
    double tolerance = tolerances::kAgreementRelative;  ///< relative to our diagonal
};

struct CreaseComparison {
    std::string input;
    Scheme scheme = Scheme::CatmullClark;
    std::string method;
    int levels = 0;
    int edge_tags = 0, vertex_tags = 0, hole_tags = 0;
    std::string core_error;  ///< non-empty: core refused the mesh (the message)
    /// "agree", "diverge", "ours-rejected", "ref-rejected", "ref-crashed".
    Verdict verdict = Verdict::Agree;
    DivergenceClass divergence_class = DivergenceClass::None;  ///< the comparison's class for "diverge"
    std::string explanation;
    std::vector<double> max_rel_per_level;  ///< levels 1..N; the last is max_rel
    double max_rel = NAN;
    bool faces_equal = false;  ///< at every level, under the matching
    /// How far creases moved the surface: the largest distance between the tagged and the
    /// untagged refinement at the last level, over the diagonal (0 would mean the tags did
    /// nothing, and the check would not test them).
    double effect_of_tags = NAN;
};

/// Refines `mesh` (its tags) with core and with OpenSubdiv and compares every level.
/// Failures of either side are recorded, never thrown.
CreaseComparison compare_creases(const PolyMesh& mesh, const std::string& name, const CreaseRequest& request);

/// The whole crease catalog (datasets::crease_meshes): Catmull-Clark on every mesh, Loop on
/// the triangle meshes, each under uniform and Chaikin decay, three levels.
std::vector<CreaseComparison> compare_crease_catalog();

nlohmann::json to_json(const CreaseComparison& c);

}  // namespace crossdiv::verification
