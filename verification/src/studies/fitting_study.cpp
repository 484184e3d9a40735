// The fitting study: exact recovery of control points from their own limit surface on the
// catalog, and closest-point fitting of Loop and Catmull-Clark limit surfaces to the CGAL demo
// meshes and the course bunny, with CGAL's Hausdorff distance at every iteration.
#include "crossdiv/verification/studies/fitting_study.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/comparisons/limit_fitting_run.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/studies/studies.h"

namespace crossdiv::verification {

using nlohmann::json;

bool has_checkerboard_kernel(const PolyMesh& mesh) {
    const PolyConnectivity conn = build_poly_connectivity(mesh);
    std::vector<int> colour(static_cast<size_t>(mesh.num_vertices()), -1);
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (conn.vertex_corner[v] < 0 || conn.is_boundary_vertex(v) || conn.fan(v).faces != 3) return false;
    std::vector<int> stack;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (colour[v] >= 0) continue;
        colour[v] = 0;
        stack.assign(1, v);
        while (!stack.empty()) {
            const int u = stack.back();
            stack.pop_back();
            const int start = conn.vertex_corner[u];
            for (int c = start;;) {
                const int w = conn.head(c);
                if (colour[w] == colour[u]) return false;
                if (colour[w] < 0) colour[w] = 1 - colour[u], stack.push_back(w);
                c = conn.next_around_vertex(c);
                if (c == start) break;
            }
        }
    }
    return mesh.num_vertices() > 0;
}

