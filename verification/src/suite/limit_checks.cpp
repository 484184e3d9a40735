#include "crossdiv/verification/suite/limit_checks.h"

#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/bfr_comparison.h"
#include "crossdiv/verification/properties/butterfly_properties.h"
#include "crossdiv/verification/comparisons/crease_comparison.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/comparisons/scheme_comparison.h"

namespace crossdiv::verification {
namespace {

using nlohmann::json;

const std::vector<std::string> kStudies = {"limits:catmull-clark", "limits:schemes", "limits:creases",
                                           "limits:opensubdiv", "limits:spectrum", "limits:convergence"};

json check(const std::string& reference, const std::string& name, const std::string& subject, double measured,
           double tolerance, const std::string& unit, const std::string& note) {
    const bool pass = measured <= tolerance;  // NaN fails
    json run = {{"reference", reference}, {"check", name}, {"curve", subject},
                {"measured", std::isfinite(measured) ? json(measured) : json(nullptr)},
                {"tolerance", tolerance}, {"unit", unit}, {"verdict", pass ? "agree" : "diverge"},
                {"explanation", note}};
    if (!pass) run["divergence_class"] = "unexplained";
    return run;
}

/// One check record per reference run of a scheme comparison.
void add_scheme_runs(const SchemeComparison& c, double tolerance, json& runs) {
    for (const SchemeReferenceRun& r : c.runs) {
        json run = {{"reference", r.reference},
                    {"check", std::string(to_string(c.scheme)) + " " + c.rule + " L" + std::to_string(c.levels)},
                    {"curve", c.input},
                    {"measured", std::isfinite(r.comparison.max_rel) ? json(r.comparison.max_rel) : json(nullptr)},
                    {"tolerance", tolerance},
                    {"unit", "rel"},
                    {"verdict", to_string(r.verdict)},
                    {"explanation", r.rule + " rule: " + r.explanation}};
        if (r.divergence_class != DivergenceClass::None) run["divergence_class"] = to_string(r.divergence_class);
        runs.push_back(run);
    }
}

json catmull_clark_study() {
    json runs = json::array(), rows = json::array();
    const std::vector<datasets::BundledMesh> meshes = datasets::catalog_meshes();
    for (CatmullClarkBoundary rule : {CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner}) {
        for (const auto& b : meshes) {
            SchemeRequest req;
            req.rule.catmull_clark = {rule};
            req.levels = 2;
            req.timeout_seconds = 60;
            const SchemeComparison c = compare_scheme(b.mesh, "bundled:" + b.name, req);
            rows.push_back(to_json(c));
            add_scheme_runs(c, req.tolerance, runs);
        }
    }
    return {{"runs", runs}, {"tables", {{"catmull_clark", rows}}}};
}

/// Doo-Sabin, sqrt3 and the modified Butterfly against their references (sqrt3 to 3 levels,
/// so that a boundary step and the step after it are both seen), and the Butterfly
/// properties of both variants.
json schemes_study() {
    json runs = json::array(), rows = json::array(), properties = json::array();
    const std::vector<datasets::BundledMesh> meshes = datasets::catalog_meshes();
    for (const auto& [scheme, levels] : {std::pair{Scheme::DooSabin, 2}, {Scheme::Sqrt3, 3}, {Scheme::ModifiedButterfly, 2}})
        for (const auto& b : meshes) {
            // The triangle schemes' refusal of polygons is tested elsewhere.
            if (scheme != Scheme::DooSabin && !b.mesh.all_triangles())
                continue;
            SchemeRequest req;
            req.scheme = scheme;
            req.levels = levels;
            req.timeout_seconds = 60;
            const SchemeComparison c = compare_scheme(b.mesh, "bundled:" + b.name, req);
            rows.push_back(to_json(c));
            add_scheme_runs(c, req.tolerance, runs);
        }
    for (const auto& b : datasets::bundled_meshes())
        for (ButterflyVariant v : {ButterflyVariant::Classic, ButterflyVariant::Modified}) {
            const ButterflyProperties p = check_butterfly_properties(b.mesh, "bundled:" + b.name, v, 2);
            properties.push_back(to_json(p));
            const std::string who = std::string(to_string(v)) + " L2";
            const std::string input = "bundled:" + b.name;
            runs.push_back(check("property", "interpolation " + who, input, p.max_interpolation_move, 0.0, "abs",
                                 "largest move of an existing vertex at a later level" +
                                     (p.core_error.empty() ? "" : "; core refused: " + p.core_error)));
            runs.push_back(check("property", "plane reproduction " + who, input, p.max_plane_residual,
                                 tolerances::kPlaneReproduction, "rel", "residual of a planar copy of the mesh"));
            runs.push_back(check("property", "published stencil " + who, input,
                                 p.regular_edges - p.regular_edges_published, 0.0, "edges",
                                 std::to_string(p.regular_edges_published) + " of " + std::to_string(p.regular_edges) +
                                     " regular interior edges have exactly 1/2, 1/2, 1/8, 1/8, 4 x -1/16"));
        }
    return {{"runs", runs}, {"tables", {{"schemes", rows}, {"butterfly_properties", properties}}}};
}

json opensubdiv_study() {
    json runs = json::array(), rows = json::array();
    const auto add = [&](const LimitComparison& c) {
        rows.push_back(to_json(c));
        const std::string what = c.scheme + " " + c.rule + " L" + std::to_string(c.levels);
        if (c.verdict == Verdict::RefRejected || c.verdict == Verdict::RefCrashed || c.verdict == Verdict::OursRejected) {
            runs.push_back({{"reference", "opensubdiv"}, {"check", "limit position " + what}, {"curve", c.input},
                            {"measured", nullptr}, {"tolerance", tolerances::kLimitAgreementRelative}, {"unit", "rel"},
                            {"verdict", to_string(c.verdict)}, {"explanation", c.explanation}});
            return;
        }
        runs.push_back(check("opensubdiv", "limit position " + what, c.input, c.max_rel_position,
                             tolerances::kLimitAgreementRelative, "rel", c.explanation));
        if (c.normals_compared > 0)
            runs.push_back(check("opensubdiv", "limit normal " + what, c.input, c.max_normal_angle,
                                 tolerances::kLimitNormalRad, "rad",
                                 std::to_string(c.normals_compared) + " interior vertices"));
    };
    for (const auto& b : datasets::bundled_meshes())
        for (LoopBoundary rule : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner})
            for (int levels : {0, 2}) add(compare_loop_limit(b.mesh, "bundled:" + b.name, {LoopWeights::Loop, rule}, levels));
    for (const auto& b : datasets::catalog_meshes())
        for (CatmullClarkBoundary rule : {CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner})
            for (int levels : {1, 3})  // level 0 of a mesh with non-quads has no limit mask
                add(compare_catmull_clark_limit(b.mesh, "bundled:" + b.name, {rule}, levels));
    // Bfr at (u, v): exact on regular faces, measured on irregular ones.
    json bfr_rows = json::array();
    for (const auto& b : datasets::catalog_meshes())
        for (const std::string scheme : {"loop", "catmull-clark"}) {
            if (scheme == "loop" && !b.mesh.all_triangles()) continue;
            const BfrComparison c = compare_bfr_limit(b.mesh, "bundled:" + b.name, scheme);
            bfr_rows.push_back(to_json(c));
            if (!c.error.empty()) {
                runs.push_back({{"reference", "opensubdiv-bfr"}, {"check", "bfr " + scheme}, {"curve", c.input},
                                {"measured", nullptr}, {"tolerance", tolerances::kBfrRegularRelative}, {"unit", "rel"},
                                {"verdict", "ref-rejected"}, {"explanation", c.error}});
                continue;
            }
            if (c.regular_faces > 0)
                runs.push_back(check("opensubdiv-bfr", "bfr " + scheme + " regular faces", c.input, c.max_regular,
                                     tolerances::kBfrRegularRelative, "rel",
                                     std::to_string(c.regular_faces) + " regular faces, dyadic points of level 1"));
        }
    return {{"runs", runs}, {"tables", {{"limit", rows}, {"bfr", bfr_rows}}}};
}

/// A refined mesh as {positions, faces} for the report's figures.
json mesh_json(const PolyMesh& m) {
    json pos = json::array(), faces = json::array();
    for (const Vec3& p : m.positions) pos.push_back({p.x(), p.y(), p.z()});
    for (int f = 0; f < m.num_faces(); ++f) faces.push_back(std::vector<int>(m.face(f), m.face(f) + m.face_size(f)));
    return {{"positions", pos}, {"faces", faces}};
}

json creases_study() {
    json runs = json::array(), rows = json::array();
    for (const CreaseComparison& c : compare_crease_catalog()) {
        rows.push_back(to_json(c));
        json run = {{"reference", "opensubdiv"},
                    {"check", std::string("creases ") + c.scheme + " " + c.method + " L" + std::to_string(c.levels)},
                    {"curve", c.input},
                    {"measured", std::isfinite(c.max_rel) ? json(c.max_rel) : json(nullptr)},
                    {"tolerance", tolerances::kAgreementRelative},
                    {"unit", "rel"},
                    {"verdict", to_string(c.verdict)},
                    {"explanation", c.explanation}};
        if (c.divergence_class != DivergenceClass::None) run["divergence_class"] = to_string(c.divergence_class);
        runs.push_back(run);
    }
    // The seed's question, as a figure: the cube refined three times, smooth, with its top
    // edges infinitely sharp, and with every edge of sharpness 2.
    json figure = json::array();
    for (auto [key, variant] : {std::pair{"no tags", datasets::CreaseCubeVariant::Smooth},
                                {"top edges infinitely sharp", datasets::CreaseCubeVariant::SharpTop},
                                {"all edges sharpness 2", datasets::CreaseCubeVariant::SemiSharp}}) {
        json m = mesh_json(catmull_clark_subdivide(datasets::crease_cube(variant), {CatmullClarkBoundary::EdgeOnly}, 3));
        m["name"] = key;
        figure.push_back(m);
    }
    return {{"runs", runs}, {"tables", {{"creases", rows}, {"crease_cube", figure}}}};
}

json spectrum_study() {
    json runs = json::array(), rows = json::array();
    for (const std::string s : {"loop", "warren", "catmull-clark"})
        for (int n = 3; n <= 20; ++n) {
            const SpectrumRow r = local_spectrum(s, n);
            rows.push_back(to_json(r));
            const std::string who = s + " n=" + std::to_string(n);
            runs.push_back(check("closed form", "spectrum", who, r.max_difference, tolerances::kSpectrumAgreement, "abs",
                                 "lambda_1 " + std::to_string(r.subdominant) + ", vertex eigenvalue " +
                                     std::to_string(r.vertex_rate)));
            // 0 when the characteristic map is regular (real, double, strictly dominant lambda_1).
            runs.push_back(check("eigen-analysis", "regular characteristic map", who,
                                 r.regular_characteristic_map ? 0.0 : 1.0, 0.0, "",
                                 "multiplicity " + std::to_string(r.subdominant_multiplicity) + ", next " +
                                     std::to_string(r.next) + ", max |imag| " + std::to_string(r.max_imaginary)));
        }
    return {{"runs", runs}, {"tables", {{"spectrum", rows}}}};
}

json convergence_study() {
    json runs = json::array(), rows = json::array();
    for (const std::string s : {"loop", "warren", "catmull-clark"})
        for (int n = 3; n <= 12; ++n) {
            const ConvergenceRow r = convergence(s, n, 8);
            rows.push_back(to_json(r));
            runs.push_back(check("eigen-analysis", "convergence rate", s + " n=" + std::to_string(n),
                                 std::abs(r.fitted_rate - r.vertex_rate) / r.vertex_rate,
                                 tolerances::kConvergenceRateRelative, "rel",
                                 "fitted " + std::to_string(r.fitted_rate) + " vs vertex eigenvalue " +
                                     std::to_string(r.vertex_rate) + " (subdominant " + std::to_string(r.subdominant) + ")"));
        }
    return {{"runs", runs}, {"tables", {{"convergence", rows}}}};
}

}  // namespace

std::vector<std::string> expand_limit_inputs(const std::vector<std::string>& specs) {
    std::vector<std::string> out;
    for (const std::string& s : specs) {
        if (s == "limits:all") {
            out.insert(out.end(), kStudies.begin(), kStudies.end());
        } else if (std::find(kStudies.begin(), kStudies.end(), s) != kStudies.end()) {
            out.push_back(s);
        } else {
            throw InputError("'" + s + "' is not a limits study (limits:all, limits:catmull-clark, limits:schemes, limits:creases, limits:opensubdiv, "
                             "limits:spectrum, limits:convergence)");
        }
    }
    return out;
}

json check_limits(const std::string& input) {
    json rec = input == "limits:catmull-clark" ? catmull_clark_study()
               : input == "limits:schemes"     ? schemes_study()
               : input == "limits:creases"     ? creases_study()
               : input == "limits:opensubdiv"  ? opensubdiv_study()
               : input == "limits:spectrum"    ? spectrum_study()
               : input == "limits:convergence" ? convergence_study()
                                               : throw InputError("unknown limits study '" + input + "'");
    rec["input"] = input;
    rec["scheme"] = "limits";
    return rec;
}

}  // namespace crossdiv::verification
