#include "crossdiv/verification/comparisons/loop_comparison.h"
#include "crossdiv/subdiv/nonmanifold.h"

#include <algorithm>
#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <string>

#include "crossdiv/error.h"
#include "harness/sci.h"
#include "crossdiv/verification/comparisons/classification.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/properties/loop_rule_oracle.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {
namespace {

std::string describe(const LoopOptions& o) {
    return "weights=" + std::string(to_string(o.weights)) + " boundary=" + std::string(to_string(o.boundary));
}

using detail::sci;

/// Our refinement of the input under one set of options, kept for classification.
struct CoreRun {
    LoopOptions options;
    std::vector<PolyMesh> levels;  ///< levels 1..N as polygon meshes (index 0 = level 1)
    std::vector<std::vector<VertexOrigin>> origins;
};

CoreRun run_core(const TriMesh& input, const LoopOptions& options, int levels) {
    CoreRun run{options, {}, {}};
    try {
        LoopRefiner refiner(input, options);
        refiner.refine(levels);
        for (int l = 1; l <= levels; ++l) {
            run.levels.push_back(to_poly_mesh(refiner.mesh(l)));
            run.origins.push_back(refiner.origins(l));
        }
        return run;
    } catch (const NonManifoldInput&) {
        if (options.nonmanifold == NonManifoldRule::Refuse) throw;
    }
    // Not a manifold: OpenSubdiv's rules (nonmanifold.h), level by level, with the same
    // provenance (old vertices, then one edge point per edge).
    PolyMesh current = to_poly_mesh(input);
    for (int l = 1; l <= levels; ++l) {
        std::vector<VertexOrigin> origins;
        for (int v = 0; v < current.num_vertices(); ++v) origins.push_back({v, -1});
        for (const auto& [a, b] : nonmanifold_edges(current)) origins.push_back({a, b});
        current = loop_subdivide_nonmanifold(current, options, 1);
        run.levels.push_back(current);
        run.origins.push_back(std::move(origins));
    }
    return run;
}

/// Levels 0..N of a core run whose level 0 is `input`.
std::vector<const PolyMesh*> levels_of(const CoreRun& run, const PolyMesh& input) {
    std::vector<const PolyMesh*> view{&input};
    for (const PolyMesh& m : run.levels) view.push_back(&m);
    return view;
}

/// The correspondence's vertex map at level `l` of `last`: its level map when matched level by
/// level, the last level's map when matched by position (nullptr at the levels before).
const std::vector<int>* level_map(const Correspondence& c, size_t l, size_t last) {
    if (l < c.level_maps.size()) return &c.level_maps[l];
    return l == last ? &c.ref_to_ours : nullptr;
}

/// Max relative error at each level 1..N under the level maps (or the last level only, when
/// the match was by nearest neighbour). Positions only: topology is compared once, at the end.
std::vector<double> level_errors(const CoreRun& core, const adapters::LevelTrace& ref, const Correspondence& c) {
    std::vector<double> e;
    for (size_t l = 1; l < ref.size(); ++l) {
        if (core.levels[l - 1].num_vertices() == 0) continue;  // a level the subject was not asked for
        if (const std::vector<int>* map = level_map(c, l, ref.size() - 1))
            e.push_back(max_relative_distance(core.levels[l - 1], ref[l], *map));
    }
    return e;
}

/// The tier's verdict on one comparison (and its per-level errors).
bool within(const LoopComparisonRequest& req, const MeshComparison& c, const std::vector<double>& level_errors,
            double hausdorff_rel) {
    switch (req.tier) {
        case Tier::Strict: return c.topology_equal() && c.max_abs == 0.0;
        case Tier::Geometric: return hausdorff_rel <= req.tolerance;
        case Tier::Weak:
            if (!c.topology_equal() || !(c.max_rel <= req.tolerance)) return false;
            for (double e : level_errors)
                if (!(e <= req.tolerance)) return false;
            return true;
    }
    return false;
}

/// A reference's vertices in our numbering (`ref_to_ours`: ours for each of its vertices);
/// NaN where none of its vertices maps.
std::vector<Vec3> in_our_numbering(const PolyMesh& ref, const std::vector<int>& ref_to_ours, int our_vertices) {
    std::vector<Vec3> mapped(our_vertices, Vec3::Constant(NAN));
    for (size_t i = 0; i < ref_to_ours.size(); ++i)
        if (ref_to_ours[i] >= 0 && ref_to_ours[i] < our_vertices) mapped[ref_to_ours[i]] = ref.positions[i];
    return mapped;
}

/// A reference's levels 0..N in our numbering, each where the correspondence has a map for it
/// (every level when matched level by level, the last one when matched by position).
std::vector<std::vector<Vec3>> levels_in_our_numbering(const CoreRun& ours, const PolyMesh& input,
                                                       const adapters::LevelTrace& ref, const Correspondence& c) {
    std::vector<std::vector<Vec3>> out(ref.size());
    for (size_t l = 0; l < ref.size(); ++l) {
        const std::vector<int>* map = level_map(c, l, ref.size() - 1);
        if (!map || map->empty() || map->size() != ref[l].positions.size()) continue;
        out[l] = in_our_numbering(ref[l], *map, l == 0 ? input.num_vertices() : ours.levels[l - 1].num_vertices());
    }
    return out;
}

/// Runs one reference, isolated, with the closest rules it has; fills the run's identity.
IsolatedTrace run_reference(const Implementation& ref, const TriMesh& input, const LoopComparisonRequest& req,
                            ReferenceRun& run) {
    run.reference = ref.name();
    run.version = ref.version();
    RefineRequest asked{Scheme::Loop, {}, req.levels};
    asked.rule.loop = req.options;
    asked.rule = ref.closest_rule(Scheme::Loop, asked.rule);
    run.ran_with = asked.rule.loop;
    const PolyMesh mesh = to_poly_mesh(input);
    IsolatedTrace iso = refine_isolated(ref, mesh, asked, req.timeout_seconds, req.isolate);
    run.outcome = iso.outcome;
    return iso;
}

LoopComparison empty_comparison(const TriMesh& input, const std::string& name, const LoopComparisonRequest& req) {
    LoopComparison out;
    out.input = name;
    out.input_vertices = input.num_vertices();
    out.input_faces = input.num_faces();
    out.options = req.options;
    out.levels = req.levels;
    out.tier = req.tier;
    out.tolerance = req.tolerance;
    return out;
}

/// The subject's levels renumbered into core's: level by level through provenance where the
/// subject keeps old vertices first (as the libraries do), else each level matched by
/// position to core's level. Levels the subject did not make stay empty. The method is the
/// weakest one any level needed; None when some level has no bijection (the note says which).
Correspondence renumber_subject(const CoreRun& core, const PolyMesh& input, const adapters::LevelTrace& trace,
                                CoreRun& subject) {
    subject.options = core.options;
    subject.origins = core.origins;
    subject.levels.assign(core.levels.size(), PolyMesh{});
    Correspondence c = match_by_provenance(levels_of(core, input), trace);
    if (c.method == MatchMethod::Order || c.method == MatchMethod::Topology) {
        for (size_t l = 1; l < trace.size(); ++l) subject.levels[l - 1] = renumber(trace[l], c.level_maps[l]);
        return c;
    }
    const std::string topological = c.note;
    c = Correspondence{};
    c.method = MatchMethod::Nearest;
    for (size_t l = 1; l < trace.size(); ++l) {
        if (trace[l].num_vertices() == 0) continue;
        const Correspondence m = match_nearest_and_faces(core.levels[l - 1], trace[l]);
        if (m.method == MatchMethod::None) {
            c.method = MatchMethod::None;
            c.note = "level " + std::to_string(l) + ": " + m.note + " (" + topological + ")";
            return c;
        }
        if (m.method == MatchMethod::NearestAndFaces) c.method = MatchMethod::NearestAndFaces;
        subject.levels[l - 1] = renumber(trace[l], m.ref_to_ours);
        c.ref_to_ours = m.ref_to_ours;
    }
    c.note = topological;
    return c;
}

std::vector<const Implementation*> selected_references(const LoopComparisonRequest& req) {
    if (req.without_references) return {};
    return select_references(Scheme::Loop, req.references);
}

}  // namespace

