// The oracles of the polygon schemes' named rules (rule_oracle.h), independent of core: the
// weights written out here, the expected vertex set built from the input alone.
#include "crossdiv/verification/properties/rule_oracle.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/fans.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/properties/loop_rule_oracle.h"
#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

/// An open strip: a triangle, two quads and a pentagon side by side, bent out of the plane.
PolyMesh open_polygons() {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0),   Vec3(1, 0, 0.1),   Vec3(2, 0, 0),     Vec3(3, 0, 0.2),  Vec3(4.1, 0.2, 0),
                   Vec3(0, 1, 0.3), Vec3(1, 1.1, 0),   Vec3(2.1, 1, 0.4), Vec3(3, 1.2, 0),  Vec3(3.6, 1.9, 0.3)};
    m.add_face({0, 1, 5});
    m.add_face({1, 6, 5});
    m.add_face({1, 2, 7, 6});
    m.add_face({2, 3, 8, 7});
    m.add_face({3, 4, 9, 8});
    return m;
}

/// A closed triangular prism, skewed: two triangles and three quads.
PolyMesh closed_prism() {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0.1), Vec3(0.4, 0.9, 0), Vec3(0.1, 0.1, 1.2), Vec3(1.2, 0, 1), Vec3(0.5, 1, 1.1)};
    m.add_face({0, 2, 1});
    m.add_face({3, 4, 5});
    m.add_face({0, 1, 4, 3});
    m.add_face({1, 2, 5, 4});
    m.add_face({2, 0, 3, 5});
    return m;
}

/// The directed edges a -> b of `m` that one face traverses and none traverses back: its
/// boundary, each edge as its face walks it.
std::vector<std::pair<int, int>> boundary_edges(const PolyMesh& m) {
    std::vector<std::pair<int, int>> directed;
    for (int f = 0; f < m.num_faces(); ++f)
        for (int i = 0; i < m.face_size(f); ++i) directed.emplace_back(m.face(f)[i], m.face(f)[(i + 1) % m.face_size(f)]);
    std::sort(directed.begin(), directed.end());
    std::vector<std::pair<int, int>> boundary;
    for (const auto& [a, b] : directed)
        if (!std::binary_search(directed.begin(), directed.end(), std::pair{b, a})) boundary.emplace_back(a, b);
    return boundary;
}

/// The level-1 vertices the rule makes, as a set: a corner point per face corner, and
/// Chaikin's two points per boundary edge under chaikin-boundary.
std::vector<Vec3> doo_sabin_vertices(const PolyMesh& m, const DooSabinOptions& rule) {
    std::vector<Vec3> out;
    for (int f = 0; f < m.num_faces(); ++f) {
        const int n = m.face_size(f);
        const auto at = [&](int k) -> const Vec3& { return m.positions[static_cast<size_t>(m.face(f)[(k + n) % n])]; };
        Vec3 centroid = Vec3::Zero();
        for (int k = 0; k < n; ++k) centroid += at(k) / n;
        for (int i = 0; i < n; ++i) {
            Vec3 p = Vec3::Zero();
            if (rule.weights == DooSabinWeights::CatmullClark) {
                // Catmull and Clark's construction: the vertex, its two edge midpoints in the
                // face and the centroid, averaged.
                p = (at(i) + 0.5 * (at(i) + at(i + 1)) + 0.5 * (at(i) + at(i - 1)) + centroid) / 4;
            } else {
                for (int k = 0; k < n; ++k) {
                    const double alpha = k == 0 ? 0.25 + 5.0 / (4.0 * n) : (3.0 + 2.0 * std::cos(2 * M_PI * k / n)) / (4.0 * n);
                    p += alpha * at(i + k);
                }
            }
            out.push_back(p);
        }
    }
    if (rule.boundary == DooSabinBoundary::ChaikinBoundary)
        for (const auto& [a, b] : boundary_edges(m)) {
            const Vec3 &pa = m.positions[static_cast<size_t>(a)], &pb = m.positions[static_cast<size_t>(b)];
            out.push_back(0.75 * pa + 0.25 * pb);
            out.push_back(0.25 * pa + 0.75 * pb);
        }
    return out;
}

/// Chaikin's refined boundary of `m` as segments: on each boundary edge a -> b its two points
/// 3/4 a + 1/4 b and 1/4 a + 3/4 b joined, and the second joined to the first of the boundary
/// edge that leaves b. The vertex set alone does not see near and far swapped; these do.
std::vector<std::pair<Vec3, Vec3>> chaikin_boundary_segments(const PolyMesh& m) {
    const std::vector<std::pair<int, int>> boundary = boundary_edges(m);
    const auto at = [&](int v) -> const Vec3& { return m.positions[static_cast<size_t>(v)]; };
    std::vector<std::pair<Vec3, Vec3>> segments;
    for (const auto& [a, b] : boundary) {
        segments.emplace_back(0.75 * at(a) + 0.25 * at(b), 0.25 * at(a) + 0.75 * at(b));
        for (const auto& [b2, c] : boundary)  // the boundary edge leaving b (one on a manifold)
            if (b2 == b) segments.emplace_back(0.25 * at(a) + 0.75 * at(b), 0.75 * at(b) + 0.25 * at(c));
    }
    return segments;
}

