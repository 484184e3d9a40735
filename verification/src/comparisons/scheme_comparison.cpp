#include "crossdiv/verification/comparisons/scheme_comparison.h"

#include "crossdiv/verification/harness/mesh_topology.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>

#include "crossdiv/error.h"
#include "harness/sci.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/comparisons/classification.h"
#include "crossdiv/verification/properties/rule_oracle.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

using detail::sci;

/// What the reference's rule does, for the explanation.
std::string rule_effect(Scheme scheme, const std::string& ref_name, const std::string& rule, int levels) {
    switch (scheme) {
        case Scheme::DooSabin: return ref_name + " drops the faces of border edges and vertices";
        case Scheme::Sqrt3:
            return ref_name + (rule == "restart-each-level"
                                   ? " counts generations per call, and was called once per level, so it never refined the boundary"
                                   : " counts generations from the input (one call of " + std::to_string(levels) + " levels)");
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly:
            return ref_name + (rule == "opposite-vertex-wings"
                                   ? " takes a wing point beyond the boundary to be the triangle's own opposite vertex"
                                   : " reflects a wing point beyond the boundary across the wing edge");
        default: return ref_name + " applies the " + rule + " boundary rule";
    }
}

/// When the reference's weight table is shorter than the input's largest valence: whether at
/// level 1 exactly the vertices beyond the table differ (the others agree within `tolerance`);
/// fills `explanation` with the figures. Later levels inherit the difference from them.
bool beyond_valence_table(const Implementation& ref, Scheme scheme, const SchemeRule& ref_rule, const PolyMesh& input,
                          const adapters::LevelTrace& trace, double tolerance, std::string& explanation) {
    const SchemeSupport* support = ref.support(scheme);
    if (!support || support->max_valence <= 0 || trace.size() < 2) return false;
    const int max_valence = support->max_valence;
    const MeshTopology topo = mesh_topology(input);
    int beyond = 0, largest = 0;
    for (int v = 0; v < input.num_vertices(); ++v) {
        beyond += topo.valence[v] > max_valence;
        largest = std::max(largest, topo.valence[v]);
    }
    if (beyond == 0) return false;
    const PolyMesh ours = subdivide(scheme, ref_rule, input, 1);
    const Correspondence c = match_nearest_and_faces(ours, trace[1]);
    if (c.method == MatchMethod::None) return false;
    const std::vector<double> d = vertex_distances(ours, trace[1], c.ref_to_ours);
    const double diagonal = bounding_box_diagonal(ours.positions);
    int differing = 0, non_finite = 0;
    double worst = 0;
    for (size_t i = 0; i < d.size(); ++i) {
        if (d[i] <= tolerance * diagonal) continue;  // a non-finite position differs too
        const int v = c.ref_to_ours[i];  // core keeps old vertices first, in input order
        if (v >= input.num_vertices() || topo.valence[v] <= max_valence) return false;
        ++differing;
        if (std::isfinite(d[i])) worst = std::max(worst, d[i] / diagonal);
        else ++non_finite;
    }
    if (differing != beyond) return false;
    explanation = ref.name() + "'s weight table ends at valence " + std::to_string(max_valence) + " (" +
                  support->valence_table + ") and what it reads past the table is undefined; at level 1 exactly the " + std::to_string(beyond) +
                  " vertices of larger valence (up to " + std::to_string(largest) + ") differ, " +
                  (non_finite == differing ? std::string("all to non-finite positions")
                                           : "by up to " + sci(worst) + " of the diagonal" +
                                                 (non_finite ? " (" + std::to_string(non_finite) + " non-finite)" : "")) +
                  ", and every other vertex agrees";
    return true;
}

/// Schemes whose levels are matched by provenance (match_by_provenance): a triangle split
/// into four, an n-gon into n quads, old vertices kept.
bool primal(Scheme scheme) {
    return scheme == Scheme::Butterfly || scheme == Scheme::ModifiedButterfly || scheme == Scheme::Loop ||
           scheme == Scheme::CatmullClark;
}

}  // namespace

PolyMesh subdivide(Scheme scheme, const SchemeRule& rule, const PolyMesh& mesh, int levels) {
    return core_implementation().refine_last(mesh, {scheme, rule, levels});
}

bool SchemeComparison::all_agree() const {
    if (!core_error.empty() || runs.empty()) return false;
    for (const SchemeReferenceRun& r : runs)
        if (r.verdict != Verdict::Agree) return false;
    return true;
}

