#include "suite/studies.h"

#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/bfr_comparison.h"
#include "crossdiv/verification/properties/butterfly_properties.h"
#include "crossdiv/verification/comparisons/crease_comparison.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/vertex_age.h"
#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/properties/loop_rule_oracle.h"
#include "crossdiv/verification/properties/rule_oracle.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

using nlohmann::json;

Check check(const std::string& reference, const std::string& name, const std::string& subject, double measured,
            double tolerance, const std::string& unit, const std::string& note) {
    return {subject, name, reference, measured, tolerance, unit, note, std::nullopt};
}

/// A check whose outcome was decided by a comparison (a refusal, a classified divergence).
Check decided(const std::string& reference, const std::string& name, const std::string& subject, double measured,
              double tolerance, const std::string& unit, const std::string& note, Outcome outcome) {
    return {subject, name, reference, measured, tolerance, unit, note, outcome};
}

}  // namespace

/// The Butterfly properties of both variants on the bundled meshes, and the rules no library
/// has in full (Doo-Sabin's Chaikin boundary, sqrt3's parities, the classic Butterfly's wings)
/// against the points written out from their sources. The comparisons of each scheme with its
/// references are the per-input cases of its own operation.
CheckReport schemes_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json properties = json::array();
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
    // Doo-Sabin's Chaikin boundary has no reference (CGAL drops the border faces): both rules
    // against the points written out from their sources (rule_oracle.h).
    for (DooSabinBoundary b : {DooSabinBoundary::ChaikinBoundary, DooSabinBoundary::DropBorderFaces}) {
        const RuleVerdict v = check_doo_sabin_rule(core_implementation(), {b});
        runs.push_back(check("published points", "doo-sabin rule oracle", std::string(to_string(b)), v.worst_rel,
                             tolerances::kAgreementRelative, "rel", v.detail));
    }
    // sqrt3's parities: which generations refine the boundary, against Kobbelt's rules.
    for (Sqrt3Parity parity : {Sqrt3Parity::CountFromInput, Sqrt3Parity::RestartEachLevel}) {
        const RuleVerdict v = check_sqrt3_rule(core_implementation(), {parity});
        runs.push_back(check("published points", "sqrt3 rule oracle", std::string(to_string(parity)), v.worst_rel,
                             tolerances::kAgreementRelative, "rel", v.detail));
    }
    // The classic Butterfly's wing rules: MeshLab's is the one reference, and only when the
    // manifest registers it.
    for (ButterflyWings w : kAllButterflyWings) {
        const RuleVerdict v = check_butterfly_rule(core_implementation(), w);
        runs.push_back(check("published points", "butterfly rule oracle", std::string(to_string(w)), v.worst_rel,
                             tolerances::kAgreementRelative, "rel", v.detail));
    }
    out.tables = {{"butterfly_properties", properties}};
    return out;
}

CheckReport limit_positions_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
    const auto add = [&](const LimitComparison& c) {
        rows.push_back(to_json(c));
        const std::string what = c.scheme + " " + c.rule + " L" + std::to_string(c.levels);
        if (c.verdict != Verdict::Agree && c.verdict != Verdict::Diverge) {
            runs.push_back(decided("opensubdiv", "limit position " + what, c.input, NAN, tolerances::kLimitAgreementRelative,
                                   "rel", c.explanation, {c.verdict, DivergenceClass::None}));
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
                runs.push_back(decided("opensubdiv-bfr", "bfr " + scheme, c.input, NAN, tolerances::kBfrRegularRelative, "rel",
                                       c.error, {Verdict::RefRejected, DivergenceClass::None}));
                continue;
            }
            if (c.regular_faces > 0)
                runs.push_back(check("opensubdiv-bfr", "bfr " + scheme + " regular faces", c.input, c.max_regular,
                                     tolerances::kBfrRegularRelative, "rel",
                                     std::to_string(c.regular_faces) + " regular faces, dyadic points of level 1"));
        }
    out.tables = {{"limit", rows}, {"bfr", bfr_rows}};
    return out;
}

json mesh_json(const PolyMesh& m) {
    json pos = json::array(), faces = json::array();
    for (const Vec3& p : m.positions) pos.push_back({p.x(), p.y(), p.z()});
    for (int f = 0; f < m.num_faces(); ++f) faces.push_back(std::vector<int>(m.face(f), m.face(f) + m.face_size(f)));
    return {{"positions", pos}, {"faces", faces}};
}