/// The boundary edges of one level of `impl` on `mesh` against `expected` segments, one to one
/// by their end positions: the largest end distance over the diagonal, or why they do not pair.
std::pair<double, std::string> boundary_against(const Implementation& impl, const PolyMesh& mesh, const RefineRequest& request,
                                                const std::vector<std::pair<Vec3, Vec3>>& expected) {
    PolyMesh got;
    try {
        got = impl.refine_last(mesh, request);
    } catch (const std::exception& e) {
        return {INFINITY, std::string("refused: ") + e.what()};
    }
    std::vector<std::pair<Vec3, Vec3>> edges;
    for (const auto& [a, b] : boundary_edges(got))
        edges.emplace_back(got.positions[static_cast<size_t>(a)], got.positions[static_cast<size_t>(b)]);
    if (edges.size() != expected.size())
        return {INFINITY, std::to_string(edges.size()) + " boundary edges where the rule makes " + std::to_string(expected.size())};
    const double diagonal = bounding_box_diagonal(mesh.positions);
    std::vector<bool> used(expected.size(), false);
    double worst = 0;
    for (const auto& [p, q] : edges) {
        // Its nearest unused segment, either way round (a few dozen segments: a plain search).
        size_t best = expected.size();
        double best_d = INFINITY;
        for (size_t k = 0; k < expected.size(); ++k) {
            if (used[k]) continue;
            const auto& [e0, e1] = expected[k];
            const double d = std::min(std::max((p - e0).norm(), (q - e1).norm()), std::max((p - e1).norm(), (q - e0).norm()));
            if (d < best_d) best_d = d, best = k;
        }
        if (best == expected.size() || best_d > tolerances::kAgreementRelative * diagonal)
            return {INFINITY, "a boundary edge from (" + detail::sci(p.x()) + ", " + detail::sci(p.y()) + ", " + detail::sci(p.z()) +
                                  ") joins points Chaikin's boundary does not join"};
        used[best] = true;
        worst = std::max(worst, best_d / diagonal);
    }
    return {worst, ""};
}

/// Largest distance from each of `got` to its one-to-one match in `expected`, or a reason
/// there is no such match.
std::pair<double, std::string> set_distance(const std::vector<Vec3>& expected, const std::vector<Vec3>& got) {
    if (got.size() != expected.size())
        return {INFINITY, std::to_string(got.size()) + " vertices where the rule makes " + std::to_string(expected.size())};
    const Correspondence c = match_nearest(expected, got);
    if (c.method == MatchMethod::None) return {INFINITY, "its vertices are not the rule's, one to one"};
    double worst = 0;
    for (size_t i = 0; i < c.ref_to_ours.size(); ++i)
        worst = std::max(worst, (got[i] - expected[static_cast<size_t>(c.ref_to_ours[i])]).norm());
    return {worst, ""};
}

/// One level of `impl` on `mesh` under `request`, its vertex set against `expected`: the
/// largest distance over the mesh's diagonal, or why it could not be measured.
std::pair<double, std::string> level_against(const Implementation& impl, const PolyMesh& mesh, const RefineRequest& request,
                                             const std::vector<Vec3>& expected) {
    try {
        const PolyMesh got = impl.refine_last(mesh, request);
        const auto [worst, reason] = set_distance(expected, got.positions);
        return {worst / bounding_box_diagonal(mesh.positions), reason};
    } catch (const std::exception& e) {
        return {INFINITY, std::string("refused: ") + e.what()};
    }
}

/// Counts one comparison into `v` (a mesh, unless `another_look` at one already counted): true
/// when it passes; else false, with the failure's sentence.
bool record(RuleVerdict& v, const std::string& who, const std::string& where, double worst_rel, const std::string& reason,
            bool another_look = false) {
    if (!another_look) ++v.meshes;
    if (reason.empty()) v.worst_rel = std::max(v.worst_rel, worst_rel);
    if (reason.empty() && worst_rel <= tolerances::kAgreementRelative) return true;
    v.detail = who + " on " + where + ": " +
               (reason.empty() ? "differs from the published points by " + detail::sci(worst_rel) + " of the diagonal" : reason);
    return false;
}

