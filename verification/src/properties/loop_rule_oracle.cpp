// The Loop rule oracle (loop_rule_oracle.h): the published stencils applied by hand to small
// fans. Deliberately independent of core: its own edge list, its own level-1 layout, the
// weights written out from their sources.
#include "crossdiv/verification/properties/loop_rule_oracle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <utility>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/fans.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/registry.h"
#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

/// An open fan of `faces` triangles: centre 0 on the boundary, spoke ends 1..faces+1; the two
/// end spokes' outer vertices have one face.
PolyMesh open_fan(int faces) {
    PolyMesh m;
    m.positions.emplace_back(0.05, 0.1, 0.3);
    for (int k = 0; k <= faces; ++k) {
        const double a = 0.9 * M_PI * k / faces;
        m.positions.emplace_back(std::cos(a) * (1 + 0.1 * k), std::sin(a), 0.07 * k * k);
    }
    for (int k = 0; k < faces; ++k) m.add_face({0, 1 + k, 2 + k});
    return m;
}

/// beta(n) as published (header): Loop's and Warren's.
double published_beta(LoopWeights w, int n) {
    if (w == LoopWeights::Warren) return n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
    const double t = 3.0 / 8.0 + std::cos(2 * M_PI / n) / 4.0;
    return (5.0 / 8.0 - t * t) / n;
}

/// One level of the published rule on a triangle mesh: vertex points, then one edge point per
/// edge (sorted by its ends), four triangles per triangle.
PolyMesh published_level(const PolyMesh& m, const LoopOptions& rule) {
    struct Edge {
        int a, b, face, opposite;
    };
    std::vector<Edge> halves;
    for (int f = 0; f < m.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = m.face(f)[k], b = m.face(f)[(k + 1) % 3];
            halves.push_back({std::min(a, b), std::max(a, b), f, m.face(f)[(k + 2) % 3]});
        }
    std::sort(halves.begin(), halves.end(), [](const Edge& x, const Edge& y) { return std::pair{x.a, x.b} < std::pair{y.a, y.b}; });
    struct FullEdge {
        int a, b;
        std::vector<int> opposite;
    };
    std::vector<FullEdge> edges;
    for (const Edge& h : halves) {
        if (edges.empty() || edges.back().a != h.a || edges.back().b != h.b) edges.push_back({h.a, h.b, {}});
        edges.back().opposite.push_back(h.opposite);
    }
    const int nv = m.num_vertices();
    std::vector<int> faces_at(static_cast<size_t>(nv), 0);
    for (int v : m.face_vertices) ++faces_at[static_cast<size_t>(v)];
    std::vector<std::vector<int>> neighbours(static_cast<size_t>(nv)), boundary_neighbours(static_cast<size_t>(nv));
    for (const FullEdge& e : edges) {
        neighbours[static_cast<size_t>(e.a)].push_back(e.b);
        neighbours[static_cast<size_t>(e.b)].push_back(e.a);
        if (e.opposite.size() == 1) {
            boundary_neighbours[static_cast<size_t>(e.a)].push_back(e.b);
            boundary_neighbours[static_cast<size_t>(e.b)].push_back(e.a);
        }
    }
    PolyMesh out;
    const auto& p = m.positions;
    for (int v = 0; v < nv; ++v) {
        const auto& bn = boundary_neighbours[static_cast<size_t>(v)];
        if (bn.empty()) {
            const int n = static_cast<int>(neighbours[static_cast<size_t>(v)].size());
            const double beta = published_beta(rule.weights, n);
            Vec3 q = (1 - n * beta) * p[static_cast<size_t>(v)];
            for (int r : neighbours[static_cast<size_t>(v)]) q += beta * p[static_cast<size_t>(r)];
            out.positions.push_back(q);
        } else if (rule.boundary == LoopBoundary::EdgeAndCorner && faces_at[static_cast<size_t>(v)] == 1) {
            out.positions.push_back(p[static_cast<size_t>(v)]);
        } else {
            out.positions.push_back(0.75 * p[static_cast<size_t>(v)] + 0.125 * (p[static_cast<size_t>(bn[0])] + p[static_cast<size_t>(bn[1])]));
        }
    }
    for (const FullEdge& e : edges)
        out.positions.push_back(e.opposite.size() == 1
                                    ? Vec3(0.5 * (p[static_cast<size_t>(e.a)] + p[static_cast<size_t>(e.b)]))
                                    : Vec3(0.375 * (p[static_cast<size_t>(e.a)] + p[static_cast<size_t>(e.b)]) +
                                           0.125 * (p[static_cast<size_t>(e.opposite[0])] + p[static_cast<size_t>(e.opposite[1])])));
    const auto edge_point = [&](int a, int b) {
        const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair{std::min(a, b), std::max(a, b)},
                                         [](const FullEdge& e, const std::pair<int, int>& k) { return std::pair{e.a, e.b} < k; });
        return nv + static_cast<int>(it - edges.begin());
    };
    for (int f = 0; f < m.num_faces(); ++f) {
        const int* v = m.face(f);
        const int m0 = edge_point(v[0], v[1]), m1 = edge_point(v[1], v[2]), m2 = edge_point(v[2], v[0]);
        out.add_face({v[0], m0, m2});
        out.add_face({v[1], m1, m0});
        out.add_face({v[2], m2, m1});
        out.add_face({m0, m1, m2});
    }
    return out;
}

