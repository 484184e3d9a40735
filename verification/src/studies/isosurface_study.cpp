// The isosurface study: marching cubes against exact implicit surfaces as the grid is refined,
// both ambiguous-face rules on single cubes whose answers are worked out by hand, the
// asymptotic decider against the minority rule on a field whose faces are ambiguous, and
// scikit-image's marching cubes (Lewiner's MC33 table and the 1987 table) on the same samples.
#include "crossdiv/verification/studies/isosurface_study.h"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "crossdiv/datasets/implicit_surfaces.h"
#include "crossdiv/verification/harness/convergence_order.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/studies/studies.h"

namespace crossdiv::verification {

Outcome skimage_outcome(const IsosurfaceRun& run, const IsosurfaceComparison* c) {
    switch (run.outcome.status) {
        case RunStatus::Ok: break;
        case RunStatus::Unavailable: return {Verdict::RefUnavailable, DivergenceClass::None};
        case RunStatus::Rejected: return {Verdict::RefRejected, DivergenceClass::None};
        default:
            return {is_invalid_output(run.outcome.status) ? Verdict::RefInvalidOutput : Verdict::RefCrashed, DivergenceClass::None};
    }
    switch (c->agreement) {
        case IsosurfaceAgreement::Identical: return {Verdict::Agree, DivergenceClass::None};
        case IsosurfaceAgreement::OtherTriangulation: return {Verdict::Diverge, DivergenceClass::Triangulation};
        case IsosurfaceAgreement::OtherTopology: return {Verdict::Diverge, DivergenceClass::Topology};
        case IsosurfaceAgreement::OtherVertices: break;
    }
    return {Verdict::Diverge, DivergenceClass::Unexplained};
}

namespace {

using nlohmann::json;

json measures_json(const IsosurfaceMeasures& m) {
    return {{"vertices", m.vertices}, {"faces", m.faces}, {"boundary_edges", m.boundary_edges},
            {"boundary_loops", m.boundary_loops}, {"mesh_errors", m.mesh_errors}, {"euler", m.euler}, {"volume", m.volume}};
}

/// The resolutions of each surface: from where the grid resolves its thinnest part (the
/// genus-2 tube's radius is 0.1 at its far ends; its holes 0.32 across).
std::vector<int> resolutions(const datasets::ImplicitSurface& s) {
    return s.name == "genus2" ? std::vector<int>{33, 65, 129, 257} : std::vector<int>{17, 33, 65, 129};
}

json convergence(CheckReport& out, json& figures) {
    json rows = json::array();
    const std::vector<const Implementation*> closers = references_with(&Capabilities::closed_mesh_report);
    for (const datasets::ImplicitSurface& s : datasets::implicit_surfaces()) {
        std::vector<double> hs, max_distance, volume_error;
        for (int res : resolutions(s)) {
            const ScalarGrid grid = datasets::sample(s, res);
            const Isosurface iso = marching_cubes(grid, {});
            const IsosurfaceMeasures m = measure_isosurface(iso.mesh);
            double worst = 0, sum = 0;
            for (const Vec3& p : iso.mesh.positions) {
                const double d = datasets::distance_to(s, p);
                worst = std::max(worst, d), sum += d * d;
            }
            const double h = grid.spacing.maxCoeff();
            hs.push_back(h), max_distance.push_back(worst);
            json row = {{"surface", s.name}, {"description", s.description}, {"resolution", res}, {"h", h},
                        {"grid", grid.size}, {"max_distance", worst},
                        {"rms_distance", std::sqrt(sum / std::max(1, m.vertices))}, {"ambiguous_faces", iso.ambiguous_faces},
                        {"centred_polygons", iso.centred_polygons}};
            row.update(measures_json(m));
            const std::string subject = fmt::format("{} res {}", s.name, res);
            if (s.euler_characteristic) {
                row["expected_euler"] = *s.euler_characteristic;
                out.checks.push_back(count_check(subject, "euler-characteristic", "exact", std::abs(m.euler - *s.euler_characteristic),
                                                 fmt::format("|V - E + F - {}| of the closed surface", *s.euler_characteristic)));
                out.checks.push_back(count_check(subject, "watertight", "ours", m.boundary_edges + m.mesh_errors,
                                                 "edges of one triangle plus check_mesh errors (non-manifold, orientation)"));
                for (const Implementation* r : closers) {
                    const adapters::ClosedMeshReport c = r->closed_mesh_report(iso.mesh);
                    row[r->name() + "_closed"] = c.built && c.valid && c.closed;
                    row[r->name() + "_outward"] = c.outward;
                    out.checks.push_back(count_check(subject, "watertight", r->name(), !(c.built && c.valid && c.closed && c.outward),
                                                     "built, valid, closed and outward oriented by " + r->name() +
                                                         (c.error.empty() ? "" : ": " + c.error)));
                }
            } else {
                // The gyroid is cut by the box: its boundary is the cut, every vertex still manifold.
                out.checks.push_back(count_check(subject, "manifold", "ours", m.mesh_errors,
                                                 "check_mesh errors (non-manifold edge or vertex, orientation)"));
            }
            if (s.volume) {
                row["exact_volume"] = *s.volume;
                volume_error.push_back(std::abs(m.volume - *s.volume) / *s.volume);
                row["volume_error"] = volume_error.back();
            }
            rows.push_back(row);
            if (s.name == "genus2" && res == 65)
                figures.push_back({{"title", "genus 2, 65 samples across (decider)"}, {"mesh", mesh_json(to_poly_mesh(iso.mesh))}});
        }
        const double order = fitted_order(hs, max_distance);
        out.checks.push_back({s.name, "distance-order", s.signed_distance ? "exact" : "newton", tolerances::kSecondOrderMin - order, 0,
                              "order", fmt::format("largest vertex distance to the exact surface over {} resolutions: fitted order "
                                                   "{:.3f} must be >= {}", hs.size(), order, tolerances::kSecondOrderMin)});
        if (!volume_error.empty()) {
            const double v_order = fitted_order(hs, volume_error);
            out.checks.push_back({s.name, "volume-order", "exact", tolerances::kSecondOrderMin - v_order, 0, "order",
                                  fmt::format("relative error of the enclosed volume: fitted order {:.3f} must be >= {}", v_order,
                                              tolerances::kSecondOrderMin)});
        }
        out.subjects.push_back(s.name);
    }
    return rows;
}

/// One cube (corner c = i + 2 j + 4 k holds values[c], the level 0, inside below) and what a
/// face rule must make of it, worked out by hand.
struct HandCube {
    const char* name;
    std::array<double, 8> values;
    AmbiguousFaceRule rule;
    int faces, joined;  ///< triangles, and ambiguous faces whose inside corners are joined
    const char* why;
};

/// Both ambiguous-face rules on single cubes: the decider joins the inside corners of a face
/// exactly when the bilinear saddle is inside (in0 in1 > out0 out1); the minority rule joins
/// them exactly when more than four corners are inside.
void hand_cubes(CheckReport& out) {
    const HandCube cubes[] = {
        {"diagonal pair, saddle inside", {-1, 0.5, 0.5, -1, 1, 1, 1, 1}, AmbiguousFaceRule::AsymptoticDecider, 4, 1,
         "corners 0 and 3 at -1, 1 and 2 at 0.5: (-1)(-1) > 0.5 * 0.5, one hexagon round both (a fan of 4)"},
        {"diagonal pair, saddle outside", {-1, 2, 2, -1, 1, 1, 1, 1}, AmbiguousFaceRule::AsymptoticDecider, 2, 0,
         "corners 0 and 3 at -1, 1 and 2 at 2: (-1)(-1) < 2 * 2, a triangle round each"},
        {"diagonal pair, two inside", {-1, 0.5, 0.5, -1, 1, 1, 1, 1}, AmbiguousFaceRule::SeparateMinority, 2, 0,
         "two of eight corners inside: the minority, separated whatever the values"},
        {"diagonal pair, six inside", {-1, 1, 1, -1, -1, -1, -1, -1}, AmbiguousFaceRule::SeparateMinority, 2, 1,
         "six inside: the outside pair is the minority and separated (a triangle each), the inside joined"},
        {"tetrahedral, four inside", {-1, 1, 1, -1, 1, -1, -1, 1}, AmbiguousFaceRule::SeparateMinority, 4, 0,
         "corners 0, 3, 5, 6 inside, every face ambiguous: four of eight is no majority, each corner cut off alone"},
    };
    for (const HandCube& c : cubes) {
        ScalarGrid grid;
        grid.size = {2, 2, 2};
        grid.values.assign(c.values.begin(), c.values.end());
        const Isosurface iso = marching_cubes(grid, {0, InsideIs::Below, c.rule});
        out.checks.push_back(count_check(fmt::format("cube: {} ({})", c.name, to_string(c.rule)), "face-rule", "hand",
                                         std::abs(iso.mesh.num_faces() - c.faces) + std::abs(iso.joined_faces - c.joined),
                                         fmt::format("{}; made {} triangles, {} joined (by hand: {}, {})", c.why,
                                                     iso.mesh.num_faces(), iso.joined_faces, c.faces, c.joined)));
    }
    out.subjects.push_back("hand cubes");
}

/// The ambiguous field under both face rules, and scikit-image's two tables on it; the field
/// at 9^3 under both rules, its holes' edges to be drawn, for the figure.
json ambiguity(CheckReport& out, json& figures) {
    json rows = json::array();
    for (int n : {9, 17, 33}) {
        const ScalarGrid grid = datasets::ambiguous_field(n);
        json row = {{"samples", n}};
        for (AmbiguousFaceRule rule : {AmbiguousFaceRule::AsymptoticDecider, AmbiguousFaceRule::SeparateMinority}) {
            const Isosurface iso = marching_cubes(grid, {0, InsideIs::Below, rule});
            const IsosurfaceMeasures m = measure_isosurface(iso.mesh);
            json r = measures_json(m);
            r.update({{"ambiguous_faces", iso.ambiguous_faces}, {"joined_faces", iso.joined_faces},
                      {"centred_polygons", iso.centred_polygons}});
            row[to_string(rule)] = r;
            if (n == 9)
                figures.push_back({{"title", fmt::format("ambiguous field 9^3, {}: {} boundary edges", to_string(rule), m.boundary_edges)},
                                   {"mesh", mesh_json(to_poly_mesh(iso.mesh))}});
        }
        const std::string subject = fmt::format("ambiguous field {}^3", n);
        out.checks.push_back(count_check(subject, "watertight", "ours", row["decider"]["boundary_edges"].get<int>() +
                                                                             row["decider"]["mesh_errors"].get<int>(),
                                         "the asymptotic decider: edges of one triangle plus check_mesh errors"));
        for (const char* method : {"lewiner", "lorensen"}) {
            const IsosurfaceRun run = run_isosurface(find_implementation("skimage"), grid, {}, method);
            row[std::string("skimage_") + method] =
                run.outcome.status == RunStatus::Ok ? measures_json(measure_isosurface(run.mesh)) : json{{"failed", run.outcome.summary()}};
        }
        rows.push_back(row);
    }
    out.subjects.push_back("ambiguous field");
    return rows;
}

/// scikit-image's MC33 on each surface at 33 samples and on the ambiguous field.
json against_skimage(CheckReport& out) {
    json rows = json::array();
    std::vector<std::pair<std::string, ScalarGrid>> grids;
    for (const datasets::ImplicitSurface& s : datasets::implicit_surfaces()) grids.emplace_back(s.name + " res 33", datasets::sample(s, 33));
    grids.emplace_back("ambiguous field 17^3", datasets::ambiguous_field(17));
    for (const auto& [subject, grid] : grids) {
        const Isosurface ours = marching_cubes(grid, {});
        const IsosurfaceRun run = run_isosurface(find_implementation("skimage"), grid, {}, "lewiner");
        json row = {{"subject", subject}, {"status", to_string(run.outcome.status)}, {"seconds", run.outcome.seconds}};
        std::optional<IsosurfaceComparison> c;
        if (run.outcome.status == RunStatus::Ok) {
            c = compare_isosurfaces(ours.mesh, run.mesh, grid);
            row.update({{"agreement", to_string(c->agreement)}, {"tolerance", c->tolerance},
                        {"max_vertex_distance", c->max_vertex_distance}, {"ours_unmatched", c->ours_unmatched},
                        {"theirs_unmatched", c->theirs_unmatched},
                        {"ours_interior", c->ours_interior}, {"theirs_interior", c->theirs_interior}, {"faces_only_ours", c->faces_only_ours},
                        {"faces_only_theirs", c->faces_only_theirs}, {"reversed_faces", c->reversed_faces},
                        {"ours", measures_json(c->ours)}, {"theirs", measures_json(c->theirs)}, {"explanation", c->explanation}});
        } else {
            row["explanation"] = run.outcome.summary();
        }
        const Outcome outcome = skimage_outcome(run, c ? &*c : nullptr);
        out.checks.push_back({subject, "vertices-match", "skimage", c ? double(c->ours_unmatched + c->theirs_unmatched) : 0, 0,
                              "count", c ? c->explanation : run.outcome.summary(), outcome});
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

CheckReport isosurface_study() {
    CheckReport out;
    nlohmann::json figures = nlohmann::json::array();  // the genus-2 surface, the ambiguous field under both rules
    out.tables["isosurface_convergence"] = convergence(out, figures);
    hand_cubes(out);
    out.tables["isosurface_ambiguity"] = ambiguity(out, figures);
    out.tables["isosurface_reference"] = against_skimage(out);
    out.tables["isosurface_figure"] = figures;
    return out;
}

}  // namespace crossdiv::verification
