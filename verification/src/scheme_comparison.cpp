#include "crossdiv/verification/scheme_comparison.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

#include "crossdiv/error.h"
#include "sci.h"
#include "crossdiv/subdiv/catmull_clark.h"
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

/// The rule one reference applies, as core options, and how to run it.
struct SchemeReference {
    std::string name, version;
    /// The rule the reference applies when asked for `requested` (its closest one).
    std::function<CatmullClarkOptions(const CatmullClarkOptions& requested)> rule;
    std::function<adapters::LevelTrace(const PolyMesh&, const CatmullClarkOptions&, int levels)> run;
};

std::vector<SchemeReference> references_of(Scheme scheme) {
    std::vector<SchemeReference> r;
    if (scheme != Scheme::CatmullClark) return r;
#ifdef CROSSDIV_HAS_OPENSUBDIV
    r.push_back({"opensubdiv", adapters::opensubdiv::version(),
                 [](const CatmullClarkOptions& o) {
                     return adapters::opensubdiv::supports(o) ? o : CatmullClarkOptions{CatmullClarkBoundary::EdgeOnly};
                 },
                 [](const PolyMesh& m, const CatmullClarkOptions& o, int levels) {
                     return adapters::opensubdiv::catmull_clark(m, o, levels);
                 }});
#endif
#ifdef CROSSDIV_HAS_OPENMESH
    r.push_back({"openmesh", adapters::openmesh::version(),
                 [](const CatmullClarkOptions&) { return CatmullClarkOptions{CatmullClarkBoundary::MidpointAverage}; },
                 [](const PolyMesh& m, const CatmullClarkOptions&, int levels) {
                     return adapters::openmesh::catmull_clark(m, levels);
                 }});
#endif
#ifdef CROSSDIV_HAS_CGAL
    r.push_back({"cgal", adapters::cgal::version(),
                 [](const CatmullClarkOptions&) { return CatmullClarkOptions{CatmullClarkBoundary::EdgeOnly}; },
                 [](const PolyMesh& m, const CatmullClarkOptions&, int levels) {
                     return adapters::cgal::catmull_clark(m, levels);
                 }});
#endif
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

/// The two rules differ only in the corner rule (EdgeOnly vs EdgeAndCorner), or elsewhere on
/// the boundary.
const char* rule_class(const CatmullClarkOptions& a, const CatmullClarkOptions& b) {
    const auto corner_only = [](CatmullClarkBoundary x) {
        return x == CatmullClarkBoundary::EdgeOnly || x == CatmullClarkBoundary::EdgeAndCorner;
    };
    return corner_only(a.boundary) && corner_only(b.boundary) ? "corner-rule" : "boundary-rule";
}

}  // namespace

const char* to_string(Scheme scheme) {
    switch (scheme) {
        case Scheme::CatmullClark: return "catmull-clark";
    }
    return "?";
}

Scheme scheme_from_string(const std::string& name) {
    if (name == "catmull-clark") return Scheme::CatmullClark;
    throw InputError("unknown scheme '" + name + "' (known: loop, catmull-clark)");
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
    out.rule = std::string(to_string(req.catmull_clark.boundary));
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
        ours = catmull_clark_subdivide(input, req.catmull_clark, req.levels);
    } catch (const InputError& e) {
        out.core_error = e.what();
    }
    out.core_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    for (const SchemeReference& ref : refs) {
        SchemeReferenceRun run;
        run.reference = ref.name;
        run.version = ref.version;
        const CatmullClarkOptions ref_rule = ref.rule(req.catmull_clark);
        run.rule = std::string(to_string(ref_rule.boundary));
        IsolatedTrace it = run_isolated([&] { return ref.run(input, req.catmull_clark, req.levels); },
                                        req.timeout_seconds, req.isolate);
        run.outcome = it.outcome;
        if (run.outcome.status == RunStatus::Rejected) {
            run.verdict = "ref-rejected";
            run.explanation = run.outcome.message;
        } else if (run.outcome.status != RunStatus::Ok) {
            run.verdict = "ref-crashed";
            run.explanation = run.outcome.summary();
        } else if (!out.core_error.empty()) {
            run.verdict = "ours-rejected";
            run.explanation = "core refused the input; " + ref.name + " made a mesh of " +
                              std::to_string(it.trace->back().num_vertices()) + " vertices and " +
                              std::to_string(it.trace->back().num_faces()) + " faces";
        } else {
            const PolyMesh& theirs = it.trace->back();
            const PolyMesh same_rule =
                ref_rule == req.catmull_clark ? ours : catmull_clark_subdivide(input, ref_rule, req.levels);
            // Match against core with the reference's rule (the same vertex order as ours):
            // positions then coincide up to rounding, so nearest-neighbour matching is sound
            // even where the requested rule moves vertices.
            run.correspondence = match_nearest(same_rule.positions, theirs.positions);
            if (run.correspondence.method == MatchMethod::None) {
                run.verdict = "diverge";
                run.divergence_class = "topology";
                run.explanation = "no vertex bijection with core's " + run.rule + " refinement (" +
                                  run.correspondence.note + "); " + std::to_string(theirs.num_faces()) +
                                  " faces against core's " + std::to_string(ours.num_faces());
            } else {
                run.comparison = compare_meshes(ours, theirs, run.correspondence.ref_to_ours);
                const MeshComparison with_rule = compare_meshes(same_rule, theirs, run.correspondence.ref_to_ours);
                run.max_rel_with_reference_rule = with_rule.max_rel;
                const double ulps = run.comparison.max_abs / ulp_of_largest_coordinate(ours);
                if (run.comparison.topology_equal() && run.comparison.max_rel <= req.tolerance) {
                    run.verdict = "agree";
                    run.explanation = "max relative error " + sci(run.comparison.max_rel) + " <= " + sci(req.tolerance);
                } else {
                    run.verdict = "diverge";
                    if (!run.comparison.topology_equal()) {
                        run.divergence_class = "topology";
                        run.explanation = std::to_string(run.comparison.faces_only_in_ref) + " faces only in " + ref.name +
                                          ", " + std::to_string(run.comparison.faces_only_in_ours) + " only in core";
                    } else if (ulps <= tolerances::kRoundingUlps) {
                        run.divergence_class = "rounding";
                        run.explanation = "differs by " + sci(ulps) + " ulps of the largest coordinate";
                    } else if (!(ref_rule == req.catmull_clark) && with_rule.max_rel <= req.tolerance) {
                        run.divergence_class = rule_class(ref_rule, req.catmull_clark);
                        run.explanation = ref.name + " applies the " + run.rule + " boundary rule: core with it agrees to " +
                                          sci(with_rule.max_rel) + ", core's " + out.rule + " differs by " +
                                          sci(run.comparison.max_rel) + " of the diagonal";
                    } else {
                        run.divergence_class = "unexplained";
                        run.explanation = "differs by " + sci(run.comparison.max_rel) + "; with " + ref.name + "'s " +
                                          run.rule + " rule still " + sci(with_rule.max_rel);
                    }
                }
            }
        }
        out.runs.push_back(std::move(run));
    }
    return out;
}

adapters::LevelTrace run_scheme_reference(const std::string& name, const SchemeRequest& req, const PolyMesh& mesh,
                                          std::string& rule) {
    const SchemeReference ref = find_reference(req.scheme, name);
    rule = std::string(to_string(ref.rule(req.catmull_clark).boundary));
    return ref.run(mesh, req.catmull_clark, req.levels);
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