namespace {

/// Exact recovery: every catalog mesh under Catmull-Clark, the triangle meshes under Loop too,
/// sampled 2 levels deep; the system singular exactly where the checkerboard mode predicts it.
json recovery(CheckReport& out) {
    json rows = json::array();
    int wrong_predictions = 0;
    std::string mispredicted;
    for (const datasets::BundledMesh& b : datasets::catalog_meshes()) {
        bool triangles = true;
        for (int f = 0; f < b.mesh.num_faces(); ++f) triangles = triangles && b.mesh.face_size(f) == 3;
        for (Scheme scheme : {Scheme::Loop, Scheme::CatmullClark}) {
            if (scheme == Scheme::Loop && !triangles) continue;
            json row = {{"mesh", b.name}, {"scheme", to_string(scheme)}, {"vertices", b.mesh.num_vertices()}};
            const bool predicted = scheme == Scheme::CatmullClark && has_checkerboard_kernel(b.mesh);
            bool singular = false;
            try {
                const SchemeRule rule;
                const LimitSampling s = scheme == Scheme::Loop ? loop_limit_sampling(to_tri_mesh(b.mesh), rule.loop, 2)
                                                               : catmull_clark_limit_sampling(b.mesh, rule.catmull_clark, 2);
                row["samples"] = s.num_samples();
                const std::vector<Vec3> x = fit_limit_points(s, s.evaluate(b.mesh.positions));
                double worst = 0;
                for (int v = 0; v < b.mesh.num_vertices(); ++v) worst = std::max(worst, (x[v] - b.mesh.positions[v]).norm());
                row["error"] = worst / bounding_box_diagonal(b.mesh.positions);
                out.checks.push_back({b.name, "exact-recovery", to_string(scheme), row["error"].get<double>(),
                                      tolerances::kFittingRecovery, "rel",
                                      "control points from the samples of their own limit surface at level 2, least squares"});
            } catch (const InputError& e) {
                singular = true;
                row["singular"] = e.what();
            }
            row["predicted_singular"] = predicted;
            if (singular != predicted) ++wrong_predictions, mispredicted += (mispredicted.empty() ? "" : ", ") + b.name;
            rows.push_back(row);
        }
    }
    out.checks.push_back(count_check("catalog", "singular-where-predicted", "checkerboard mode", wrong_predictions,
                                     mispredicted.empty() ? "the system is singular exactly on the closed, valence-3, "
                                                            "bipartite meshes under Catmull-Clark"
                                                          : "singular or not against the prediction: " + mispredicted));
    out.subjects.push_back("catalog");
    return rows;
}

/// The sampling matrix A = Lim_L S_L ... S_1 that fitting solves with, applied to the control
/// points, against OpenSubdiv's limit points after the same levels (PrimvarRefiner::Limit): A is
/// assembled from core's own matrices, so nothing else checks it. Every catalog mesh, 2 levels,
/// each vertex moved by a seeded random offset so that no symmetry of the mesh hides a wrong
/// weight.
json sampling_against_opensubdiv(CheckReport& out) {
    json rows = json::array();
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    for (const datasets::BundledMesh& b : datasets::catalog_meshes()) {
        PolyMesh mesh = b.mesh;
        const double diagonal = bounding_box_diagonal(mesh.positions);
        for (Vec3& p : mesh.positions) p += diagonal * Vec3(jitter(rng), jitter(rng), jitter(rng));
        for (Scheme scheme : {Scheme::Loop, Scheme::CatmullClark}) {
            if (scheme == Scheme::Loop && !mesh.all_triangles()) continue;
            const RefineRequest request{scheme, SchemeRule{}, 2};
            adapters::LimitPoints ours;
            std::string core_error;
            try {
                // The rows of A are the vertices of the level the sampling refines to, one level at a
                // time, in that order (two levels at once may number them otherwise).
                const bool loop = scheme == Scheme::Loop;
                const LimitSampling s = loop ? loop_limit_sampling(to_tri_mesh(mesh), request.rule.loop, 2)
                                             : catmull_clark_limit_sampling(mesh, request.rule.catmull_clark, 2);
                const LoopOptions& lo = request.rule.loop;
                const CatmullClarkOptions& co = request.rule.catmull_clark;
                ours.level = loop ? to_poly_mesh(loop_subdivide(loop_subdivide(to_tri_mesh(mesh), lo, 1), lo, 1))
                                  : catmull_clark_subdivide(catmull_clark_subdivide(mesh, co, 1), co, 1);
                ours.position = s.evaluate(mesh.positions);
                ours.normal.assign(ours.position.size(), Vec3::Constant(NAN));  // A carries no normals
            } catch (const InputError& e) {
                core_error = e.what();
            }
            const LimitComparison c = compare_limit_points(ours, core_error, mesh, "bundled:" + b.name, request);
            rows.push_back(to_json(c));
            const std::string what = "limit sampling " + std::string(to_string(scheme)) + " L2";
            if (c.verdict != Verdict::Agree && c.verdict != Verdict::Diverge)
                out.checks.push_back(decided_check("opensubdiv", what, c.input, NAN, tolerances::kLimitAgreementRelative, "rel",
                                                   c.explanation, {c.verdict, DivergenceClass::None}));
            else
                out.checks.push_back(measured_check("opensubdiv", what, c.input, c.max_rel_position,
                                                    tolerances::kLimitAgreementRelative, "rel",
                                                    "fitting's sampling matrix times the jittered control points: " + c.explanation));
        }
    }
    return rows;
}

json step_json(const FittingStep& s, double diagonal, const std::vector<double>& hausdorff, size_t k) {
    json j = {{"energy", s.energy},
              {"rms_sample_to_target", s.rms_sample_to_target / diagonal},
              {"max_sample_to_target", s.max_sample_to_target / diagonal},
              {"rms_target_to_surface", s.rms_target_to_surface / diagonal},
              {"max_target_to_surface", s.max_target_to_surface / diagonal}};
    if (k < hausdorff.size()) j["hausdorff"] = hausdorff[k] / diagonal;
    return j;
}

/// One target under one scheme from one control mesh: the iterations, the checks, the row.
json fit_row(CheckReport& out, const FittingTarget& t, const TriMesh& control, int budget, Scheme scheme, int iterations,
             const Implementation* hausdorff, json& figures) {
    const std::string subject = fmt::format("{} {} {} control vertices", t.name, to_string(scheme), control.num_vertices());
    json row = {{"target", t.name}, {"scheme", to_string(scheme)}, {"edge_budget", budget},
                {"target_vertices", t.mesh.num_vertices()}, {"control_vertices", control.num_vertices()},
                {"control_faces", control.num_faces()}};
    FittingRun run;
    try {
        run = run_fitting(scheme, control, t.mesh, 2, iterations, hausdorff);
    } catch (const InputError& e) {
        row["error"] = e.what();
        out.checks.push_back(count_check(subject, "fitted", "ours", 1, e.what()));
        return row;
    }
    const double diagonal = bounding_box_diagonal(t.mesh.positions);
    row["samples"] = run.sampling.num_samples();
    json steps = json::array();
    for (size_t k = 0; k < run.result.steps.size(); ++k) steps.push_back(step_json(run.result.steps[k], diagonal, run.hausdorff, k));
    row["steps"] = steps;
    out.checks.push_back(count_check(subject, "energy-never-increases", "ours",
                                     energy_increases(run.result, t.mesh, run.sampling.num_samples()),
                                     "iterations whose distance energy exceeds the previous one's beyond rounding"));
    if (!run.hausdorff_error.empty()) {
        row["hausdorff_error"] = run.hausdorff_error;
        out.checks.push_back({subject, "hausdorff-decreases", run.hausdorff_by, 0, 0, "ratio", run.hausdorff_error,
                              Outcome{Verdict::RefRejected, DivergenceClass::None}});
    } else if (!run.hausdorff.empty()) {
        int rises = 0;
        double below = 0;  // how far CGAL's distance falls under our largest vertex distance
        for (size_t k = 0; k < run.hausdorff.size(); ++k) {
            if (k > 0 && run.hausdorff[k] > run.hausdorff[k - 1]) ++rises;
            const FittingStep& s = run.result.steps[k];
            below = std::max(below, (std::max(s.max_sample_to_target, s.max_target_to_surface) - run.hausdorff[k]) / diagonal);
        }
        row["hausdorff_rises"] = rises;
        out.checks.push_back({subject, "hausdorff-decreases", run.hausdorff_by, run.hausdorff.back() / run.hausdorff.front(), 1,
                              "ratio", fmt::format("two-sided Hausdorff distance after {} iterations over the start's; it "
                                                   "rose at {} of them (least squares lowers the mean, not the largest)",
                                                   iterations, rises)});
        out.checks.push_back({subject, "hausdorff-bounds-vertex-distances", run.hausdorff_by, below,
                              tolerances::kPointMeshDistanceAgreement, "rel",
                              "its samples hold both meshes' vertices, so it is at least our largest vertex distance"});
    }
    if (t.name == "bunny" && scheme == Scheme::Loop && figures.empty()) {
        figures.push_back({{"title", fmt::format("target: {} triangles", t.mesh.num_faces())}, {"mesh", mesh_json(to_poly_mesh(t.mesh))}});
        figures.push_back({{"title", fmt::format("control by edge collapse: {} vertices", control.num_vertices())},
                           {"mesh", mesh_json(to_poly_mesh(control))}, {"wire", true}});
        figures.push_back({{"title", "its limit surface (start)"}, {"mesh", mesh_json(to_poly_mesh(run.sampling.surface(control.positions)))}});
        figures.push_back({{"title", fmt::format("after {} iterations", iterations)}, {"mesh", mesh_json(to_poly_mesh(run.fitted_surface()))}});
    }
    return row;
}

}  // namespace