/// The classic Butterfly's level-1 vertices on a triangle mesh, as a set: the old vertices
/// (it interpolates), the eight-point stencil on each interior edge with each missing wing
/// taken by `wings`, the four-point rule on each boundary edge.
std::vector<Vec3> butterfly_vertices(const PolyMesh& m, ButterflyWings wings) {
    struct Half {
        int from, to, third;
    };
    std::vector<Half> halves;
    for (int f = 0; f < m.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) halves.push_back({m.face(f)[k], m.face(f)[(k + 1) % 3], m.face(f)[(k + 2) % 3]});
    std::sort(halves.begin(), halves.end(), [](const Half& x, const Half& y) { return std::pair{x.from, x.to} < std::pair{y.from, y.to}; });
    const auto find = [&](int from, int to) -> const Half* {
        const auto it = std::lower_bound(halves.begin(), halves.end(), std::pair{from, to},
                                         [](const Half& h, const std::pair<int, int>& k) { return std::pair{h.from, h.to} < k; });
        return it != halves.end() && it->from == from && it->to == to ? &*it : nullptr;
    };
    const auto& p = m.positions;
    const auto at = [&](int v) -> const Vec3& { return p[static_cast<size_t>(v)]; };
    // The wing beyond edge (x, y) of the triangle whose third vertex is t; `other` is the
    // apex of the triangle across the central edge.
    const auto wing = [&](int x, int y, int t, int other) -> Vec3 {
        if (const Half* across = find(y, x)) return at(across->third);
        switch (wings) {
            case ButterflyWings::Reflected: return at(x) + at(y) - at(t);
            case ButterflyWings::OppositeVertex: return at(t);
            case ButterflyWings::OtherFaceVertex: return at(other);
        }
        return at(t);
    };
    std::vector<Vec3> out(p.begin(), p.end());
    for (const Half& h : halves) {
        const Half* twin = find(h.to, h.from);
        if (twin && h.from > h.to) continue;  // each interior edge once
        const int a = h.from, b = h.to;
        if (!twin) {
            // Boundary polygon: p -> a -> b -> q, each step a boundary half-edge.
            int before = -1, after = -1;
            for (const Half& g : halves) {
                if (g.to == a && !find(a, g.from)) before = g.from;
                if (g.from == b && !find(g.to, b)) after = g.to;
            }
            out.push_back(9.0 / 16.0 * (at(a) + at(b)) - 1.0 / 16.0 * (at(before) + at(after)));
            continue;
        }
        const int o1 = h.third, o2 = twin->third;
        out.push_back(0.5 * (at(a) + at(b)) + 0.125 * (at(o1) + at(o2)) -
                      0.0625 * (wing(b, o1, a, o2) + wing(o1, a, b, o2) + wing(a, o2, b, o1) + wing(o2, b, a, o1)));
    }
    return out;
}

}  // namespace

RuleVerdict check_butterfly_rule(const Implementation& impl, ButterflyWings wings) {
    RuleVerdict v;
    v.known = true;
    const std::string who = impl.name() + "'s Butterfly, " + std::string(to_string(wings));
    // A disc of seven triangles: every spoke has two wings beyond the boundary.
    const PolyMesh disc = to_poly_mesh(loop_fan(7));
    const auto [worst, reason] = level_against(impl, disc, {Scheme::Butterfly, SchemeRule{.butterfly_wings = wings}, 1},
                                               butterfly_vertices(disc, wings));
    if (!record(v, who, "a disc of seven triangles", worst, reason)) return v;
    v.passed = true;
    v.detail = who + " makes the published points on a disc to " + detail::sci(v.worst_rel);
    return v;
}