SchemeComparison compare_scheme(const PolyMesh& input, const std::string& name, const SchemeRequest& req) {
    SchemeComparison out;
    out.input = name;
    out.scheme = req.scheme;
    out.rule = rule_name(req.scheme, req.rule);
    out.levels = req.levels;
    out.tier = req.tier;
    out.tolerance = req.tolerance;
    out.input_vertices = input.num_vertices();
    out.input_faces = input.num_faces();

    std::vector<const Implementation*> refs = select_references(req.scheme, req.references);
    if (req.references.empty() && !input.creases.empty()) {
        // Only references with crease rules read the tags; the others would refuse them.
        std::erase_if(refs, [&](const Implementation* r) { return !r->support(req.scheme)->creases; });
        std::string names;
        for (const Implementation* r : refs) names += (names.empty() ? "" : ", ") + r->name();
        out.notes.push_back(name + " has " + input.creases.describe() + "; compared with " +
                            (names.empty() ? std::string("no reference (none has crease rules)") : names) +
                            ", the references with crease and hole rules");
    }

    // Core under the requested rule, and under each reference's rule when it differs.
    PolyMesh ours;
    adapters::LevelTrace our_levels;  // every level, for a primal scheme (matched by provenance)
    const auto t0 = std::chrono::steady_clock::now();
    try {
        if (primal(req.scheme)) {
            our_levels = core_implementation().refine(input, {req.scheme, req.rule, req.levels});
            ours = our_levels.back();
        } else {
            ours = subdivide(req.scheme, req.rule, input, req.levels);
        }
    } catch (const InputError& e) {
        out.core_error = e.what();
    }
    out.core_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    // The input's largest valence, for the float tier's bound (only a float reference reads it).
    int max_valence = 0;
    for (const Implementation* r : refs)
        if (r->capabilities().precision == Precision::Float) {
            for (int v : mesh_topology(input).valence) max_valence = std::max(max_valence, v);
            break;
        }

    // For the 3D view: each matched reference's last level in our numbering.
    std::map<std::string, std::vector<Vec3>> at_last_level;
    for (const Implementation* impl : refs) {
        const Implementation& ref = *impl;
        SchemeReferenceRun run;
        run.reference = ref.name();
        run.version = ref.version();
        const SchemeRule ref_rule = ref.closest_rule(req.scheme, req.rule);
        const bool rules_differ = !same_rule(req.scheme, ref_rule, req.rule);
        run.rule = rule_name(req.scheme, ref_rule);
        IsolatedTrace it =
            refine_isolated(ref, input, {req.scheme, req.rule, req.levels}, req.timeout_seconds, req.isolate);
        run.outcome = it.outcome;
        const auto made = [&] {
            const PolyMesh& m = it.trace->back();
            return "core refused the input; " + ref.name() + " made a mesh of " + std::to_string(m.num_vertices()) +
                   " vertices and " + std::to_string(m.num_faces()) + " faces";
        };
        if (const std::optional<EarlyVerdict> early =
                verdict_before_comparing(run.outcome, out.core_error, it.trace ? made() : std::string())) {
            run.verdict = early->verdict;
            run.explanation = early->explanation;
            out.runs.push_back(std::move(run));
            continue;
        }
        const PolyMesh& theirs = it.trace->back();
        // Core with the reference's rule, to measure what the rule explains; a rule core has
        // only for manifold meshes (OpenMesh's midpoint-average on a bowtie) is not measured.
        // Every level of it for a primal scheme, to match by provenance.
        std::string no_same_rule;
        adapters::LevelTrace same_rule_levels;
        PolyMesh same_rule_mesh = ours;
        if (rules_differ) {
            try {
                if (primal(req.scheme)) {
                    same_rule_levels = core_implementation().refine(input, {req.scheme, ref_rule, req.levels});
                    same_rule_mesh = same_rule_levels.back();
                } else {
                    same_rule_mesh = subdivide(req.scheme, ref_rule, input, req.levels);
                }
            } catch (const InputError& e) {
                no_same_rule = "; core cannot apply " + ref.name() + "'s " + run.rule + " rule here (" + e.what() + ")";
            }
        }
        // Match against core with the reference's rule: by provenance where the scheme and the
        // reference's numbering give it, else by position, which then coincide up to rounding
        // even where the requested rule moves vertices (or makes others).
        if (primal(req.scheme))
            run.correspondence = match_refinement(level_view(same_rule_levels.empty() ? our_levels : same_rule_levels), *it.trace);
        else
            run.correspondence = match_nearest_and_faces(same_rule_mesh, theirs);
        // A reference whose weight table ends below the input's valence reads past it: what it
        // puts at those vertices is undefined (OpenMesh's Sqrt3T reads whatever lies beyond
        // its vector), and only level 1, where nothing else has yet mixed it in, shows it.
        // The test stands whether or not the final levels could be matched.
        // A reference that computes in float is held to the float tier (tolerances::kFloatAgreementUlps).
        const bool in_float = ref.capabilities().precision == Precision::Float;
        const double tolerance = agreement_tolerance(ours, in_float, req.tolerance, max_valence, req.levels);
        const DivergenceTest valence_table = [&]() -> std::optional<Classification> {
            std::string why;
            if (!beyond_valence_table(ref, req.scheme, ref_rule, input, *it.trace, tolerance, why)) return std::nullopt;
            return Classification{DivergenceClass::ValenceLimit, why};
        };
        // The tier the run is held to: a float reference to the weak tier at the float bound.
        const Tier tier = in_float && req.tier == Tier::Strict ? Tier::Weak : req.tier;
        if (tier == Tier::Geometric) {
            const double d = bounding_box_diagonal(ours.positions);
            run.hausdorff_rel = hausdorff_vertex_sets(ours.positions, theirs.positions) / (d > 0 ? d : 1);
        }
        const bool geometric_agree = tier == Tier::Geometric && run.hausdorff_rel <= tolerance;
        const std::string geometric_why = "vertex-set Hausdorff distance " + sci(run.hausdorff_rel) + " <= " + sci(tolerance);
        if (run.correspondence.method == MatchMethod::None && geometric_agree) {
            run.verdict = Verdict::Agree;
            run.explanation = geometric_why + " (no vertex correspondence: " + run.correspondence.note + ")";
            out.runs.push_back(std::move(run));
            continue;
        }
        if (run.correspondence.method == MatchMethod::None) {
            // Without a correspondence only the valence-table and topology tests of the ladder
            // can be run.
            run.verdict = Verdict::Diverge;
            // With equal counts that is no measured topology difference: a rule that moves
            // vertices far (a wrong weight) breaks a match by position too.
            const std::string unmatched = "no vertex bijection with core's " + run.rule + " refinement (" +
                                          run.correspondence.note + "); " + std::to_string(theirs.num_faces()) +
                                          " faces and " + std::to_string(theirs.num_vertices()) + " vertices against core's " +
                                          std::to_string(same_rule_mesh.num_faces()) + " and " +
                                          std::to_string(same_rule_mesh.num_vertices());
            DivergenceTests only_topology;
            only_topology.valence_table = valence_table;
            only_topology.topology = [&]() -> std::optional<Classification> {
                if (!measured_topology_difference(topology_counts(same_rule_mesh), topology_counts(theirs), false,
                                                  MatchMethod::None))
                    return std::nullopt;
                return Classification{DivergenceClass::Topology, unmatched};
            };
            only_topology.unexplained = [&] { return unmatched + ": the same counts, so not a topology difference"; };
            const Classification c = classify_divergence(only_topology);
            run.divergence_class = c.cls;
            run.explanation = c.explanation;
            out.runs.push_back(std::move(run));
            continue;
        }
        // Under the requested rule the same map holds only where the vertex sets coincide;
        // otherwise compare_meshes reports the counts and no distances.
        const std::vector<int> no_map;
        run.comparison = compare_meshes(ours, theirs, rules_differ && ours.num_vertices() != same_rule_mesh.num_vertices()
                                                          ? no_map
                                                          : run.correspondence.ref_to_ours);
        if (req.view_max_faces > 0 && !(rules_differ && ours.num_vertices() != same_rule_mesh.num_vertices())) {
            std::vector<Vec3>& mapped = at_last_level[ref.name()];
            mapped.assign(ours.positions.size(), Vec3::Constant(NAN));
            for (size_t i = 0; i < run.correspondence.ref_to_ours.size(); ++i)
                if (const int v = run.correspondence.ref_to_ours[i]; v >= 0 && v < ours.num_vertices())
                    mapped[v] = theirs.positions[i];
        }
        const MeshComparison with_rule = compare_meshes(same_rule_mesh, theirs, run.correspondence.ref_to_ours);
        run.max_rel_with_reference_rule = with_rule.max_rel;
        const bool within_tier = tier == Tier::Strict ? run.comparison.topology_equal() && run.comparison.max_abs == 0.0
                                 : tier == Tier::Weak ? run.comparison.topology_equal() && run.comparison.max_rel <= tolerance
                                                      : geometric_agree;
        if (within_tier) {
            run.verdict = Verdict::Agree;
            run.explanation = tier == Tier::Strict    ? std::string("bitwise identical")
                              : tier == Tier::Geometric ? geometric_why
                                                        : "max relative error " + sci(run.comparison.max_rel) + " <= " +
                                                              sci(tolerance) + (in_float ? " (float tier)" : "");
        } else {
            run.verdict = Verdict::Diverge;
            const bool same_faces = run.comparison.topology_equal();
            const std::string faces = std::to_string(theirs.num_faces()) + " faces and " +
                                      std::to_string(theirs.num_vertices()) + " vertices against core's " +
                                      std::to_string(ours.num_faces()) + " and " + std::to_string(ours.num_vertices());
            DivergenceTests tests;
            tests.isolated_vertices = [&]() -> std::optional<Classification> {
                if (!same_faces || !only_isolated_vertices_differ(ours, theirs, run.correspondence.ref_to_ours, tolerance))
                    return std::nullopt;
                return Classification{DivergenceClass::IsolatedVertexHandling,
                                      "only vertices no face uses differ, by up to " + sci(run.comparison.max_rel) +
                                          " of the diagonal"};
            };
            tests.rounding = [&]() -> std::optional<Classification> {
                const double ulps = run.comparison.max_abs / ulp_of_largest_coordinate(ours);
                if (!same_faces || !(ulps <= tolerances::kRoundingUlps)) return std::nullopt;
                return Classification{DivergenceClass::Rounding, "differs by " + sci(ulps) + " ulps of the largest coordinate"};
            };
            std::string oracle_failed;  // the requested rule's oracle, when it fails
            tests.reference_rule = [&]() -> std::optional<Classification> {
                // The reference's rule explains the divergence when core with that rule agrees,
                // or agrees at every vertex a face uses: a reference can have two named causes
                // at once (OpenMesh's boundary rule on a model with isolated vertices, which it
                // moves).
                if (!rules_differ || !with_rule.topology_equal()) return std::nullopt;
                const bool rule_agrees = with_rule.max_rel <= tolerance;
                if (!rule_agrees &&
                    !only_isolated_vertices_differ(same_rule_mesh, theirs, run.correspondence.ref_to_ours, tolerance))
                    return std::nullopt;
                // A rule difference explains the divergence only if core's requested rule is
                // the published one (rule_oracle.h).
                const RuleVerdict oracle = check_core_rule(req.scheme, req.rule);
                if (oracle.known && !oracle.passed) {
                    oracle_failed = "; " + out.rule + " fails its oracle: " + oracle.detail;
                    return std::nullopt;
                }
                const std::string agrees =
                    rule_agrees ? "core with " + run.rule + " agrees to " + sci(with_rule.max_rel)
                                : "core with " + run.rule + " agrees at every vertex a face uses; only vertices no face uses "
                                                            "differ beyond that (isolated-vertex-handling too), by up to " +
                                      sci(with_rule.max_rel);
                return Classification{rule_difference_class(req.scheme, ref_rule, req.rule),
                                      rule_effect(req.scheme, ref.name(), run.rule, req.levels) + ": " + agrees + "; core's " +
                                          out.rule +
                                          (same_faces ? " differs by " + sci(run.comparison.max_rel) + " of the diagonal"
                                                      : " makes different faces (" + faces + ")")};
            };
            tests.nonmanifold = [&]() -> std::optional<Classification> {
                // Measured: core took OpenSubdiv's non-manifold rules here, and every vertex
                // that differs by more than the tolerance from core under the reference's own
                // rule (its boundary rule too) lies where the non-manifold vertices reach.
                if (req.scheme != Scheme::CatmullClark || req.rule.catmull_clark.nonmanifold != NonManifoldRule::OpenSubdiv)
                    return std::nullopt;
                const bool own_rule = !rules_differ || same_rule_levels.empty();
                const PolyMesh& core_rule = own_rule ? ours : same_rule_mesh;
                if (!(own_rule ? same_faces : with_rule.topology_equal())) return std::nullopt;
                return nonmanifold_handling(nonmanifold_reach(level_view(own_rule ? our_levels : same_rule_levels)), core_rule,
                                            theirs, run.correspondence.ref_to_ours, tolerance, ref.name(),
                                            own_rule ? run.comparison.max_rel : with_rule.max_rel,
                                            own_rule ? "" : " from core with " + run.rule);
            };
            tests.valence_table = valence_table;
            tests.topology = [&]() -> std::optional<Classification> {
                if (same_faces || !measured_topology_difference(run.comparison.ours, run.comparison.ref, false,
                                                                run.correspondence.method))
                    return std::nullopt;
                return Classification{DivergenceClass::Topology,
                                      faces + "; " + std::to_string(run.comparison.faces_only_in_ref) + " faces only in " +
                                          ref.name() + ", " + std::to_string(run.comparison.faces_only_in_ours) + " only in core"};
            };
            tests.unexplained = [&] {
                if (!same_faces)
                    return faces + "; the face sets differ only under a match by position (" +
                           to_string(run.correspondence.method) + "), which a vertex moved far breaks: not a topology difference";
                if (!no_same_rule.empty()) return "differs by " + sci(run.comparison.max_rel) + no_same_rule;
                if (!oracle_failed.empty()) return "differs by " + sci(run.comparison.max_rel) + oracle_failed;
                return "differs by " + sci(run.comparison.max_rel) + "; with " + ref.name() + "'s " + run.rule + " rule still " +
                       sci(with_rule.max_rel);
            };
            const Classification found = classify_divergence(tests);
            run.divergence_class = found.cls;
            run.explanation = found.explanation;
        }
        out.runs.push_back(std::move(run));
    }
    const bool diverges = std::any_of(out.runs.begin(), out.runs.end(), [](const SchemeReferenceRun& r) {
        return r.verdict == Verdict::Diverge;
    });
    if (diverges && req.view_max_faces > 0 && out.core_error.empty() && ours.num_faces() <= req.view_max_faces) {
        // Every level of core (a scheme that is not primal is refined again for them, the
        // mesh being small); the references are matched at the last level.
        DivergenceView& view = out.view.emplace();
        adapters::LevelTrace levels =
            our_levels.empty() ? core_implementation().refine(input, {req.scheme, req.rule, req.levels}) : our_levels;
        levels.back() = ours;  // the level the references were matched to
        view.levels.assign(levels.begin(), levels.end());
        for (auto& [reference, positions] : at_last_level) {
            std::vector<std::vector<Vec3>>& per_level = view.references[reference];
            per_level.resize(view.levels.size());
            per_level.back() = std::move(positions);
        }
    }
    return out;
}

