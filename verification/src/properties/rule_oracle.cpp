// The oracles of the polygon schemes' named rules (rule_oracle.h), independent of core: the
// weights written out here, the expected vertex set built from the input alone.
#include "crossdiv/verification/properties/rule_oracle.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "crossdiv/verification/harness/correspondence.h"
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

/// The level-1 vertices the rule makes, as a set: a corner point per face corner, and
/// Chaikin's two points per boundary edge under chaikin-boundary.
std::vector<Vec3> doo_sabin_vertices(const PolyMesh& m, const DooSabinOptions& rule) {
    std::vector<Vec3> out;
    for (int f = 0; f < m.num_faces(); ++f) {
        const int n = m.face_size(f);
        for (int i = 0; i < n; ++i) {
            Vec3 p = Vec3::Zero();
            for (int k = 0; k < n; ++k) {
                const double alpha = k == 0 ? 0.25 + 5.0 / (4.0 * n) : (3.0 + 2.0 * std::cos(2 * M_PI * k / n)) / (4.0 * n);
                p += alpha * m.positions[static_cast<size_t>(m.face(f)[(i + k) % n])];
            }
            out.push_back(p);
        }
    }
    if (rule.boundary == DooSabinBoundary::ChaikinBoundary) {
        // An edge is on the boundary when one face traverses it: count both directions.
        std::vector<std::pair<int, int>> directed;
        for (int f = 0; f < m.num_faces(); ++f)
            for (int i = 0; i < m.face_size(f); ++i)
                directed.emplace_back(m.face(f)[i], m.face(f)[(i + 1) % m.face_size(f)]);
        std::sort(directed.begin(), directed.end());
        for (const auto& [a, b] : directed)
            if (!std::binary_search(directed.begin(), directed.end(), std::pair{b, a})) {
                const Vec3 &pa = m.positions[static_cast<size_t>(a)], &pb = m.positions[static_cast<size_t>(b)];
                out.push_back(0.75 * pa + 0.25 * pb);
                out.push_back(0.25 * pa + 0.75 * pb);
            }
    }
    return out;
}

}  // namespace

RuleVerdict check_doo_sabin_rule(const Implementation& impl, const DooSabinOptions& rule) {
    RuleVerdict v;
    v.known = true;
    const std::string who = impl.name() + "'s Doo-Sabin, " + std::string(to_string(rule.boundary));
    for (const auto& [name, mesh] : {std::pair{std::string("open strip of a triangle, quads and a pentagon"), open_polygons()},
                                     std::pair{std::string("closed triangular prism"), closed_prism()}}) {
        ++v.meshes;
        std::string reason;
        double worst = INFINITY;
        try {
            const PolyMesh got = impl.refine_last(mesh, {Scheme::DooSabin, SchemeRule{.doo_sabin = rule}, 1});
            const std::vector<Vec3> expected = doo_sabin_vertices(mesh, rule);
            const Correspondence c = match_nearest(expected, got.positions);
            if (got.num_vertices() != static_cast<int>(expected.size()))
                reason = std::to_string(got.num_vertices()) + " vertices where the rule makes " + std::to_string(expected.size());
            else if (c.method == MatchMethod::None)
                reason = "its vertices are not the rule's, one to one";
            else {
                worst = 0;
                for (size_t i = 0; i < c.ref_to_ours.size(); ++i)
                    worst = std::max(worst, (got.positions[i] - expected[static_cast<size_t>(c.ref_to_ours[i])]).norm());
                worst /= bounding_box_diagonal(mesh.positions);
            }
        } catch (const std::exception& e) {
            reason = std::string("refused: ") + e.what();
        }
        if (reason.empty()) v.worst_rel = std::max(v.worst_rel, worst);
        if (!reason.empty() || !(worst <= tolerances::kAgreementRelative)) {
            v.detail = who + " on a " + name + ": " +
                       (reason.empty() ? "differs from the published points by " + detail::sci(worst) + " of the diagonal"
                                       : reason);
            return v;
        }
    }
    v.passed = true;
    v.detail = who + " makes the published points on " + std::to_string(v.meshes) + " meshes to " + detail::sci(v.worst_rel);
    return v;
}

RuleVerdict check_core_rule(Scheme scheme, const SchemeRule& rule, const std::vector<int>& valences) {
    switch (scheme) {
        case Scheme::Loop: return check_core_loop_rule(rule.loop, valences);
        case Scheme::DooSabin: return check_doo_sabin_rule(core_implementation(), rule.doo_sabin);
        default: {
            RuleVerdict v;
            v.detail = "no oracle for " + rule_name(scheme, rule);
            return v;
        }
    }
}

}  // namespace crossdiv::verification