/// `impl`'s level 1 of `fan` against the published level: the largest distance over the
/// fan's diagonal, or a reason it could not be measured.
std::pair<double, std::string> measure(const Implementation& impl, const PolyMesh& fan, const LoopOptions& rule) {
    RefineRequest request;
    request.scheme = Scheme::Loop;
    request.rule.loop = rule;
    request.levels = 1;
    adapters::LevelTrace trace;
    try {
        trace = impl.refine(fan, request);
    } catch (const std::exception& e) {
        return {INFINITY, std::string("refused: ") + e.what()};
    }
    const PolyMesh expected = published_level(fan, rule);
    const Correspondence c = match_by_provenance({&fan, &expected}, trace);
    if (c.method == MatchMethod::None) return {INFINITY, "its vertices could not be matched: " + c.note};
    const double diagonal = bounding_box_diagonal(fan.positions);
    double worst = 0;
    for (size_t i = 0; i < c.ref_to_ours.size(); ++i) {
        const double d = (trace.back().positions[i] - expected.positions[static_cast<size_t>(c.ref_to_ours[i])]).norm();
        worst = std::max(worst, std::isfinite(d) ? d / diagonal : INFINITY);
    }
    return {worst, ""};
}

/// "core's warren weights, edge-only match the published stencils on 14 fans to 3.3e-17".
std::string passed_detail(const Implementation& impl, const LoopOptions& rule, int fans, double worst) {
    return impl.name() + "'s " + std::string(to_string(rule.weights)) + " weights, " + std::string(to_string(rule.boundary)) +
           " match the published stencils on " + std::to_string(fans) + " fans to " + detail::sci(worst);
}

/// "core's warren weights, edge-only on a closed fan of valence 4: differs ... by 9e-3 of the diagonal".
std::string failed_detail(const Implementation& impl, const LoopOptions& rule, const std::string& fan, double worst,
                          const std::string& reason) {
    return impl.name() + "'s " + std::string(to_string(rule.weights)) + " weights, " + std::string(to_string(rule.boundary)) +
           " on a " + fan + ": " +
           (reason.empty() ? "differs from the published stencils by " + detail::sci(worst) + " of the diagonal" : reason);
}

/// Whether one fan's measurement passes.
bool fan_passes(double worst, const std::string& reason) {
    return reason.empty() && worst <= tolerances::kAgreementRelative;
}

}  // namespace

RuleVerdict check_loop_rule(const Implementation& impl, const LoopOptions& rule, const std::vector<int>& valences) {
    RuleVerdict v;
    if (rule.weights != LoopWeights::Loop && rule.weights != LoopWeights::Warren) {
        v.detail = "no published closed form for the " + std::string(to_string(rule.weights)) + " weights";
        return v;
    }
    v.known = true;
    std::vector<int> closed;
    for (int n = 3; n <= 12; ++n) closed.push_back(n);
    for (int n : valences)
        if (n >= 3) closed.push_back(n);
    std::sort(closed.begin(), closed.end());
    closed.erase(std::unique(closed.begin(), closed.end()), closed.end());
    std::vector<std::pair<std::string, PolyMesh>> fans;
    for (int n : closed) fans.emplace_back("closed fan of valence " + std::to_string(n), to_poly_mesh(loop_fan(n)));
    for (int f = 1; f <= 4; ++f) fans.emplace_back("open fan of " + std::to_string(f) + " faces", open_fan(f));
    for (const auto& [name, fan] : fans) {
        const auto [worst, reason] = measure(impl, fan, rule);
        v.worst_rel = std::max(v.worst_rel, worst);
        ++v.meshes;
        if (!fan_passes(worst, reason)) {
            v.detail = failed_detail(impl, rule, name, worst, reason);
            return v;
        }
    }
    v.passed = true;
    v.detail = passed_detail(impl, rule, v.meshes, v.worst_rel);
    return v;
}

RuleVerdict check_core_loop_rule(const LoopOptions& rule, const std::vector<int>& valences) {
    // Per rule, the valences already checked and the first failure: a suite asks once per run.
    struct Entry {
        const Implementation* core;  // a test may stand a double in core's place
        LoopOptions rule;
        std::vector<int> checked;
        RuleVerdict verdict;
    };
    static std::mutex mutex;
    static std::vector<Entry> cache;
    std::lock_guard<std::mutex> lock(mutex);
    const Implementation* core = &core_implementation();
    // A stand-in for core (a test's double) is checked afresh: its address may be reused.
    if (core->kind() != ImplementationKind::Core) {
        std::vector<int> all(valences);
        return check_loop_rule(*core, rule, all);
    }
    auto it = std::find_if(cache.begin(), cache.end(), [&](const Entry& e) { return e.core == core && e.rule == rule; });
    if (it == cache.end()) {
        cache.push_back({core, rule, {}, check_loop_rule(*core, rule)});
        it = cache.end() - 1;
    }
    // Valences past the default 3..12 not checked yet: their closed fans alone.
    std::vector<int> fresh;
    for (int n : valences)
        if (n > 12 && std::find(it->checked.begin(), it->checked.end(), n) == it->checked.end()) fresh.push_back(n);
    std::sort(fresh.begin(), fresh.end());
    fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
    RuleVerdict& v = it->verdict;
    for (int n : fresh) {
        if (!v.passed) break;
        it->checked.push_back(n);
        const auto [worst, reason] = measure(*core, to_poly_mesh(loop_fan(n)), rule);
        v.worst_rel = std::max(v.worst_rel, worst);
        ++v.meshes;
        if (!fan_passes(worst, reason)) {
            v.passed = false;
            v.detail = failed_detail(*core, rule, "closed fan of valence " + std::to_string(n), worst, reason);
        } else {
            v.detail = passed_detail(*core, rule, v.meshes, v.worst_rel);
        }
    }
    return v;
}

}  // namespace crossdiv::verification
