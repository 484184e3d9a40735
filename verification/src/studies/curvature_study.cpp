// The curvature study: discrete curvature (mesh/discrete_curvature.h) against the analytic
// sphere and torus as the meshes are refined, against CGAL's jet fitting on the same meshes,
// the discrete Gauss-Bonnet theorem on every manifold catalog mesh, and the Gaussian curvature
// of Loop's limit surface at an extraordinary vertex as the levels grow.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "crossdiv/datasets/analytic_surfaces.h"
#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/discrete_curvature.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/convergence_order.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/isolated_calls.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/studies/curvature_study.h"
#include "crossdiv/verification/studies/studies.h"

namespace crossdiv::verification {
namespace {

using nlohmann::json;
constexpr double kPi = std::numbers::pi;

/// The exact curvatures of a point of a surface.
struct Exact {
    double k1, k2;
    Vec3 direction1;  ///< zero at an umbilic
};

/// A surface with known curvature and its meshes from coarse to fine.
struct AnalyticCase {
    std::string name;
    std::vector<TriMesh> meshes;
    Exact (*exact)(const Vec3&);
    bool umbilic = false;  ///< every point an umbilic: no principal direction to check
};

/// The unit sphere: every point an umbilic of curvature 1.
Exact sphere_exact(const Vec3&) { return {1.0, 1.0, Vec3::Zero()}; }

constexpr double kTorusR = 1.0, kTorusr = 0.4;
/// The torus R = 1, r = 0.4 at p: with rho = |p_xy| the distance from the axis,
/// cos v = (rho - R) / r, k1 = 1/r along the meridian, k2 = cos v / rho along the parallel.
Exact torus_exact(const Vec3& p) {
    const double rho = std::hypot(p.x(), p.y());
    const double cos_v = (rho - kTorusR) / kTorusr;
    const Vec3 axial(p.x() / rho, p.y() / rho, 0);
    const Vec3 tube = (rho - kTorusR) * axial + Vec3(0, 0, p.z());  // from the tube's centre circle to p
    const Vec3 parallel = Vec3(-p.y(), p.x(), 0) / rho;
    return {1.0 / kTorusr, cos_v / rho, tube.cross(parallel).normalized()};
}

/// Errors of one estimator on one mesh against the exact values, over the vertices it estimated.
struct ErrorRow {
    double h = 0;                   ///< mean edge length
    double mean_max = 0, mean_rms = 0, gauss_max = 0, gauss_rms = 0;
    double direction_max = 0;       ///< rad, where the exact surface is not umbilic
    int estimated = 0;
};

double mean_edge_length(const TriMesh& m) {
    double sum = 0;
    for (const Triangle& t : m.triangles)
        for (int j = 0; j < 3; ++j) sum += (m.positions[t[(j + 1) % 3]] - m.positions[t[j]]).norm();
    return sum / (3.0 * m.num_faces());
}

ErrorRow errors(const TriMesh& m, const PrincipalCurvatures& c, Exact (*exact)(const Vec3&)) {
    ErrorRow r;
    r.h = mean_edge_length(m);
    double sum_h = 0, sum_k = 0;
    for (int v = 0; v < m.num_vertices(); ++v) {
        if (!c.estimated[v]) continue;
        const Exact e = exact(m.positions[v]);
        const double dh = std::abs(c.mean[v] - (e.k1 + e.k2) / 2);
        const double dk = std::abs(c.gaussian[v] - e.k1 * e.k2);
        r.mean_max = std::max(r.mean_max, dh);
        r.gauss_max = std::max(r.gauss_max, dk);
        sum_h += dh * dh, sum_k += dk * dk;
        ++r.estimated;
        if (!e.direction1.isZero()) {
            const Vec3& d = c.direction1[v];
            const double angle = d.isZero() ? kPi / 2 : std::atan2(d.cross(e.direction1).norm(), std::abs(d.dot(e.direction1)));
            r.direction_max = std::max(r.direction_max, angle);
        }
    }
    r.mean_rms = std::sqrt(sum_h / std::max(r.estimated, 1));
    r.gauss_rms = std::sqrt(sum_k / std::max(r.estimated, 1));
    return r;
}

/// Largest differences of two estimators where both estimated: mean and Gaussian curvature,
/// and the angle (rad, 0..pi/2) between their first principal directions where both have one.
struct Difference {
    double mean = 0, gaussian = 0, direction = 0;
};

Difference difference(const PrincipalCurvatures& a, const PrincipalCurvatures& b) {
    Difference d;
    for (size_t v = 0; v < a.k1.size(); ++v) {
        if (!a.estimated[v] || !b.estimated[v]) continue;
        d.mean = std::max(d.mean, std::abs(a.mean[v] - b.mean[v]));
        d.gaussian = std::max(d.gaussian, std::abs(a.gaussian[v] - b.gaussian[v]));
        const Vec3 &da = a.direction1[v], &db = b.direction1[v];
        if (!da.isZero() && !db.isZero())
            d.direction = std::max(d.direction, std::atan2(da.cross(db).norm(), std::abs(da.dot(db))));
    }
    return d;
}

json convergence(CheckReport& out) {
    std::vector<AnalyticCase> cases(2);
    cases[0] = {"sphere", {}, sphere_exact, true};
    // From level 2: at level 1 every vertex star is symmetric enough that both operators are
    // exact to rounding (measured 7e-16), which would make the fitted order meaningless.
    for (int level = 2; level <= 6; ++level) cases[0].meshes.push_back(datasets::icosphere(level));
    cases[1] = {"torus", {}, torus_exact};
    for (int k = 0; k < 5; ++k) cases[1].meshes.push_back(datasets::regular_torus(16 << k, 8 << k, kTorusR, kTorusr));

    json rows = json::array();
    const std::vector<const Implementation*> estimators = [] {
        std::vector<const Implementation*> e{&core_implementation()};
        for (const Implementation* r : references_with(&Capabilities::curvatures)) e.push_back(r);
        return e;
    }();
    for (const AnalyticCase& c : cases) {
        std::vector<std::vector<ErrorRow>> err(estimators.size());
        std::vector<double> hs;
        std::vector<std::vector<Difference>> diff(estimators.size());  // from core, per reference
        // A reference that fails on some mesh (crashes, hangs, refuses: isolated_calls.h) is
        // recorded once and left out of this surface's orders.
        std::vector<std::string> failed(estimators.size());
        for (const TriMesh& m : c.meshes) {
            std::vector<PrincipalCurvatures> est;
            for (size_t i = 0; i < estimators.size(); ++i) {
                IsolatedValue<PrincipalCurvatures> run = curvatures_isolated(*estimators[i], m);
                if (!run.value && i == 0)  // core's own estimator: its failure is the study's
                    throw std::runtime_error("core's curvature estimator failed on the " + c.name + ": " +
                                             run.outcome.failure_explanation());
                if (!run.value && failed[i].empty()) {
                    failed[i] = run.outcome.failure_explanation();
                    out.checks.push_back({c.name, "curvatures", estimators[i]->name(), NAN, 0, "order",
                                          estimators[i]->name() + " on " + std::to_string(m.num_vertices()) + " vertices: " +
                                              failed[i],
                                          Outcome{verdict_of_failed_run(run.outcome.status), DivergenceClass::None}});
                }
                est.push_back(run.value ? std::move(*run.value) : PrincipalCurvatures{});
                if (!run.value) {
                    err[i].emplace_back();
                    continue;
                }
                err[i].push_back(errors(m, est.back(), c.exact));
                const ErrorRow& e = err[i].back();
                rows.push_back({{"surface", c.name}, {"estimator", estimators[i]->name()}, {"method", est.back().method},
                                {"vertices", m.num_vertices()}, {"h", e.h}, {"estimated", e.estimated},
                                {"mean_max", e.mean_max}, {"mean_rms", e.mean_rms}, {"gauss_max", e.gauss_max},
                                {"gauss_rms", e.gauss_rms}, {"direction_max", e.direction_max}});
            }
            hs.push_back(err[0].back().h);
            for (size_t i = 1; i < est.size(); ++i)
                if (failed[i].empty()) diff[i].push_back(difference(est[0], est[i]));
        }
        // Core on the regular torus and the icosphere: second order in the largest error (Meyer
        // et al.'s operators are consistent on meshes whose vertex stars are symmetric).
        for (auto [what, pick] : {std::pair{"mean", &ErrorRow::mean_max}, std::pair{"gaussian", &ErrorRow::gauss_max}}) {
            std::vector<double> e;
            for (const ErrorRow& r : err[0]) e.push_back(r.*pick);
            const double order = fitted_order(hs, e);
            out.checks.push_back({c.name, std::string(what) + "-curvature-order", "analytic", tolerances::kSecondOrderMin - order,
                                  0, "order", "core's largest error against the exact curvature over 5 refinements: fitted order " +
                                  std::to_string(order) + " must be >= " + std::to_string(tolerances::kSecondOrderMin)});
        }
        // Principal directions against the exact ones, for every estimator: the angle falls at
        // least at first order (Cazals and Pouget 2005: a degree-2 jet's directions are first
        // order; Meyer et al.'s tensor is second order on symmetric stars). A direction taken
        // from the wrong eigenvector is off by pi/2 at every vertex and has order 0.
        if (!c.umbilic)
            for (size_t i = 0; i < estimators.size(); ++i) {
                if (!failed[i].empty()) continue;
                std::vector<double> e;
                for (const ErrorRow& r : err[i]) e.push_back(r.direction_max);
                const double order = fitted_order(hs, e);
                out.checks.push_back({c.name, "principal-direction-order", estimators[i]->name(),
                                      tolerances::kPrincipalDirectionOrderMin - order, 0, "order",
                                      "largest angle between " + estimators[i]->name() + "'s first principal direction and the exact "
                                      "one over 5 refinements (" + std::to_string(e.back()) + " rad at the finest): fitted order " +
                                      std::to_string(order) + " must be >= " + std::to_string(tolerances::kPrincipalDirectionOrderMin)});
            }
        for (size_t i = 1; i < estimators.size(); ++i) {
            if (!failed[i].empty()) continue;
            // Two consistent estimators converge to the same surface: their difference shrinks
            // at least at the slower one's rate (a degree-2 jet's curvature is first order).
            std::vector<double> dh, dk, dd;
            for (const Difference& d : diff[i]) dh.push_back(d.mean), dk.push_back(d.gaussian), dd.push_back(d.direction);
            const double order = std::min(fitted_order(hs, dh), fitted_order(hs, dk));
            out.checks.push_back({c.name, "curvature-agreement-order", estimators[i]->name(),
                                  tolerances::kCurvatureAgreementOrderMin - order, 0, "order",
                                  "largest |H| and |K| difference between core and " + estimators[i]->name() + " over 5 refinements: "
                                  "fitted order " + std::to_string(order) + " must be >= " +
                                  std::to_string(tolerances::kCurvatureAgreementOrderMin)});
            if (c.umbilic) continue;
            const double direction_order = fitted_order(hs, dd);
            out.checks.push_back({c.name, "principal-direction-agreement-order", estimators[i]->name(),
                                  tolerances::kCurvatureAgreementOrderMin - direction_order, 0, "order",
                                  "largest angle between core's and " + estimators[i]->name() + "'s first principal directions over 5 "
                                  "refinements: fitted order " + std::to_string(direction_order) + " must be >= " +
                                  std::to_string(tolerances::kCurvatureAgreementOrderMin)});
        }
        out.subjects.push_back(c.name);
    }
    return rows;
}

/// One manifold triangle mesh's Gauss-Bonnet row, or its refusal.
json gauss_bonnet_row(const std::string& name, const PolyMesh& poly, CheckReport& out) {
    json row = {{"mesh", name}};
    try {
        const TriMesh m = to_tri_mesh(poly, "discrete curvature");
        const DiscreteCurvature c = discrete_curvature(m);
        const int boundary = static_cast<int>(std::count(c.status.begin(), c.status.end(), CurvatureStatus::Boundary));
        const int chi = c.euler_characteristic;
        const double total = c.total_angle_defect(), error = std::abs(total - 2 * kPi * chi);
        const double bound = tolerances::gauss_bonnet_bound(m.num_faces());
        row.update({{"vertices", m.num_vertices()}, {"faces", m.num_faces()}, {"boundary_vertices", boundary}, {"chi", chi},
                    {"total_defect", total}, {"error", error}, {"bound", bound}});
        out.checks.push_back({name, "gauss-bonnet", "exact", error, bound, "abs",
                              "|sum of angle defects (turning angles on the boundary) - 2 pi chi|, chi = V - E + F"});
    } catch (const InputError& e) {
        row["refused"] = e.what();  // a non-manifold edge case: the operators need a manifold
    }
    return row;
}

json gauss_bonnet(CheckReport& out) {
    json rows = json::array();
    for (const datasets::BundledMesh& b : datasets::bundled_meshes()) rows.push_back(gauss_bonnet_row(b.name, b.mesh, out));
    for (const datasets::EdgeCase& e : datasets::edge_cases()) rows.push_back(gauss_bonnet_row("edgecase:" + e.name, e.mesh, out));
    for (const std::string& path : datasets::cgal_mesh_files()) {
        const std::string name = "cgal:" + path.substr(path.find_last_of('/') + 1);
        try {
            rows.push_back(gauss_bonnet_row(name, read_mesh(path), out));
        } catch (const InputError& e) {
            rows.push_back({{"mesh", name}, {"refused", e.what()}});
        }
    }
    return rows;
}

/// A disc of `rings` rings around one vertex of valence n: ring r has r n vertices, each of
/// the n sectors a regular triangle grid, so every vertex but the centre has valence 6 (the
/// rim's are on the boundary). The height z = 0.3 (x^2 - y^2) + 0.2 x y + 0.1 x^3 holds every
/// harmonic the local subdivision matrix separates, the second (cos 2 theta) included.
TriMesh extraordinary_disc(int n, int rings) {
    TriMesh m;
    m.positions.push_back(Vec3::Zero());
    auto first = [n](int r) { return r == 0 ? 0 : 1 + n * r * (r - 1) / 2; };  // index of ring r's first vertex
    auto id = [&](int r, int i) { return r == 0 ? 0 : first(r) + i % (n * r); };
    for (int r = 1; r <= rings; ++r)
        for (int i = 0; i < n * r; ++i) {
            const int s = i / r, t = i % r;
            const Vec3 a(std::cos(2 * kPi * s / n), std::sin(2 * kPi * s / n), 0);
            const Vec3 b(std::cos(2 * kPi * (s + 1) / n), std::sin(2 * kPi * (s + 1) / n), 0);
            const Vec3 p = (r - t) * a + t * b;
            const double x = p.x() / rings, y = p.y() / rings;
            m.positions.emplace_back(x, y, 0.3 * (x * x - y * y) + 0.2 * x * y + 0.1 * x * x * x);
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < n; ++s) {
            for (int t = 0; t <= r; ++t) m.triangles.push_back({id(r, s * r + t), id(r + 1, s * (r + 1) + t), id(r + 1, s * (r + 1) + t + 1)});
            for (int t = 0; t < r; ++t) m.triangles.push_back({id(r, s * r + t), id(r + 1, s * (r + 1) + t + 1), id(r, s * r + t + 1)});
        }
    return m;
}

/// The triangles of `m` whose vertices are all within `depth` edges of vertex 0, renumbered
/// with vertex 0 first (its ring is all the refinement at the centre depends on).
TriMesh crop_around_first(const TriMesh& m, int depth) {
    const TriConnectivity conn = build_tri_connectivity(m);
    std::vector<std::vector<int>> adjacent(m.num_vertices());
    for (const auto& [a, b] : conn.edge_vertices) adjacent[a].push_back(b), adjacent[b].push_back(a);
    std::vector<int> dist(m.num_vertices(), -1), order{0};
    dist[0] = 0;
    for (size_t i = 0; i < order.size(); ++i)
        if (dist[order[i]] < depth)
            for (int w : adjacent[order[i]])
                if (dist[w] < 0) dist[w] = dist[order[i]] + 1, order.push_back(w);
    std::vector<int> index(m.num_vertices(), -1);
    TriMesh out;
    for (int v : order) index[v] = out.num_vertices(), out.positions.push_back(m.positions[v]);
    for (const Triangle& t : m.triangles)
        if (index[t[0]] >= 0 && index[t[1]] >= 0 && index[t[2]] >= 0) out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    return out;
}

json loop_blowup(CheckReport& out) {
    constexpr int kLevels = 10;
    const LoopOptions options{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    json rows = json::array();
    for (int n : {3, 4, 5, 6, 7, 8, 9, 10, 12}) {
        // Loop 1987: the 1-ring subdivision matrix has eigenvalues 3/8 + cos(2 pi k / n) / 4;
        // lambda (k = 1) scales the ring, mu (k = 2, n >= 4) carries the cos 2 theta part of the
        // height; the 2-ring adds 1/8 (and 1/16). With nu the larger of mu and 1/8, curvature
        // over the level-l ring scales as nu^l / lambda^(2 l), so the Gaussian curvature changes
        // by (nu / lambda^2)^2 per level: it grows where nu > lambda^2 (n = 3 through 1/8, n > 6
        // through mu), stays at n = 6, and falls to 0 at n = 4, 5 (a flat spot).
        const double lambda = 3.0 / 8 + std::cos(2 * kPi / n) / 4;
        const double mu = n >= 4 ? 3.0 / 8 + std::cos(4 * kPi / n) / 4 : 0.0, nu = std::max(mu, 1.0 / 8);
        const double predicted = (nu / (lambda * lambda)) * (nu / (lambda * lambda));
        TriMesh level = extraordinary_disc(n, 5);
        std::vector<double> gauss, mean, ratio;
        for (int l = 0; l <= kLevels; ++l) {
            TriMesh limit = level;
            limit.positions = loop_limit(level, options).position;
            const DiscreteCurvature c = discrete_curvature(crop_around_first(limit, 1));
            gauss.push_back(c.gaussian[0]);
            mean.push_back(c.mean[0]);
            if (l > 0) ratio.push_back(gauss[l] / gauss[l - 1]);
            level = crop_around_first(loop_subdivide(level, options, 1), 4);
        }
        rows.push_back({{"valence", n}, {"lambda", lambda}, {"nu", nu}, {"predicted_ratio", predicted},
                        {"gaussian", gauss}, {"mean", mean}, {"ratio", ratio}});
        out.checks.push_back({"valence " + std::to_string(n), "loop-curvature-growth", "eigenvalues",
                                  std::abs(ratio.back() - predicted) / predicted, tolerances::kCurvatureGrowthRelative, "rel",
                                  "Gaussian curvature ratio between levels " + std::to_string(kLevels - 1) + " and " +
                                  std::to_string(kLevels) + " at the limit ring against (nu / lambda^2)^2 = " +
                                  std::to_string(predicted)});
    }
    return rows;
}

/// A figure row: the mesh and core's Gaussian curvature, with where it was estimated.
json figure_row(const std::string& title, const TriMesh& m) {
    const DiscreteCurvature c = discrete_curvature(m);
    std::vector<int> estimated;
    for (CurvatureStatus s : c.status) estimated.push_back(s == CurvatureStatus::Estimated);
    return {{"surface", title}, {"mesh", mesh_json(to_poly_mesh(m))}, {"gaussian", c.gaussian}, {"estimated", estimated}};
}

/// The torus at 32 x 16, and Loop's limit surface around a vertex of valence 8 after 3 levels
/// (the limit positions of level 3, 16 rings around it), for the coloured figure.
json curvature_figures() {
    const TriMesh disc = loop_subdivide(extraordinary_disc(8, 5), {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 3);
    TriMesh limit = disc;
    limit.positions = loop_limit(disc, {LoopWeights::Loop, LoopBoundary::EdgeOnly}).position;
    return json::array({figure_row("torus R 1 r 0.4, 32 x 16", datasets::regular_torus(32, 16, kTorusR, kTorusr)),
                        figure_row("Loop limit at valence 8, level 3", crop_around_first(limit, 16))});
}

}  // namespace

CheckReport curvature_study() {
    CheckReport out;
    out.tables["curvature_convergence"] = convergence(out);
    out.tables["gauss_bonnet"] = gauss_bonnet(out);
    out.tables["loop_curvature_growth"] = loop_blowup(out);
    out.tables["curvature_figure"] = curvature_figures();
    return out;
}

}  // namespace crossdiv::verification
