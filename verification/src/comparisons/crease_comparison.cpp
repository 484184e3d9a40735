#include "crossdiv/verification/comparisons/crease_comparison.h"
#include "crossdiv/verification/comparisons/classification.h"

#include <algorithm>
#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

LoopOptions loop_options(const CreaseRequest& req) {
    return {LoopWeights::Loop, req.edge_and_corner ? LoopBoundary::EdgeAndCorner : LoopBoundary::EdgeOnly, req.method};
}

CatmullClarkOptions catmull_clark_options(const CreaseRequest& req) {
    return {req.edge_and_corner ? CatmullClarkBoundary::EdgeAndCorner : CatmullClarkBoundary::EdgeOnly, req.method};
}

/// Core's levels 1..N (each level refines the previous one, tags and all).
std::vector<PolyMesh> core_levels(const PolyMesh& mesh, const CreaseRequest& req) {
    std::vector<PolyMesh> out;
    PolyMesh current = mesh;
    for (int l = 0; l < req.levels; ++l) {
        current = req.scheme == Scheme::Loop ? loop_subdivide(current, loop_options(req), 1)
                           : catmull_clark_subdivide(current, catmull_clark_options(req), 1);
        out.push_back(current);
    }
    return out;
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

    std::vector<PolyMesh> ours;
    try {
        ours = core_levels(mesh, req);
        PolyMesh untagged = mesh;
        untagged.creases = {};
        const PolyMesh smooth = core_levels(untagged, req).back();
        const double diag = bounding_box_diagonal(ours.back().positions);
        double effect = 0;  // same order: the tags change weights, not topology, at one level
        if (smooth.num_vertices() == ours.back().num_vertices() && req.levels == 1)
            for (int v = 0; v < smooth.num_vertices(); ++v)
                effect = std::max(effect, (smooth.positions[v] - ours.back().positions[v]).norm());
        else
            effect = hausdorff_vertex_sets(smooth.positions, ours.back().positions);
        c.effect_of_tags = effect / diag;
    } catch (const InputError& e) {
        c.core_error = e.what();
    }

    // The references with crease rules for the scheme: OpenSubdiv.
    const Scheme scheme = req.scheme;
    const Implementation* ref = nullptr;
    for (const Implementation* i : references_for(scheme))
        if (i->support(scheme)->creases) ref = ref ? ref : i;
    if (!ref) {
        c.verdict = Verdict::RefRejected;
        c.explanation = "this build has no OpenSubdiv";
        return c;
    }
    RefineRequest r{scheme, {}, req.levels};
    r.rule.loop = loop_options(req);
    r.rule.catmull_clark = catmull_clark_options(req);
    IsolatedTrace it = refine_isolated(*ref, mesh, r, req.timeout_seconds, req.isolate);
    if (const std::optional<EarlyVerdict> early = verdict_before_comparing(
            it.outcome, c.core_error, "core refused the tags; OpenSubdiv refined the mesh (Far only warns about a bad tag)")) {
        c.verdict = early->verdict;
        c.explanation = early->explanation;
        return c;
    }
    // Matched level by level from provenance (positions play no part), else by position at
    // each level; only the first can show a topology difference with equal counts.
    std::vector<const PolyMesh*> our_levels{&mesh};
    for (const PolyMesh& m : ours) our_levels.push_back(&m);
    const Correspondence by_provenance = match_by_provenance(our_levels, *it.trace);
    const bool provenance = by_provenance.method != MatchMethod::None;
    c.faces_equal = true;
    bool topology_differs = false;
    for (int l = 1; l <= req.levels; ++l) {
        const PolyMesh& theirs = (*it.trace)[static_cast<size_t>(l)];
        const PolyMesh& level = ours[static_cast<size_t>(l - 1)];
        const Correspondence m = provenance ? Correspondence{by_provenance.method, by_provenance.level_maps[static_cast<size_t>(l)], {}, ""}
                                            : match_nearest_and_faces(level, theirs);
        if (m.method == MatchMethod::None) {
            c.verdict = Verdict::Diverge;
            c.faces_equal = false;
            const bool counts_differ = !(topology_counts(level) == topology_counts(theirs));
            c.divergence_class = counts_differ ? DivergenceClass::Topology : DivergenceClass::Unexplained;
            c.explanation = "level " + std::to_string(l) + ": no vertex bijection (" + m.note + ")" +
                            (counts_differ ? "; the counts differ" : "; the same counts, so not a topology difference");
            return c;
        }
        const MeshComparison mc = compare_meshes(level, theirs, m.ref_to_ours, 1);
        c.faces_equal = c.faces_equal && mc.topology_equal();
        topology_differs = topology_differs || (!mc.topology_equal() && measured_topology_difference(
                                                                             mc.ours, mc.ref, false, m.method));
        c.max_rel_per_level.push_back(mc.max_rel);
    }
    c.max_rel = c.max_rel_per_level.back();
    const double worst = *std::max_element(c.max_rel_per_level.begin(), c.max_rel_per_level.end());
    const bool agree = c.faces_equal && worst <= req.tolerance;
    c.verdict = agree ? Verdict::Agree : Verdict::Diverge;
    if (!agree) c.divergence_class = topology_differs ? DivergenceClass::Topology : DivergenceClass::Unexplained;
    char buf[200];
    const std::string holes = c.hole_tags ? ", " + std::to_string(c.hole_tags) + " hole" : std::string();
    std::snprintf(buf, sizeof buf, "%d edge and %d vertex%s tags, %s decay; worst level %.2e of the diagonal; the tags "
                  "move the surface by %.2e", c.edge_tags, c.vertex_tags, holes.c_str(), c.method.c_str(), worst,
                  c.effect_of_tags);
    c.explanation = buf;
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
    auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
    nlohmann::json levels = nlohmann::json::array();
    for (double x : c.max_rel_per_level) levels.push_back(num(x));
    nlohmann::json j = {{"input", c.input},          {"scheme", to_string(c.scheme)}, {"method", c.method},
                        {"levels", c.levels},        {"edge_tags", c.edge_tags},     {"vertex_tags", c.vertex_tags}, {"hole_tags", c.hole_tags},
                        {"verdict", to_string(c.verdict)},      {"max_rel", num(c.max_rel)},    {"max_rel_per_level", levels},
                        {"faces_equal", c.faces_equal}, {"effect_of_tags", num(c.effect_of_tags)},
                        {"explanation", c.explanation}};
    if (!c.core_error.empty()) j["core_error"] = c.core_error;
    if (c.divergence_class != DivergenceClass::None) j["divergence_class"] = to_string(c.divergence_class);
    return j;
}

}  // namespace crossdiv::verification
