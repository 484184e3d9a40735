#include "crossdiv/verification/loop_comparison.h"

#include <chrono>
#include <deque>
#include <memory>
#include <string>

#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/references.h"
#include "crossdiv/verification/tolerances.h"

namespace crossdiv::verification {
namespace {

std::string describe(const LoopOptions& o) {
    return "weights=" + std::string(to_string(o.weights)) + " boundary=" + std::string(to_string(o.boundary));
}

std::string sci(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

/// Our refinement of the input under one set of options, kept for classification.
struct CoreRun {
    LoopOptions options;
    std::unique_ptr<LoopRefiner> refiner;
    std::vector<PolyMesh> levels;  ///< levels 1..N as polygon meshes (index 0 = level 1)
    std::vector<std::vector<VertexOrigin>> origins;
};

CoreRun run_core(const TriMesh& input, const LoopOptions& options, int levels) {
    CoreRun run{options, std::make_unique<LoopRefiner>(input, options), {}, {}};
    run.refiner->refine(levels);
    for (int l = 1; l <= levels; ++l) {
        run.levels.push_back(to_poly_mesh(run.refiner->mesh(l)));
        run.origins.push_back(run.refiner->origins(l));
    }
    return run;
}

/// Max relative error at each level 1..N under the level maps (or the last level only, when
/// the match was by nearest neighbour). Positions only: topology is compared once, at the end.
std::vector<double> level_errors(const CoreRun& core, const adapters::LevelTrace& ref, const Correspondence& c) {
    std::vector<double> e;
    for (size_t l = 1; l < ref.size(); ++l) {
        if (l < c.level_maps.size())
            e.push_back(max_relative_distance(core.levels[l - 1], ref[l], c.level_maps[l]));
        else if (l + 1 == ref.size())
            e.push_back(max_relative_distance(core.levels[l - 1], ref[l], c.ref_to_ours));
    }
    return e;
}

bool all_within(const std::vector<double>& errors) {
    for (double e : errors)
        if (!(e <= tolerances::kAgreementRelative)) return false;
    return true;
}

}  // namespace

bool LoopComparison::all_agree() const {
    for (const ReferenceRun& r : runs)
        if (r.verdict != "agree") return false;
    return true;
}

LoopComparison compare_loop(const TriMesh& input, const std::string& name, const LoopComparisonRequest& req) {
    std::vector<const LoopReference*> refs;
    if (req.references.empty())
        for (const LoopReference& r : loop_references()) refs.push_back(&r);
    for (const std::string& n : req.references) refs.push_back(&find_loop_reference(n));

    LoopComparison out;
    out.input = name;
    out.input_vertices = input.num_vertices();
    out.input_faces = input.num_faces();
    out.options = req.options;
    out.levels = req.levels;

    const auto t0 = std::chrono::steady_clock::now();
    // [0] = requested options; others are added for classification. A deque, so references to
    // earlier runs stay valid while later ones are added.
    std::deque<CoreRun> core;
    core.push_back(run_core(input, req.options, req.levels));
    out.core_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    auto core_with = [&](const LoopOptions& o) -> const CoreRun& {
        for (const CoreRun& c : core)
            if (c.options == o) return c;
        core.push_back(run_core(input, o, req.levels));
        return core.back();
    };

    for (const LoopReference* ref : refs) {
        ReferenceRun run;
        run.reference = ref->name;
        run.version = ref->version;
        run.ran_with = closest_supported(*ref, req.options);
        const int levels = req.levels;
        const LoopOptions ran_with = run.ran_with;
        IsolatedTrace iso = run_isolated([&] { return ref->loop(input, ran_with, levels); }, req.timeout_seconds, req.isolate);
        run.outcome = iso.outcome;
        if (run.outcome.status != RunStatus::Ok) {
            run.verdict = run.outcome.status == RunStatus::Rejected ? "ref-rejected" : "ref-crashed";
            run.explanation = ref->name + " " + run.outcome.summary();
            out.runs.push_back(std::move(run));
            continue;
        }
        const adapters::LevelTrace& trace = *iso.trace;
        const CoreRun& ours = core.front();
        run.correspondence = match_loop_refinement(ours.origins, input.positions, trace, ours.levels.back().positions);
        if (run.correspondence.method == MatchMethod::None) {
            run.verdict = "diverge";
            run.divergence_class = "topology";
            run.explanation = "no vertex correspondence: " + run.correspondence.note;
            out.runs.push_back(std::move(run));
            continue;
        }
        run.comparison = compare_meshes(ours.levels.back(), trace.back(), run.correspondence.ref_to_ours);
        run.level_max_rel = level_errors(ours, trace, run.correspondence);
        if (run.comparison.agree() && all_within(run.level_max_rel)) {
            run.verdict = "agree";
            run.explanation = "max relative error " + sci(run.comparison.max_rel) + " <= " +
                              sci(tolerances::kAgreementRelative);
            out.runs.push_back(std::move(run));
            continue;
        }
        run.verdict = "diverge";
        const std::string worst = run.comparison.worst.empty()
                                      ? ""
                                      : " (worst: our vertex " + std::to_string(run.comparison.worst[0].ours_index) +
                                            ", valence " + std::to_string(run.comparison.worst[0].valence) +
                                            (run.comparison.worst[0].boundary ? ", boundary" : ", interior") + ")";
        if (!run.comparison.topology_equal()) {
            run.divergence_class = "topology";
            run.explanation = "refined topology differs: " + std::to_string(run.comparison.faces_only_in_ref) +
                              " faces only in " + ref->name + ", " + std::to_string(run.comparison.faces_only_in_ours) +
                              " only in core";
        } else if (!(run.ran_with == req.options)) {
            // Measured, not assumed: rerun core with the reference's rule; if that agrees, the
            // rule difference explains the whole divergence.
            const CoreRun& same_rule = core_with(run.ran_with);
            const MeshComparison c2 =
                compare_meshes(same_rule.levels.back(), trace.back(), run.correspondence.ref_to_ours);
            const std::vector<double> e2 = level_errors(same_rule, trace, run.correspondence);
            if (c2.agree() && all_within(e2)) {
                const bool w = run.ran_with.weights != req.options.weights;
                const bool b = run.ran_with.boundary != req.options.boundary;
                run.divergence_class = w && b ? "weight-family+boundary-rule" : w ? "weight-family" : "boundary-rule";
                run.explanation = ref->name + " has no " + describe(req.options) + "; run with " + describe(run.ran_with) +
                                  " it agrees with core's " + describe(run.ran_with) + " to " + sci(c2.max_rel) +
                                  ", and differs from the requested rule by " + sci(run.comparison.max_rel) + worst;
            } else {
                run.divergence_class = "unexplained";
                run.explanation = "differs by " + sci(run.comparison.max_rel) + worst + "; with " +
                                  describe(run.ran_with) + " still " + sci(c2.max_rel);
            }
        } else {
            run.divergence_class = "unexplained";
            run.explanation = "same rules, differs by " + sci(run.comparison.max_rel) + worst;
        }
        out.runs.push_back(std::move(run));
    }
    return out;
}

nlohmann::json to_json(const LoopComparison& c) {
    using nlohmann::json;
    auto options = [](const LoopOptions& o) {
        return json{{"weights", std::string(to_string(o.weights))}, {"boundary", std::string(to_string(o.boundary))}};
    };
    auto topo = [](const TopologyCounts& t) {
        return json{{"vertices", t.vertices}, {"edges", t.edges}, {"faces", t.faces}, {"euler", t.euler},
                    {"boundary_loops", t.boundary_loops}};
    };
    auto vec = [](const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); };
    auto finite = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    json runs = json::array();
    for (const ReferenceRun& r : c.runs) {
        json worst = json::array();
        for (const WorstVertex& w : r.comparison.worst)
            worst.push_back({{"ours_index", w.ours_index}, {"ref_index", w.ref_index}, {"valence", w.valence},
                             {"boundary", w.boundary}, {"ours", vec(w.ours)}, {"ref", vec(w.ref)}, {"distance", w.distance}});
        json run = {{"reference", r.reference},
                    {"version", r.version},
                    {"ran_with", options(r.ran_with)},
                    {"status", to_string(r.outcome.status)},
                    {"status_message", r.outcome.message},
                    {"seconds", r.outcome.seconds},
                    {"verdict", r.verdict},
                    {"divergence_class", r.divergence_class},
                    {"explanation", r.explanation}};
        if (r.outcome.status == RunStatus::Ok) {
            run["match"] = {{"method", to_string(r.correspondence.method)}, {"note", r.correspondence.note}};
            run["topology"] = {{"core", topo(r.comparison.ours)},
                               {"reference", topo(r.comparison.ref)},
                               {"face_sets_equal", r.comparison.face_sets_equal},
                               {"faces_only_in_core", r.comparison.faces_only_in_ours},
                               {"faces_only_in_reference", r.comparison.faces_only_in_ref}};
            json levels = json::array();
            for (double e : r.level_max_rel) levels.push_back(finite(e));
            run["positions"] = {{"diagonal", r.comparison.diagonal}, {"max_abs", finite(r.comparison.max_abs)},
                                {"rms_abs", finite(r.comparison.rms_abs)}, {"max_rel", finite(r.comparison.max_rel)},
                                {"rms_rel", finite(r.comparison.rms_rel)}, {"level_max_rel", levels},
                                {"worst", worst}};
        }
        runs.push_back(run);
    }
    return {{"input", c.input},      {"input_vertices", c.input_vertices}, {"input_faces", c.input_faces},
            {"scheme", "loop"},      {"options", options(c.options)},      {"levels", c.levels},
            {"core_seconds", c.core_seconds}, {"agreement_tolerance_rel", tolerances::kAgreementRelative},
            {"all_agree", c.all_agree()},     {"runs", runs}};
}

}  // namespace crossdiv::verification