nlohmann::json to_json(const SchemeComparison& c) {
    using nlohmann::json;
    const auto finite = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    json runs = json::array();
    for (const SchemeReferenceRun& r : c.runs) {
        json run = {{"reference", r.reference},
                    {"version", r.version},
                    {"rule", r.rule},
                    {"status", to_string(r.outcome.status)},
                    {"status_message", r.outcome.message},
                    {"seconds", r.outcome.seconds},
                    {"verdict", to_string(r.verdict)},
                    {"divergence_class", to_string(r.divergence_class)},
                    {"explanation", r.explanation},
                    {"correspondence", to_string(r.correspondence.method)}};
        if (r.correspondence.method != MatchMethod::None && r.outcome.status == RunStatus::Ok) {
            run["faces_only_in_core"] = r.comparison.faces_only_in_ours;
            run["faces_only_in_reference"] = r.comparison.faces_only_in_ref;
            run["max_rel"] = finite(r.comparison.max_rel);
            run["rms_rel"] = finite(r.comparison.rms_rel);
            run["max_rel_with_reference_rule"] = finite(r.max_rel_with_reference_rule);
        }
        if (c.tier == Tier::Geometric) run["hausdorff_rel"] = finite(r.hausdorff_rel);
        runs.push_back(run);
    }
    json out = {{"input", c.input},           {"scheme", to_string(c.scheme)}, {"rule", c.rule},
            {"levels", c.levels},         {"tier", to_string(c.tier)}, {"tolerance_rel", finite(c.tolerance)},
            {"input_vertices", c.input_vertices}, {"input_faces", c.input_faces},
            {"core_seconds", c.core_seconds}, {"core_error", c.core_error}, {"all_agree", c.all_agree()},
            {"runs", runs}};
    if (!c.notes.empty()) out["notes"] = c.notes;
    return out;
}

}  // namespace crossdiv::verification