bool LoopComparison::all_agree() const {
    for (const ReferenceRun& r : runs)
        if (r.verdict != Verdict::Agree) return false;
    return true;
}

LoopComparison compare_loop(const TriMesh& input, const std::string& name, const LoopComparisonRequest& req) {
    const std::vector<const Implementation*> refs = selected_references(req);
    LoopComparison out = empty_comparison(input, name, req);

    const auto t0 = std::chrono::steady_clock::now();
    // [0] = requested options; others are added for classification. A deque, so references to
    // earlier runs stay valid while later ones are added.
    const PolyMesh input_mesh = to_poly_mesh(input);
    std::deque<CoreRun> core;
    core.push_back(run_core(input, req.options, req.levels));
    out.core_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    auto core_with = [&](const LoopOptions& o) -> const CoreRun& {
        for (const CoreRun& c : core)
            if (c.options == o) return c;
        core.push_back(run_core(input, o, req.levels));
        return core.back();
    };

    // The implementation under test: core with the requested rule, or the subject in core's
    // numbering with the rule it is measured to follow (none when no named rule fits).
    const CoreRun* under_test = &core.front();
    CoreRun subject;
    std::optional<LoopOptions> subject_rule = req.options;
    const std::string subject_name = req.subject ? req.subject->name() : "core";
    if (req.subject) {
        out.subject = subject_name;
        RefineRequest asked{Scheme::Loop, {}, req.levels};
        asked.rule.loop = req.options;
        const PolyMesh& mesh = input_mesh;
        IsolatedTrace iso = refine_isolated(*req.subject, mesh, asked, req.timeout_seconds, req.isolate);
        out.subject_outcome = iso.outcome;
        if (iso.outcome.status != RunStatus::Ok) return out;
        out.subject_match = renumber_subject(core.front(), mesh, *iso.trace, subject);
        if (out.subject_match.method == MatchMethod::None) {
            out.subject_unmatched = "no vertex correspondence with core's refinement: " + out.subject_match.note;
            return out;
        }
        std::vector<std::vector<PolyMesh>> by_rule;
        for (const LoopOptions& o : loop_named_rules()) by_rule.push_back(core_with(o).levels);
        out.rules = identify_loop_rule(mesh, subject.levels, by_rule, core.front().origins, req.options, req.tolerance);
        subject_rule = out.rules->rule;
        under_test = &subject;
    }

    // The input's largest valence, for the float tier's bound: counted once, when a float
    // reference first needs it.
    int max_valence = -1;
    auto largest_valence = [&] {
        if (max_valence < 0)
            for (int v : mesh_topology(input_mesh).valence) max_valence = std::max(max_valence, v);
        return std::max(max_valence, 0);
    };

    // The valences of the input's interior vertices, where a rule's vertex mask is used.
    std::vector<int> interior_valence_list;
    bool interior_valences_counted = false;
    auto interior_valences = [&]() -> const std::vector<int>& {
        if (!interior_valences_counted) {
            const MeshTopology t = mesh_topology(input_mesh);
            for (size_t v = 0; v < t.valence.size(); ++v)
                if (!t.boundary_vertex[v] && t.valence[v] >= 3) interior_valence_list.push_back(t.valence[v]);
            std::sort(interior_valence_list.begin(), interior_valence_list.end());
            interior_valence_list.erase(std::unique(interior_valence_list.begin(), interior_valence_list.end()),
                                        interior_valence_list.end());
            interior_valences_counted = true;
        }
        return interior_valence_list;
    };

    // Each matched reference's last level in our vertex order, to report every
    // implementation's value at the case's worst vertex.
    std::map<std::string, std::vector<Vec3>> in_our_order;
    // And, for the 3D view, every level of each matched reference (not gathered for a last
    // level larger than the view allows).
    const bool keep_view = req.view_max_faces > 0 && under_test->levels.back().num_faces() <= req.view_max_faces;
    std::map<std::string, std::vector<std::vector<Vec3>>> at_each_level;
    for (const Implementation* ref : refs) {
        ReferenceRun run;
        IsolatedTrace iso = run_reference(*ref, input, req, run);
        if (run.outcome.status != RunStatus::Ok) {
            run.verdict = verdict_of_failed_run(run.outcome.status);
            run.explanation = ref->name() + " " + run.outcome.summary();
            out.runs.push_back(std::move(run));
            continue;
        }
        const adapters::LevelTrace& trace = *iso.trace;
        const CoreRun& ours = *under_test;
        // A reference that computes in float is held to the float tier: the weak tier at the
        // float bound (tolerances::kFloatAgreementUlps), whatever tier the case asks of doubles.
        const bool in_float = ref->capabilities().precision == Precision::Float;
        LoopComparisonRequest tier = req;
        if (in_float) {
            tier.tolerance = agreement_tolerance(ours.levels.back(), true, req.tolerance, largest_valence(), req.levels);
            if (tier.tier == Tier::Strict) tier.tier = Tier::Weak;
        }
        // Against core's own levels: a subject renumbered into core's order has the same.
        run.correspondence = match_refinement(levels_of(core.front(), input_mesh), trace);
        if (req.tier == Tier::Geometric) {
            const double d = bounding_box_diagonal(ours.levels.back().positions);
            run.hausdorff_rel = hausdorff_vertex_sets(ours.levels.back().positions, trace.back().positions) / (d > 0 ? d : 1);
        }
        if (run.correspondence.method == MatchMethod::None) {
            const bool same_counts = trace.back().num_vertices() == ours.levels.back().num_vertices() &&
                                     trace.back().num_faces() == ours.levels.back().num_faces();
            if (req.tier == Tier::Geometric && run.hausdorff_rel <= req.tolerance) {
                run.verdict = Verdict::Agree;
                run.explanation = "vertex-set Hausdorff distance " + sci(run.hausdorff_rel) + " <= " + sci(req.tolerance) +
                                  " (no vertex correspondence: " + run.correspondence.note + ")";
            } else {
                // Without a correspondence only the topology test of the ladder can be run.
                run.verdict = Verdict::Diverge;
                DivergenceTests only_topology;
                only_topology.topology = [&]() -> std::optional<Classification> {
                    return Classification{same_counts ? DivergenceClass::AmbiguousCorrespondence : DivergenceClass::Topology,
                                          "no vertex correspondence: " + run.correspondence.note};
                };
                const Classification c = classify_divergence(only_topology);
                run.divergence_class = c.cls;
                run.explanation = c.explanation;
            }
            out.runs.push_back(std::move(run));
            continue;
        }
        run.comparison = compare_meshes(ours.levels.back(), trace.back(), run.correspondence.ref_to_ours);
        run.level_max_rel = level_errors(ours, trace, run.correspondence);
        std::vector<Vec3>& mapped = in_our_order[ref->name()];
        mapped = in_our_numbering(trace.back(), run.correspondence.ref_to_ours, ours.levels.back().num_vertices());
        if (keep_view) at_each_level[ref->name()] = levels_in_our_numbering(ours, input_mesh, trace, run.correspondence);
        if (within(tier, run.comparison, run.level_max_rel, run.hausdorff_rel)) {
            run.verdict = Verdict::Agree;
            run.explanation = tier.tier == Tier::Geometric
                                  ? "vertex-set Hausdorff distance " + sci(run.hausdorff_rel) + " <= " + sci(tier.tolerance)
                              : tier.tier == Tier::Strict ? "bitwise identical"
                                                          : "max relative error " + sci(run.comparison.max_rel) + " <= " +
                                                                sci(tier.tolerance) + (in_float ? " (float tier)" : "");
            out.runs.push_back(std::move(run));
            continue;
        }
        run.verdict = Verdict::Diverge;
        const std::string worst = run.comparison.worst.empty()
                                      ? ""
                                      : " (worst: our vertex " + std::to_string(run.comparison.worst[0].ours_index) +
                                            ", valence " + std::to_string(run.comparison.worst[0].valence) +
                                            (run.comparison.worst[0].boundary ? ", boundary" : ", interior") + ")";
        const bool same_faces = run.comparison.topology_equal();
        DivergenceTests tests;
        tests.isolated_vertices = [&]() -> std::optional<Classification> {
            if (!same_faces || !only_isolated_vertices_differ(ours.levels.back(), trace.back(),
                                                              run.correspondence.ref_to_ours, tier.tolerance))
                return std::nullopt;
            return Classification{DivergenceClass::IsolatedVertexHandling,
                                  "only vertices no face uses differ, by up to " + sci(run.comparison.max_rel) + worst};
        };
        tests.rounding = [&]() -> std::optional<Classification> {
            const double ulps = run.comparison.max_abs / ulp_of_largest_coordinate(ours.levels.back());
            if (!same_faces || !(ulps <= tolerances::kRoundingUlps)) return std::nullopt;
            return Classification{DivergenceClass::Rounding, "differs by " + sci(run.comparison.max_rel) +
                                                                 " of the diagonal, which is " + sci(ulps) +
                                                                 " ulps of the largest coordinate" + worst};
        };
        std::string still;  // what core with the reference's rule still differs by, when it does
        // The rule the implementation under test applies, as seen against this reference: of
        // the named rules that fit the subject, the one nearest the reference's (on a closed
        // mesh both boundary rules fit, and only the weights can tell them apart).
        const std::optional<LoopOptions> applied_rule =
            req.subject && out.rules ? nearest_fitting_rule(*out.rules, run.ran_with) : subject_rule;
        tests.reference_rule = [&]() -> std::optional<Classification> {
            if (!same_faces || !applied_rule || run.ran_with == *applied_rule) return std::nullopt;
            // Measured, not assumed: rerun core with the reference's rule; if that agrees, the
            // rule difference explains the whole divergence. Whatever the tier, the rule
            // explains the divergence only if core with that rule equals the reference up to
            // rounding (the weak tier at its tolerance; strict would demand bits, geometric
            // would accept what the rule itself moves).
            const CoreRun& same_rule = core_with(run.ran_with);
            const MeshComparison c2 =
                compare_meshes(same_rule.levels.back(), trace.back(), run.correspondence.ref_to_ours);
            const std::vector<double> e2 = level_errors(same_rule, trace, run.correspondence);
            LoopComparisonRequest up_to_rounding = tier;
            up_to_rounding.tier = Tier::Weak;
            if (tier.tier != Tier::Weak)
                up_to_rounding.tolerance = agreement_tolerance(same_rule.levels.back(), in_float, tolerances::kAgreementRelative,
                                                               in_float ? largest_valence() : 0, req.levels);
            // Two named causes at once: the rule explains every vertex a face uses, and only
            // vertices no face uses differ beyond that (a reference that moves them).
            const bool agrees_with_rule = within(up_to_rounding, c2, e2, NAN);
            const bool but_isolated = !agrees_with_rule && c2.topology_equal() &&
                                      only_isolated_vertices_differ(same_rule.levels.back(), trace.back(),
                                                                    run.correspondence.ref_to_ours, up_to_rounding.tolerance);
            if (!agrees_with_rule && !but_isolated) {
                still = "; with " + describe(run.ran_with) + " still " + sci(c2.max_rel);
                return std::nullopt;
            }
            const std::string agrees = but_isolated ? " at every vertex a face uses (only vertices no face uses differ beyond "
                                                      "that: isolated-vertex-handling too, by up to " + sci(c2.max_rel) + ")"
                                                    : " to " + sci(c2.max_rel);
            // A rule difference explains the divergence only if the rule under test is the
            // published one: core's version of it must pass the oracle that does not read its
            // masks, at the input's interior valences too (loop_rule_oracle.h).
            const RuleVerdict oracle = check_core_loop_rule(*applied_rule, interior_valences());
            if (oracle.known && !oracle.passed) {
                still = "; " + describe(*applied_rule) + " fails its oracle: " + oracle.detail;
                return std::nullopt;
            }
            SchemeRule applied, requested;
            applied.loop = run.ran_with;
            requested.loop = *applied_rule;
            const DivergenceClass cls = rule_difference_class(Scheme::Loop, applied, requested);
            if (req.subject)
                return Classification{cls, subject_name + " applies " + describe(*applied_rule) + ", " + ref->name() + " " +
                                               describe(run.ran_with) + " (it agrees with core's " + describe(run.ran_with) +
                                               agrees + "); they differ by " + sci(run.comparison.max_rel) + worst};
            return Classification{cls, ref->name() + " has no " + describe(req.options) + "; run with " + describe(run.ran_with) +
                                           " it agrees with core's " + describe(run.ran_with) + agrees +
                                           ", and differs from the requested rule by " + sci(run.comparison.max_rel) + worst};
        };
        tests.nonmanifold = [&]() -> std::optional<Classification> {
            // Measured: core took OpenSubdiv's non-manifold rules here, and every vertex that
            // differs by more than the tolerance from core under the reference's own rule
            // (the corner rule it may lack) lies where the non-manifold vertices reach.
            if (!same_faces || req.options.nonmanifold != NonManifoldRule::OpenSubdiv) return std::nullopt;
            const bool own_rule = !applied_rule || run.ran_with == *applied_rule;
            const CoreRun& core_rule = own_rule ? ours : core_with(run.ran_with);
            std::optional<Classification> c =
                nonmanifold_handling(nonmanifold_reach(levels_of(core.front(), input_mesh)), core_rule.levels.back(),
                                     trace.back(), run.correspondence.ref_to_ours, tier.tolerance, ref->name(),
                                     run.comparison.max_rel, own_rule ? "" : " from core with " + describe(run.ran_with));
            if (c) c->explanation += worst;
            return c;
        };
        tests.topology = [&]() -> std::optional<Classification> {
            if (same_faces || !measured_topology_difference(run.comparison.ours, run.comparison.ref, false,
                                                            run.correspondence.method))
                return std::nullopt;
            return Classification{DivergenceClass::Topology,
                                  "refined topology differs: " + std::to_string(run.comparison.faces_only_in_ref) +
                                      " faces only in " + ref->name() + ", " +
                                      std::to_string(run.comparison.faces_only_in_ours) + " only in core"};
        };
        tests.unexplained = [&] {
            if (!same_faces)
                return "the face sets differ only under a match by position (" + std::string(to_string(run.correspondence.method)) +
                       "), which a vertex moved far breaks: not a topology difference; differs by " +
                       sci(run.comparison.max_rel) + worst;
            if (req.subject && !subject_rule)
                return subject_name + " follows no named rule; differs by " + sci(run.comparison.max_rel) + worst;
            return run.ran_with == subject_rule ? "same rules, differs by " + sci(run.comparison.max_rel) + worst
                                                : "differs by " + sci(run.comparison.max_rel) + worst + still;
        };
        const Classification found = classify_divergence(tests);
        run.divergence_class = found.cls;
        run.explanation = found.explanation;
        out.runs.push_back(std::move(run));
    }
    const ReferenceRun* worst_run = nullptr;
    for (const ReferenceRun& r : out.runs)
        if (r.verdict == Verdict::Diverge && !r.comparison.worst.empty() &&
            (!worst_run || r.comparison.worst[0].distance > worst_run->comparison.worst[0].distance))
            worst_run = &r;
    if (worst_run && keep_view) {
        DivergenceView& view = out.view.emplace();
        view.levels.push_back(input_mesh);
        view.levels.insert(view.levels.end(), under_test->levels.begin(), under_test->levels.end());
        view.origins = under_test->origins;
        view.references = std::move(at_each_level);
    }
    if (worst_run) {
        const WorstVertex& w = worst_run->comparison.worst[0];
        out.worst_vertex = CaseWorstVertex{w.ours_index, w.valence, w.boundary, w.ours, std::nullopt, {}};
        if (req.subject) out.worst_vertex->core_with_requested_rule = core.front().levels.back().positions[w.ours_index];
        for (const auto& [name, positions] : in_our_order) out.worst_vertex->reference_positions[name] = positions[w.ours_index];
    }
    return out;
}

