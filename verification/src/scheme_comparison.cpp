#include "crossdiv/verification/scheme_comparison.h"

#include "crossdiv/verification/mesh_topology.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

#include "crossdiv/error.h"
#include "sci.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/butterfly.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/doo_sabin.h"
#include "crossdiv/subdiv/sqrt3.h"
#ifdef CROSSDIV_HAS_OPENSUBDIV
#include "crossdiv/adapters/opensubdiv.h"
#endif
#ifdef CROSSDIV_HAS_OPENMESH
#include "crossdiv/adapters/openmesh.h"
#endif
#ifdef CROSSDIV_HAS_CGAL
#include "crossdiv/adapters/cgal.h"
#endif

namespace crossdiv::verification {
namespace {

using detail::sci;

/// The rule one reference applies, and how to run it.
struct SchemeReference {
    std::string name, version;
    /// The rule the reference applies when asked for `requested` (its closest one).
    std::function<SchemeRule(const SchemeRule& requested)> rule;
    std::function<adapters::LevelTrace(const PolyMesh&, const SchemeRule&, int levels)> run;
    /// The largest valence its weight table holds (0: any), with where that is written.
    int max_valence = 0;
    std::string valence_table;
};

/// A rule that is `requested` with one member replaced.
template <class Member, class Value>
std::function<SchemeRule(const SchemeRule&)> with(Member member, Value value) {
    return [member, value](const SchemeRule& requested) {
        SchemeRule r = requested;
        r.*member = value;
        return r;
    };
}
const auto as_requested = [](const SchemeRule& requested) { return requested; };

#if defined(CROSSDIV_HAS_OPENMESH) || defined(CROSSDIV_HAS_CGAL)
/// The triangle schemes' adapters take a TriMesh; a polygon is the reference's refusal.
TriMesh triangles_for(const PolyMesh& m, const char* scheme) {
    try {
        return to_tri_mesh(m, scheme);
    } catch (const InputError& e) {
        throw adapters::Rejected(e.what());
    }
}
#endif

std::vector<SchemeReference> references_of(Scheme scheme) {
    std::vector<SchemeReference> r;
    [[maybe_unused]] const auto sqrt3_rule = [](Sqrt3Parity p) { return with(&SchemeRule::sqrt3, Sqrt3Options{p}); };
    switch (scheme) {
        case Scheme::CatmullClark:
#ifdef CROSSDIV_HAS_OPENSUBDIV
            r.push_back({"opensubdiv", adapters::opensubdiv::version(),
                         [](const SchemeRule& o) {
                             SchemeRule r = o;
                             if (!adapters::opensubdiv::supports(o.catmull_clark)) r.catmull_clark = {CatmullClarkBoundary::EdgeOnly};
                             return r;
                         },
                         [](const PolyMesh& m, const SchemeRule& o, int levels) {
                             return adapters::opensubdiv::catmull_clark(m, o.catmull_clark, levels);
                         }});
#endif
#ifdef CROSSDIV_HAS_OPENMESH
            r.push_back({"openmesh", adapters::openmesh::version(),
                         with(&SchemeRule::catmull_clark, CatmullClarkOptions{CatmullClarkBoundary::MidpointAverage}),
                         [](const PolyMesh& m, const SchemeRule&, int levels) { return adapters::openmesh::catmull_clark(m, levels); }});
#endif
#ifdef CROSSDIV_HAS_CGAL
            r.push_back({"cgal", adapters::cgal::version(),
                         with(&SchemeRule::catmull_clark, CatmullClarkOptions{CatmullClarkBoundary::EdgeOnly}),
                         [](const PolyMesh& m, const SchemeRule&, int levels) { return adapters::cgal::catmull_clark(m, levels); }});
#endif
            break;
        case Scheme::DooSabin:
#ifdef CROSSDIV_HAS_CGAL
            r.push_back({"cgal", adapters::cgal::version(),
                         with(&SchemeRule::doo_sabin, DooSabinOptions{DooSabinBoundary::DropBorderFaces}),
                         [](const PolyMesh& m, const SchemeRule&, int levels) { return adapters::cgal::doo_sabin(m, levels); }});
#endif
            break;
        case Scheme::Sqrt3:
            // Both libraries count the boundary generations within one call: called once per
            // level (as every other trace is made) they never refine the boundary; asked for
            // all levels in one call they follow Kobbelt. Both ways are references.
#ifdef CROSSDIV_HAS_OPENMESH
            // Sqrt3T fills its weights for valences below 50 (init_weights(50)) and indexes the
            // table with the valence unchecked.
            r.push_back({"openmesh", adapters::openmesh::version(), sqrt3_rule(Sqrt3Parity::RestartEachLevel),
                         [](const PolyMesh& m, const SchemeRule&, int levels) {
                             return adapters::openmesh::sqrt3(triangles_for(m, "sqrt3"), levels, false);
                         },
                         49, "Sqrt3T::init_weights(50)"});
            r.push_back({"openmesh-one-call", adapters::openmesh::version(), sqrt3_rule(Sqrt3Parity::CountFromInput),
                         [](const PolyMesh& m, const SchemeRule&, int levels) {
                             return adapters::openmesh::sqrt3(triangles_for(m, "sqrt3"), levels, true);
                         },
                         49, "Sqrt3T::init_weights(50)"});
#endif
#ifdef CROSSDIV_HAS_CGAL
            r.push_back({"cgal", adapters::cgal::version(), sqrt3_rule(Sqrt3Parity::RestartEachLevel),
                         [](const PolyMesh& m, const SchemeRule&, int levels) {
                             return adapters::cgal::sqrt3(triangles_for(m, "sqrt3"), levels, false);
                         }});
            r.push_back({"cgal-one-call", adapters::cgal::version(), sqrt3_rule(Sqrt3Parity::CountFromInput),
                         [](const PolyMesh& m, const SchemeRule&, int levels) {
                             return adapters::cgal::sqrt3(triangles_for(m, "sqrt3"), levels, true);
                         }});
#endif
            break;
        case Scheme::ModifiedButterfly:
#ifdef CROSSDIV_HAS_OPENMESH
            r.push_back({"openmesh", adapters::openmesh::version(), as_requested,
                         [](const PolyMesh& m, const SchemeRule&, int levels) {
                             return adapters::openmesh::modified_butterfly(triangles_for(m, "modified-butterfly"), levels);
                         }});
#endif
            break;
        case Scheme::Butterfly:  // no library has the classic scheme: butterfly_properties() checks it
            break;
    }
    return r;
}

SchemeReference find_reference(Scheme scheme, const std::string& name) {
    std::string known;
    for (const SchemeReference& r : references_of(scheme)) {
        if (r.name == name) return r;
        known += (known.empty() ? "" : ", ") + r.name;
    }
    throw InputError("reference '" + name + "' has no " + to_string(scheme) + " in this build (those that have it: " +
                     (known.empty() ? "none" : known) + ")");
}

double ulp_of_largest_coordinate(const PolyMesh& m) {
    double largest = 0;
    for (const Vec3& p : m.positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    return std::nextafter(largest, INFINITY) - largest;
}

/// The class of a divergence that the reference's rule explains.
const char* rule_class(Scheme scheme, const SchemeRule& ref, const SchemeRule& requested) {
    switch (scheme) {
        case Scheme::CatmullClark: {
            const auto corner_only = [](CatmullClarkBoundary x) {
                return x == CatmullClarkBoundary::EdgeOnly || x == CatmullClarkBoundary::EdgeAndCorner;
            };
            return corner_only(ref.catmull_clark.boundary) && corner_only(requested.catmull_clark.boundary) ? "corner-rule"
                                                                                                            : "boundary-rule";
        }
        case Scheme::DooSabin:
            return ref.doo_sabin.boundary == DooSabinBoundary::DropBorderFaces ? "border-faces-dropped" : "boundary-rule";
        case Scheme::Sqrt3: return "parity";
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: break;
    }
    return "boundary-rule";
}

/// What the reference's rule does, for the explanation.
std::string rule_effect(Scheme scheme, const std::string& ref_name, const std::string& rule, int levels) {
    switch (scheme) {
        case Scheme::DooSabin: return ref_name + " drops the faces of border edges and vertices";
        case Scheme::Sqrt3:
            return ref_name + (rule == "restart-each-level"
                                   ? " counts generations per call, and was called once per level, so it never refined the boundary"
                                   : " counts generations from the input (one call of " + std::to_string(levels) + " levels)");
        default: return ref_name + " applies the " + rule + " boundary rule";
    }
}

/// When the reference's weight table is shorter than the input's largest valence: whether at
/// level 1 exactly the vertices beyond the table differ (the others agree within `tolerance`);
/// fills `explanation` with the figures. Later levels inherit the difference from them.
bool beyond_valence_table(const SchemeReference& ref, Scheme scheme, const SchemeRule& ref_rule, const PolyMesh& input,
                          const adapters::LevelTrace& trace, double tolerance, std::string& explanation) {
    if (ref.max_valence <= 0 || trace.size() < 2) return false;
    const MeshTopology topo = mesh_topology(input);
    int beyond = 0, largest = 0;
    for (int v = 0; v < input.num_vertices(); ++v) {
        beyond += topo.valence[v] > ref.max_valence;
        largest = std::max(largest, topo.valence[v]);
    }
    if (beyond == 0) return false;
    const PolyMesh ours = subdivide(scheme, ref_rule, input, 1);
    const Correspondence c = match_nearest_and_faces(ours, trace[1]);
    if (c.method == MatchMethod::None) return false;
    const std::vector<double> d = vertex_distances(ours, trace[1], c.ref_to_ours);
    const double diagonal = bounding_box_diagonal(ours.positions);
    int differing = 0;
    double worst = 0;
    for (size_t i = 0; i < d.size(); ++i) {
        if (!(d[i] > tolerance * diagonal)) continue;
        const int v = c.ref_to_ours[i];  // core keeps old vertices first, in input order
        if (v >= input.num_vertices() || topo.valence[v] <= ref.max_valence) return false;
        ++differing;
        worst = std::max(worst, d[i] / diagonal);
    }
    if (differing != beyond) return false;
    explanation = ref.name + "'s weight table ends at valence " + std::to_string(ref.max_valence) + " (" +
                  ref.valence_table + "); at level 1 exactly the " + std::to_string(beyond) +
                  " vertices of larger valence (up to " + std::to_string(largest) + ") differ, by up to " + sci(worst) +
                  " of the diagonal, and every other vertex agrees";
    return true;
}

}  // namespace

const char* to_string(Scheme scheme) {
    switch (scheme) {
        case Scheme::CatmullClark: return "catmull-clark";
        case Scheme::DooSabin: return "doo-sabin";
        case Scheme::Sqrt3: return "sqrt3";
        case Scheme::Butterfly: return "butterfly";
        case Scheme::ModifiedButterfly: return "modified-butterfly";
    }
    return "?";
}

std::vector<Scheme> all_schemes() {
    return {Scheme::CatmullClark, Scheme::DooSabin, Scheme::Sqrt3, Scheme::Butterfly, Scheme::ModifiedButterfly};
}

Scheme scheme_from_string(const std::string& name) {
    std::string known = "loop";
    for (Scheme s : all_schemes()) {
        if (name == to_string(s)) return s;
        known += std::string(", ") + to_string(s);
    }
    throw InputError("unknown scheme '" + name + "' (known: " + known + ")");
}

std::string rule_name(Scheme scheme, const SchemeRule& rule) {
    switch (scheme) {
        case Scheme::CatmullClark: return std::string(to_string(rule.catmull_clark.boundary));
        case Scheme::DooSabin: return std::string(to_string(rule.doo_sabin.boundary));
        case Scheme::Sqrt3: return std::string(to_string(rule.sqrt3.parity));
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: break;
    }
    return "-";
}

bool same_rule(Scheme scheme, const SchemeRule& a, const SchemeRule& b) { return rule_name(scheme, a) == rule_name(scheme, b); }

PolyMesh subdivide(Scheme scheme, const SchemeRule& rule, const PolyMesh& mesh, int levels) {
    switch (scheme) {
        case Scheme::CatmullClark: return catmull_clark_subdivide(mesh, rule.catmull_clark, levels);
        case Scheme::DooSabin: return doo_sabin_subdivide(mesh, rule.doo_sabin, levels);
        case Scheme::Sqrt3: return sqrt3_subdivide(mesh, rule.sqrt3, levels);
        case Scheme::Butterfly: return butterfly_subdivide(mesh, ButterflyVariant::Classic, levels);
        case Scheme::ModifiedButterfly: return butterfly_subdivide(mesh, ButterflyVariant::Modified, levels);
    }
    throw InputError("unknown scheme");
}

std::vector<std::string> scheme_reference_names(Scheme scheme) {
    std::vector<std::string> names;
    for (const SchemeReference& r : references_of(scheme)) names.push_back(r.name);
    return names;
}

bool SchemeComparison::all_agree() const {
    if (!core_error.empty() || runs.empty()) return false;
    for (const SchemeReferenceRun& r : runs)
        if (r.verdict != "agree") return false;
    return true;
}

SchemeComparison compare_scheme(const PolyMesh& input, const std::string& name, const SchemeRequest& req) {
    SchemeComparison out;
    out.input = name;
    out.scheme = req.scheme;
    out.rule = rule_name(req.scheme, req.rule);
    out.levels = req.levels;
    out.input_vertices = input.num_vertices();
    out.input_faces = input.num_faces();

    std::vector<SchemeReference> refs = references_of(req.scheme);
    if (!req.references.empty()) {
        std::vector<SchemeReference> chosen;
        for (const std::string& want : req.references) chosen.push_back(find_reference(req.scheme, want));
        refs = std::move(chosen);
    }

    // Core under the requested rule, and under each reference's rule when it differs.
    PolyMesh ours;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        ours = subdivide(req.scheme, req.rule, input, req.levels);
    } catch (const InputError& e) {
        out.core_error = e.what();
    }
    out.core_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    for (const SchemeReference& ref : refs) {
        SchemeReferenceRun run;
        run.reference = ref.name;
        run.version = ref.version;
        const SchemeRule ref_rule = ref.rule(req.rule);
        const bool rules_differ = !same_rule(req.scheme, ref_rule, req.rule);
        run.rule = rule_name(req.scheme, ref_rule);
        IsolatedTrace it =
            run_isolated([&] { return ref.run(input, req.rule, req.levels); }, req.timeout_seconds, req.isolate);
        run.outcome = it.outcome;
        if (run.outcome.status == RunStatus::Rejected) {
            run.verdict = "ref-rejected";
            run.explanation = run.outcome.message;
            out.runs.push_back(std::move(run));
            continue;
        }
        if (run.outcome.status != RunStatus::Ok) {
            run.verdict = "ref-crashed";
            run.explanation = run.outcome.summary();
            out.runs.push_back(std::move(run));
            continue;
        }
        const PolyMesh& theirs = it.trace->back();
        if (!out.core_error.empty()) {
            run.verdict = "ours-rejected";
            run.explanation = "core refused the input; " + ref.name + " made a mesh of " +
                              std::to_string(theirs.num_vertices()) + " vertices and " +
                              std::to_string(theirs.num_faces()) + " faces";
            out.runs.push_back(std::move(run));
            continue;
        }
        const PolyMesh same_rule_mesh = rules_differ ? subdivide(req.scheme, ref_rule, input, req.levels) : ours;
        // Match against core with the reference's rule: positions then coincide up to
        // rounding, so nearest-neighbour matching is sound even where the requested rule
        // moves vertices (or makes others).
        run.correspondence = match_nearest_and_faces(same_rule_mesh, theirs);
        if (run.correspondence.method == MatchMethod::None) {
            run.verdict = "diverge";
            run.divergence_class = "topology";
            run.explanation = "no vertex bijection with core's " + run.rule + " refinement (" + run.correspondence.note +
                              "); " + std::to_string(theirs.num_faces()) + " faces against core's " +
                              std::to_string(ours.num_faces());
            out.runs.push_back(std::move(run));
            continue;
        }
        // Under the requested rule the same map holds only where the vertex sets coincide;
        // otherwise compare_meshes reports the counts and no distances.
        const std::vector<int> no_map;
        run.comparison = compare_meshes(ours, theirs, rules_differ && ours.num_vertices() != same_rule_mesh.num_vertices()
                                                          ? no_map
                                                          : run.correspondence.ref_to_ours);
        const MeshComparison with_rule = compare_meshes(same_rule_mesh, theirs, run.correspondence.ref_to_ours);
        run.max_rel_with_reference_rule = with_rule.max_rel;
        const bool rule_explains = rules_differ && with_rule.topology_equal() && with_rule.max_rel <= req.tolerance;
        if (run.comparison.topology_equal() && run.comparison.max_rel <= req.tolerance) {
            run.verdict = "agree";
            run.explanation = "max relative error " + sci(run.comparison.max_rel) + " <= " + sci(req.tolerance);
        } else {
            run.verdict = "diverge";
            const double ulps = run.comparison.max_abs / ulp_of_largest_coordinate(ours);
            const std::string faces = std::to_string(theirs.num_faces()) + " faces and " +
                                      std::to_string(theirs.num_vertices()) + " vertices against core's " +
                                      std::to_string(ours.num_faces()) + " and " + std::to_string(ours.num_vertices());
            if (run.comparison.topology_equal() && ulps <= tolerances::kRoundingUlps) {
                run.divergence_class = "rounding";
                run.explanation = "differs by " + sci(ulps) + " ulps of the largest coordinate";
            } else if (rule_explains) {
                run.divergence_class = rule_class(req.scheme, ref_rule, req.rule);
                run.explanation = rule_effect(req.scheme, ref.name, run.rule, req.levels) + ": core with " + run.rule +
                                  " agrees to " + sci(with_rule.max_rel) + "; core's " + out.rule +
                                  (run.comparison.topology_equal()
                                       ? " differs by " + sci(run.comparison.max_rel) + " of the diagonal"
                                       : " makes different faces (" + faces + ")");
            } else if (std::string why; beyond_valence_table(ref, req.scheme, ref_rule, input, *it.trace, req.tolerance, why)) {
                run.divergence_class = "valence-limit";
                run.explanation = why;
            } else if (!run.comparison.topology_equal()) {
                run.divergence_class = "topology";
                run.explanation = faces + "; " + std::to_string(run.comparison.faces_only_in_ref) + " faces only in " +
                                  ref.name + ", " + std::to_string(run.comparison.faces_only_in_ours) + " only in core";
            } else {
                run.divergence_class = "unexplained";
                run.explanation = "differs by " + sci(run.comparison.max_rel) + "; with " + ref.name + "'s " + run.rule +
                                  " rule still " + sci(with_rule.max_rel);
            }
        }
        out.runs.push_back(std::move(run));
    }
    return out;
}

adapters::LevelTrace run_scheme_reference(const std::string& name, const SchemeRequest& req, const PolyMesh& mesh,
                                          std::string& rule) {
    const SchemeReference ref = find_reference(req.scheme, name);
    rule = rule_name(req.scheme, ref.rule(req.rule));
    return ref.run(mesh, req.rule, req.levels);
}

nlohmann::json to_json(const SchemeComparison& c) {
    using nlohmann::json;
    const auto finite = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
    json runs = json::array();
    for (const SchemeReferenceRun& r : c.runs) {
        json run = {{"reference", r.reference},
                    {"version", r.version},
                    {"rule", r.rule},
                    {"outcome", r.outcome.summary()},
                    {"seconds", r.outcome.seconds},
                    {"verdict", r.verdict},
                    {"divergence_class", r.divergence_class},
                    {"explanation", r.explanation},
                    {"correspondence", to_string(r.correspondence.method)}};
        if (r.correspondence.method != MatchMethod::None && r.outcome.status == RunStatus::Ok) {
            run["faces_only_in_core"] = r.comparison.faces_only_in_ours;
            run["faces_only_in_reference"] = r.comparison.faces_only_in_ref;
            run["max_rel"] = finite(r.comparison.max_rel);
            run["rms_rel"] = finite(r.comparison.rms_rel);
            run["max_rel_with_reference_rule"] = finite(r.max_rel_with_reference_rule);
        }
        runs.push_back(run);
    }
    return {{"input", c.input},           {"scheme", to_string(c.scheme)}, {"rule", c.rule},
            {"levels", c.levels},         {"input_vertices", c.input_vertices}, {"input_faces", c.input_faces},
            {"core_seconds", c.core_seconds}, {"core_error", c.core_error}, {"all_agree", c.all_agree()},
            {"runs", runs}};
}

}  // namespace crossdiv::verification