CheckReport creases_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
    for (const CreaseComparison& c : compare_crease_catalog()) {
        rows.push_back(to_json(c));
        runs.push_back(decided("opensubdiv", std::string("creases ") + c.scheme + " " + c.method + " L" + std::to_string(c.levels),
                               c.input, c.max_rel, tolerances::kAgreementRelative, "rel", c.explanation,
                               {c.verdict, c.divergence_class}));
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
    out.tables = {{"creases", rows}, {"crease_cube", figure}};
    return out;
}

CheckReport vertex_age_study() {
    CheckReport out;
    json rows = json::array();
    const PolyMesh input = datasets::bundled_mesh("icosahedron");
    constexpr int kLevels = 3;
    for (Scheme scheme : all_schemes()) {
        const adapters::LevelTrace levels = core_implementation().refine(input, {scheme, SchemeRule{}, kLevels});
        std::vector<size_t> counts;
        for (const PolyMesh& m : levels) counts.push_back(m.positions.size());
        const bool dual = scheme == Scheme::DooSabin;
        const std::vector<int> born = vertex_birth_levels(counts, dual);
        // The vertices each level adds, from the level before's topology (the icosahedron and
        // its refinements are closed, so E is half the face corners): Loop and the Butterflies
        // one per edge, Catmull-Clark one per edge and face, sqrt3 one per face; Doo-Sabin
        // one per face corner, every vertex new.
        std::vector<long> expected(kLevels + 1, 0), measured(kLevels + 1, 0);
        expected[0] = dual ? 0 : static_cast<long>(counts[0]);
        for (int l = 1; l <= kLevels; ++l) {
            const PolyMesh& before = levels[l - 1];
            const long corners = static_cast<long>(before.face_vertices.size()), faces = before.num_faces();
            const long edges = corners / 2;
            switch (scheme) {
                case Scheme::CatmullClark: expected[l] = edges + faces; break;
                case Scheme::Sqrt3: expected[l] = faces; break;
                case Scheme::DooSabin: expected[l] = l == kLevels ? corners : 0; break;
                default: expected[l] = edges;
            }
        }
        for (int b : born) ++measured[b];
        long mismatch = 0;
        for (int l = 0; l <= kLevels; ++l) mismatch += std::abs(measured[l] - expected[l]);
        const std::string who = std::string(to_string(scheme)) + " icosahedron L3";
        out.checks.push_back(count_check(who, "vertex-age counts", "topology", static_cast<double>(mismatch),
                                         "vertices born at each level vs the input's, then E, E + F, F (sqrt3) or "
                                         "every face corner (Doo-Sabin) of the level before"));
        json row = {{"scheme", to_string(scheme)}, {"input", "icosahedron"}, {"levels", kLevels},
                    {"vertex_counts", counts}, {"born", measured}, {"expected", expected}};
        if (scheme == Scheme::Butterfly || scheme == Scheme::ModifiedButterfly) {
            // Interpolating: the oldest vertices are where the input put them, exactly.
            double moved = 0;
            for (size_t v = 0; v < counts[0]; ++v)
                moved = std::max(moved, (levels.back().positions[v] - input.positions[v]).norm());
            out.checks.push_back(check("analytic", "age-0 vertices fixed", who, moved, 0.0, "abs",
                                       "the input's vertices, age 0, at their input positions after 3 levels"));
        }
        if (scheme == Scheme::Loop || scheme == Scheme::CatmullClark) {
            row["mesh"] = mesh_json(levels.back());
            row["ages"] = born;
        }
        rows.push_back(row);
    }
    out.tables = {{"vertex_age", rows}};
    return out;
}

CheckReport spectrum_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
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
    // The Loop rules no reference has in full (Warren's weights; the corner rule CGAL and
    // OpenMesh lack) checked against the stencils as published, not against core's masks.
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren})
        for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
            const RuleVerdict v = check_core_loop_rule({w, b}, {13, 14, 15, 16, 17, 18, 19, 20, 64, 360});
            runs.push_back(check("published stencils", "loop rule oracle",
                                 std::string(to_string(w)) + " " + std::string(to_string(b)), v.worst_rel,
                                 tolerances::kAgreementRelative, "rel", v.detail));
        }
    out.tables = {{"spectrum", rows}};
    return out;
}

CheckReport convergence_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
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
    out.tables = {{"convergence", rows}};
    return out;
}

}  // namespace crossdiv::verification