LoopComparison compare_loop_refused(const TriMesh& input, const std::string& name, const LoopComparisonRequest& req,
                                    const std::string& core_error) {
    LoopComparison out = empty_comparison(input, name, req);
    out.core_error = core_error;
    // The class names what the input breaks, from the checker's first error.
    const DivergenceClass handling = input_handling_class(to_poly_mesh(input));
    for (const Implementation* ref : selected_references(req)) {
        ReferenceRun run;
        IsolatedTrace iso = run_reference(*ref, input, req, run);
        run.verdict = Verdict::OursRejected;
        if (run.outcome.status == RunStatus::Ok) {
            run.divergence_class = handling;
            const PolyMesh& last = iso.trace->back();
            run.explanation = "core refuses the input (" + core_error + "); " + ref->name() + " refines it to " +
                              std::to_string(last.num_vertices()) + " vertices, " + std::to_string(last.num_faces()) +
                              " faces";
        } else {
            run.explanation = "core refuses the input (" + core_error + "); so does " + ref->name() + " (" +
                              run.outcome.summary() + ")";
        }
        out.runs.push_back(std::move(run));
    }
    return out;
}

nlohmann::json subject_json(const LoopComparison& c) {
    using nlohmann::json;
    auto finite = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    auto fits = [&](const std::vector<RuleFit>& list) {
        json a = json::array();
        for (const RuleFit& f : list) a.push_back({{"rule", describe(f.rule)}, {"max_rel", finite(f.max_rel)}, {"fits", f.fits}});
        return a;
    };
    json s = {{"name", c.subject},
              {"status", to_string(c.subject_outcome.status)},
              {"status_message", c.subject_outcome.message},
              {"seconds", c.subject_outcome.seconds},
              {"unmatched", c.subject_unmatched}};
    if (c.subject_outcome.status == RunStatus::Ok)
        s["match"] = {{"method", to_string(c.subject_match.method)}, {"note", c.subject_match.note}};
    if (c.rules) {
        json rows = json::array();
        for (const VertexClassRow& r : c.rules->rows)
            rows.push_back({{"class", to_string(r.cls)}, {"valence", r.valence}, {"count", r.count},
                            {"worst_vertex", r.worst_vertex}, {"fits", fits(r.fits)}});
        s["rules"] = {{"classified_level", c.rules->classified_level},
                      {"rule", c.rules->rule ? json(describe(*c.rules->rule)) : json(nullptr)},
                      {"whole", fits(c.rules->whole)},
                      {"classes", rows}};
    }
    return s;
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
    json worst = nullptr;
    if (c.worst_vertex) {
        json at = json::object();
        for (const auto& [name, p] : c.worst_vertex->reference_positions)
            at[name] = p.allFinite() ? vec(p) : json(nullptr);
        worst = {{"ours_index", c.worst_vertex->ours_index}, {"valence", c.worst_vertex->valence},
                 {"boundary", c.worst_vertex->boundary}, {"core", vec(c.worst_vertex->core)}, {"references", at}};
        if (c.worst_vertex->core_with_requested_rule) {
            // The subject's value under "subject"; "core" is then core's with the requested rule.
            worst["subject"] = worst["core"];
            worst["core"] = vec(*c.worst_vertex->core_with_requested_rule);
        }
    }
    json runs = json::array();
    for (const ReferenceRun& r : c.runs) {
        json worst_list = json::array();
        for (const WorstVertex& w : r.comparison.worst)
            worst_list.push_back({{"ours_index", w.ours_index}, {"ref_index", w.ref_index}, {"valence", w.valence},
                             {"boundary", w.boundary}, {"ours", vec(w.ours)}, {"ref", vec(w.ref)}, {"distance", w.distance}});
        json run = {{"reference", r.reference},
                    {"version", r.version},
                    {"ran_with", options(r.ran_with)},
                    {"status", to_string(r.outcome.status)},
                    {"status_message", r.outcome.message},
                    {"seconds", r.outcome.seconds},
                    {"verdict", to_string(r.verdict)},
                    {"divergence_class", to_string(r.divergence_class)},
                    {"explanation", r.explanation}};
        if (!std::isnan(r.hausdorff_rel)) run["hausdorff_rel"] = finite(r.hausdorff_rel);
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
                                {"worst", worst_list}};
        }
        runs.push_back(run);
    }
    json out = {{"input", c.input},      {"input_vertices", c.input_vertices}, {"input_faces", c.input_faces},
            {"scheme", "loop"},      {"options", options(c.options)},      {"levels", c.levels},
            {"core_seconds", c.core_seconds}, {"tier", to_string(c.tier)}, {"tolerance_rel", c.tolerance},
            {"core_error", c.core_error},     {"all_agree", c.all_agree()}, {"runs", runs},
            {"worst_vertex", worst}};
    if (c.subject != "core") out["subject"] = subject_json(c);
    return out;
}

}  // namespace crossdiv::verification