std::vector<FittingTarget> fitting_targets() {
    std::vector<FittingTarget> out;
    for (const std::string& path : datasets::cgal_mesh_files())
        out.push_back({std::filesystem::path(path).stem().string(), to_tri_mesh(read_mesh(path), "fitting")});
    for (const std::string& path : datasets::course_mesh_files())
        if (std::filesystem::path(path).stem() == "bunny") out.push_back({"bunny", to_tri_mesh(read_mesh(path), "fitting")});
    if (out.empty()) out.push_back({"torus", to_tri_mesh(datasets::bundled_mesh("torus"), "fitting")});
    return out;
}

CheckReport fitting_study(const std::vector<FittingTarget>& targets, const std::vector<int>& edge_budgets, int iterations) {
    CheckReport out;
    out.tables["fitting_recovery"] = recovery(out);
    if (!references_with(&Capabilities::limit_positions).empty())
        out.tables["fitting_sampling"] = sampling_against_opensubdiv(out);
    const std::vector<const Implementation*> simplifiers = references_with(&Capabilities::simplification);
    const std::vector<const Implementation*> distances = references_with(&Capabilities::hausdorff_distance);
    json rows = json::array(), figures = json::array();
    if (simplifiers.empty()) {
        out.checks.push_back({"targets", "fitted", "simplification", 0, 0, "count", "no reference of this build simplifies meshes",
                              Outcome{Verdict::RefUnavailable, DivergenceClass::None}});
    } else {
        for (const FittingTarget& t : targets) {
            const int target_edges = t.mesh.num_faces() * 3 / 2;
            for (int budget : edge_budgets) {
                if (2 * budget > target_edges) continue;  // no coarser than half the target
                TriMesh control;
                try {
                    control = coarse_control(t.mesh, budget, *simplifiers[0]);
                } catch (const std::exception& e) {
                    rows.push_back({{"target", t.name}, {"edge_budget", budget}, {"error", e.what()}});
                    out.checks.push_back(count_check(t.name, "control-mesh", simplifiers[0]->name(), 1, e.what()));
                    continue;
                }
                for (Scheme scheme : {Scheme::Loop, Scheme::CatmullClark})
                    rows.push_back(fit_row(out, t, control, budget, scheme, iterations, distances.empty() ? nullptr : distances[0], figures));
            }
            out.subjects.push_back(t.name);
        }
    }
    out.tables["fitting_iterations"] = rows;
    out.tables["fitting_figure"] = figures;
    return out;
}

CheckReport fitting_study() { return fitting_study(fitting_targets(), {300, 1200}, 6); }

}  // namespace crossdiv::verification