RuleVerdict check_sqrt3_rule(const Implementation& impl, const Sqrt3Options& rule) {
    RuleVerdict v;
    v.known = true;
    const std::string who = impl.name() + "'s sqrt3, " + std::string(to_string(rule.parity));
    // A disc of six triangles: the centre interior (valence 6), the ring its boundary loop.
    const PolyMesh disc = to_poly_mesh(loop_fan(6));
    const int n = 6;
    const double diagonal = bounding_box_diagonal(disc.positions);
    adapters::LevelTrace trace;
    try {
        trace = impl.refine(disc, {Scheme::Sqrt3, SchemeRule{.sqrt3 = rule}, 2});
    } catch (const std::exception& e) {
        record(v, who, "a disc of six triangles", INFINITY, std::string("refused: ") + e.what());
        return v;
    }
    const auto& p = disc.positions;
    // Level 1, generation 0: the centre smoothed with Kobbelt's alpha_6 = (4 - 2 cos(pi/3)) / 9
    // = 1/3, the boundary kept, a centroid per triangle.
    std::vector<Vec3> level1;
    Vec3 centre = (2.0 / 3.0) * p[0];
    for (int k = 1; k <= n; ++k) centre += (1.0 / 18.0) * p[static_cast<size_t>(k)];
    level1.push_back(centre);
    for (int k = 1; k <= n; ++k) level1.push_back(p[static_cast<size_t>(k)]);
    for (int k = 0; k < n; ++k) level1.push_back((p[0] + p[static_cast<size_t>(1 + k)] + p[static_cast<size_t>(1 + (k + 1) % n)]) / 3.0);
    const auto [d1, r1] = set_distance(level1, trace[1].positions);
    if (!record(v, who, "level 1 of a disc of six triangles", d1 / diagonal, r1)) return v;
    // Level 2's boundary: generation 1 trisects the ring (Kobbelt, section 4) when counted
    // from the input; restarted at each level it is generation 0 again and the ring stays.
    std::vector<Vec3> boundary;
    for (int k = 0; k < n; ++k) {
        const Vec3 &prev = p[static_cast<size_t>(1 + (k + n - 1) % n)], &a = p[static_cast<size_t>(1 + k)],
                   &b = p[static_cast<size_t>(1 + (k + 1) % n)], &next = p[static_cast<size_t>(1 + (k + 2) % n)];
        if (rule.parity == Sqrt3Parity::RestartEachLevel) {
            boundary.push_back(a);
            continue;
        }
        boundary.push_back((4.0 * prev + 19.0 * a + 4.0 * b) / 27.0);
        boundary.push_back((prev + 16.0 * a + 10.0 * b) / 27.0);
        boundary.push_back((10.0 * a + 16.0 * b + next) / 27.0);
    }
    const MeshTopology t = mesh_topology(trace[2]);
    std::vector<Vec3> got;
    for (int i = 0; i < trace[2].num_vertices(); ++i)
        if (t.boundary_vertex[static_cast<size_t>(i)]) got.push_back(trace[2].positions[static_cast<size_t>(i)]);
    const auto [d2, r2] = set_distance(boundary, got);
    if (!record(v, who, "the boundary of level 2 of a disc of six triangles", d2 / diagonal,
                r2.empty() ? r2 : "boundary: " + r2))
        return v;
    v.passed = true;
    v.detail = who + " makes the published points at both levels of a disc to " + detail::sci(v.worst_rel);
    return v;
}

RuleVerdict check_doo_sabin_rule(const Implementation& impl, const DooSabinOptions& rule) {
    RuleVerdict v;
    v.known = true;
    const std::string who = impl.name() + "'s Doo-Sabin, " + rule_name(Scheme::DooSabin, SchemeRule{.doo_sabin = rule});
    for (const auto& [name, mesh] : {std::pair{std::string("an open strip of a triangle, quads and a pentagon"), open_polygons()},
                                     std::pair{std::string("a closed triangular prism"), closed_prism()}}) {
        const RefineRequest request{Scheme::DooSabin, SchemeRule{.doo_sabin = rule}, 1};
        const auto [worst, reason] = level_against(impl, mesh, request, doo_sabin_vertices(mesh, rule));
        if (!record(v, who, name, worst, reason)) return v;
        if (rule.boundary != DooSabinBoundary::ChaikinBoundary || mesh_topology(mesh).boundary_loops == 0) continue;
        const auto [edge_worst, edge_reason] = boundary_against(impl, mesh, request, chaikin_boundary_segments(mesh));
        if (!record(v, who, name + " (its boundary polyline)", edge_worst, edge_reason, true)) return v;
    }
    v.passed = true;
    v.detail = who + " makes the published points on " + std::to_string(v.meshes) + " meshes to " + detail::sci(v.worst_rel);
    return v;
}

Check oracle_check(const std::string& reference, const std::string& name, const std::string& subject, const RuleVerdict& v) {
    const bool measured = v.passed || v.worst_rel > tolerances::kAgreementRelative;  // else a structural reason
    return decided_check(reference, name, subject, measured ? v.worst_rel : INFINITY,
                         tolerances::kAgreementRelative, "rel", v.detail,
                         v.passed ? Outcome{Verdict::Agree, DivergenceClass::None}
                                  : Outcome{Verdict::Diverge, DivergenceClass::Unexplained});
}

RuleVerdict check_core_rule(Scheme scheme, const SchemeRule& rule, const std::vector<int>& valences) {
    switch (scheme) {
        case Scheme::Loop: return check_core_loop_rule(rule.loop, valences);
        case Scheme::DooSabin: return check_doo_sabin_rule(core_implementation(), rule.doo_sabin);
        case Scheme::Sqrt3: return check_sqrt3_rule(core_implementation(), rule.sqrt3);
        case Scheme::Butterfly: return check_butterfly_rule(core_implementation(), rule.butterfly_wings);
        default: {
            RuleVerdict v;
            v.detail = "no oracle for " + rule_name(scheme, rule);
            return v;
        }
    }
}

}  // namespace crossdiv::verification
