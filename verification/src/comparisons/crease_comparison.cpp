#include "crossdiv/verification/comparisons/crease_comparison.h"

#include <algorithm>
#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/harness/json_text.h"

namespace crossdiv::verification {
namespace {

/// The rule of the request: Loop's weights (OpenSubdiv's) or Catmull-Clark, the boundary rule
/// and the creasing method.
SchemeRule crease_rule(const CreaseRequest& req) {
    SchemeRule rule;
    const bool corner = req.edge_and_corner;
    rule.loop = {LoopWeights::Loop, corner ? LoopBoundary::EdgeAndCorner : LoopBoundary::EdgeOnly, req.method};
    rule.catmull_clark = {corner ? CatmullClarkBoundary::EdgeAndCorner : CatmullClarkBoundary::EdgeOnly, req.method};
    return rule;
}

}  // namespace

CreaseComparison compare_creases(const PolyMesh& mesh, const std::string& name, const CreaseRequest& req) {
    CreaseComparison c;
    c.input = name;
    c.scheme = req.scheme;
    c.method = std::string(to_string(req.method));
    c.levels = req.levels;
    c.edge_tags = static_cast<int>(mesh.creases.edges.size());
    c.vertex_tags = static_cast<int>(mesh.creases.vertices.size());
    c.hole_tags = static_cast<int>(mesh.creases.holes.size());

    // The one comparison, against the references with crease rules (OpenSubdiv).
    RefinementRequest r;
    r.scheme = req.scheme;
    r.rule = crease_rule(req);
    r.levels = req.levels;
    r.timeout_seconds = req.timeout_seconds;
    r.isolate = req.isolate;
    r.tolerance = req.tolerance;
    for (const Implementation* i : references_for(req.scheme))
        if (i->support(req.scheme)->creases) r.references.push_back(i->name());
    if (r.references.empty()) {
        c.verdict = Verdict::RefRejected;
        c.explanation = "this build has no reference with crease rules (OpenSubdiv)";
        return c;
    }
    r.references.resize(1);
    const RefinementComparison cmp = compare_refinement(mesh, name, r);
    c.core_error = cmp.core_error;
    const RefinementRun& run = cmp.runs.front();
    c.verdict = run.verdict;
    c.divergence_class = run.divergence_class;
    c.explanation = run.explanation;
    if (run.outcome.status != RunStatus::Ok || !c.core_error.empty() || run.correspondence.method == MatchMethod::None)
        return c;
    c.max_rel_per_level = run.level_max_rel;
    c.max_rel = run.comparison.max_rel;
    c.faces_equal = run.comparison.topology_equal();

    // How far the tags move the surface: the tagged against the untagged refinement (the
    // same order: the tags change weights, not topology, at one level).
    PolyMesh untagged = mesh;
    untagged.creases = {};
    const PolyMesh tagged = subdivide(req.scheme, r.rule, mesh, req.levels);
    const PolyMesh smooth = subdivide(req.scheme, r.rule, untagged, req.levels);
    double effect = 0;
    if (smooth.num_vertices() == tagged.num_vertices() && req.levels == 1)
        for (int v = 0; v < smooth.num_vertices(); ++v)
            effect = std::max(effect, (smooth.positions[v] - tagged.positions[v]).norm());
    else
        effect = hausdorff_vertex_sets(smooth.positions, tagged.positions);
    c.effect_of_tags = effect / bounding_box_diagonal(tagged.positions);
    if (c.verdict == Verdict::Agree) {
        char buf[200];
        const std::string holes = c.hole_tags ? ", " + std::to_string(c.hole_tags) + " hole" : std::string();
        const double worst = *std::max_element(c.max_rel_per_level.begin(), c.max_rel_per_level.end());
        std::snprintf(buf, sizeof buf, "%d edge and %d vertex%s tags, %s decay; worst level %.2e of the diagonal; the tags "
                      "move the surface by %.2e", c.edge_tags, c.vertex_tags, holes.c_str(), c.method.c_str(), worst,
                      c.effect_of_tags);
        c.explanation = buf;
    }
    return c;
}

std::vector<CreaseComparison> compare_crease_catalog() {
    std::vector<CreaseComparison> out;
    for (const datasets::BundledMesh& b : datasets::crease_meshes())
        for (Scheme scheme : {Scheme::CatmullClark, Scheme::Loop}) {
            if (scheme == Scheme::Loop && !b.mesh.all_triangles()) continue;
            for (CreaseMethod method : {CreaseMethod::Uniform, CreaseMethod::Chaikin}) {
                CreaseRequest req;
                req.scheme = scheme;
                req.method = method;
                out.push_back(compare_creases(b.mesh, "bundled:" + b.name, req));
            }
        }
    return out;
}

nlohmann::json to_json(const CreaseComparison& c) {
    nlohmann::json levels = nlohmann::json::array();
    for (double x : c.max_rel_per_level) levels.push_back(finite_or_null(x));
    nlohmann::json j = {{"input", c.input},          {"scheme", to_string(c.scheme)}, {"method", c.method},
                        {"levels", c.levels},        {"edge_tags", c.edge_tags},     {"vertex_tags", c.vertex_tags}, {"hole_tags", c.hole_tags},
                        {"verdict", to_string(c.verdict)},      {"max_rel", finite_or_null(c.max_rel)},    {"max_rel_per_level", levels},
                        {"faces_equal", c.faces_equal}, {"effect_of_tags", finite_or_null(c.effect_of_tags)},
                        {"explanation", c.explanation}};
    if (!c.core_error.empty()) j["core_error"] = c.core_error;
    if (c.divergence_class != DivergenceClass::None) j["divergence_class"] = to_string(c.divergence_class);
    return j;
}

}  // namespace crossdiv::verification
