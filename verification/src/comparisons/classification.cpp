#include "crossdiv/verification/comparisons/classification.h"

#include <algorithm>
#include <numeric>

#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/mesh/vertex_fans.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/nearest_points.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "harness/sci.h"

namespace crossdiv::verification {

Classification classify_divergence(const DivergenceTests& tests) {
    for (const DivergenceTest* test : {&tests.isolated_vertices, &tests.rounding, &tests.reference_rule,
                                       &tests.valence_table, &tests.short_boundary_loops, &tests.nonmanifold, &tests.topology})
        if (*test)
            if (std::optional<Classification> c = (*test)()) return *c;
    return {DivergenceClass::Unexplained, tests.unexplained ? tests.unexplained() : std::string()};
}

DivergenceClass rule_difference_class(Scheme scheme, const SchemeRule& applied, const SchemeRule& requested) {
    switch (scheme) {
        case Scheme::Loop: {
            const bool weights = applied.loop.weights != requested.loop.weights;
            const bool boundary = applied.loop.boundary != requested.loop.boundary;
            if (!weights && !boundary && applied.loop.crease_rules != requested.loop.crease_rules) return DivergenceClass::CreaseRules;
            return weights && boundary ? DivergenceClass::WeightFamilyAndCornerRule
                   : weights           ? DivergenceClass::WeightFamily
                                       : DivergenceClass::CornerRule;
        }
        case Scheme::CatmullClark: {
            const CatmullClarkOptions &a = applied.catmull_clark, &r = requested.catmull_clark;
            const bool boundary = a.boundary != r.boundary, vertex = a.vertex != r.vertex;
            if (!boundary && !vertex && a.smooth_triangles == r.smooth_triangles && a.crease_rules != r.crease_rules)
                return DivergenceClass::CreaseRules;
            if (a.smooth_triangles != r.smooth_triangles && !boundary && !vertex) return DivergenceClass::TriangleRule;
            const auto corner_only = [](CatmullClarkBoundary x) {
                return x == CatmullClarkBoundary::EdgeOnly || x == CatmullClarkBoundary::EdgeAndCorner;
            };
            const bool corner = boundary && corner_only(a.boundary) && corner_only(r.boundary);
            // The interior vertex rule is the weight family of Catmull-Clark; with another
            // boundary rule besides, the sentence names both rules.
            if (vertex) return corner ? DivergenceClass::WeightFamilyAndCornerRule : DivergenceClass::WeightFamily;
            return corner ? DivergenceClass::CornerRule : DivergenceClass::BoundaryRule;
        }
        case Scheme::DooSabin:
            if (applied.doo_sabin.boundary == requested.doo_sabin.boundary) return DivergenceClass::WeightFamily;
            return applied.doo_sabin.boundary == DooSabinBoundary::DropBorderFaces ? DivergenceClass::BorderFacesDropped
                                                                                   : DivergenceClass::BoundaryRule;
        case Scheme::Sqrt3: return DivergenceClass::Parity;
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: return DivergenceClass::WingRule;
        case Scheme::Bilinear:
        case Scheme::Midpoint: break;  // one rule: no rule difference to name
    }
    return DivergenceClass::BoundaryRule;
}

std::vector<char> nonmanifold_reach(const std::vector<const PolyMesh*>& levels) {
    if (levels.empty()) return {};
    PolyMesh base = *levels[0];
    base.creases = {};  // the topology alone
    return reach_of(levels, nonmanifold_vertices(base));
}

std::vector<char> reach_of(const std::vector<const PolyMesh*>& levels, const std::vector<int>& seeds) {
    if (levels.empty() || seeds.empty()) return {};
    const PolyMesh& base = *levels[0];
    std::vector<char> reached(static_cast<size_t>(base.num_vertices()), 0);
    for (int v : seeds) reached[static_cast<size_t>(v)] = 1;
    for (size_t l = 0; l + 1 < levels.size(); ++l) {
        const PolyMesh& coarse = *levels[l];
        const PolyMesh& fine = *levels[l + 1];
        std::vector<char> near = reached;  // reached, or sharing a face with a reached vertex
        for (int f = 0; f < coarse.num_faces(); ++f) {
            const int* c = coarse.face(f);
            const int n = coarse.face_size(f);
            if (std::any_of(c, c + n, [&](int v) { return reached[static_cast<size_t>(v)]; }))
                for (int k = 0; k < n; ++k) near[static_cast<size_t>(c[k])] = 1;
        }
        const int n_old = coarse.num_vertices();
        std::vector<char> next(static_cast<size_t>(fine.num_vertices()), 0);
        for (int v = 0; v < n_old; ++v) next[static_cast<size_t>(v)] = near[static_cast<size_t>(v)];
        for (int f = 0; f < fine.num_faces(); ++f) {
            const int* c = fine.face(f);
            const int n = fine.face_size(f);
            if (std::any_of(c, c + n, [&](int v) { return v < n_old && near[static_cast<size_t>(v)]; }))
                for (int k = 0; k < n; ++k)
                    if (c[k] >= n_old) next[static_cast<size_t>(c[k])] = 1;
        }
        reached = std::move(next);
    }
    return reached;
}

namespace {

/// The vertices of `ours` farther than `tolerance` x its diagonal from their match in `ref`,
/// when every such vertex that some face uses lies where `reach` marks: how many, and how many
/// no face uses (isolated-vertex-handling, the other named cause a reference may show beside,
/// counted apart and never in the reach). Nothing when one lies outside, or the sizes differ.
struct DifferingInReach {
    int differing = 0, isolated = 0;
    long long reached = 0;
};
std::optional<DifferingInReach> differing_in_reach(const std::vector<char>& reach, const PolyMesh& ours, const PolyMesh& ref,
                                                   const std::vector<int>& ref_to_ours, double tolerance) {
    if (reach.size() != static_cast<size_t>(ours.num_vertices()) ||
        ref_to_ours.size() != static_cast<size_t>(ref.num_vertices()))
        return std::nullopt;
    const double diagonal = bounding_box_diagonal(ours.positions);
    std::vector<char> used(static_cast<size_t>(ours.num_vertices()), 0);
    for (int v : ours.face_vertices) used[static_cast<size_t>(v)] = 1;
    DifferingInReach out;
    for (size_t i = 0; i < ref_to_ours.size(); ++i) {
        const int v = ref_to_ours[i];
        if (v < 0 || v >= ours.num_vertices()) return std::nullopt;
        if ((ours.positions[static_cast<size_t>(v)] - ref.positions[i]).norm() / diagonal <= tolerance) continue;
        if (!used[static_cast<size_t>(v)]) {
            ++out.isolated;
            continue;
        }
        if (!reach[static_cast<size_t>(v)]) return std::nullopt;
        ++out.differing;
    }
    out.reached = std::count(reach.begin(), reach.end(), 1);
    return out;
}

std::string isolated_too(int isolated) {
    return isolated ? "; " + std::to_string(isolated) + " vertices no face uses differ too (isolated-vertex-handling)" : "";
}

}  // namespace

std::optional<Classification> nonmanifold_handling(const std::vector<char>& reach, const PolyMesh& ours,
                                                   const PolyMesh& ref, const std::vector<int>& ref_to_ours,
                                                   double tolerance, const std::string& reference, double max_rel,
                                                   const std::string& against) {
    const std::optional<DifferingInReach> d = differing_in_reach(reach, ours, ref, ref_to_ours, tolerance);
    if (!d) return std::nullopt;
    return Classification{DivergenceClass::NonManifoldHandling,
                          reference + " refines the non-manifold vertices by another rule than OpenSubdiv's, which core "
                          "follows: all " + std::to_string(d->differing) + " vertices that differ" + against + " (by up to " +
                          detail::sci(max_rel) + ") lie where they reach (" + std::to_string(d->reached) + " of " +
                          std::to_string(ours.num_vertices()) + " vertices)" + isolated_too(d->isolated)};
}

std::optional<Classification> fan_walk_handling(const std::vector<char>& reach, const std::vector<int>& accepted,
                                                const PolyMesh& ours, const PolyMesh& ref,
                                                const std::vector<int>& ref_to_ours, double tolerance,
                                                const std::string& reference, double max_rel) {
    if (accepted.empty()) return std::nullopt;
    const std::optional<DifferingInReach> d = differing_in_reach(reach, ours, ref, ref_to_ours, tolerance);
    if (!d) return std::nullopt;
    std::string named;
    for (size_t k = 0; k < accepted.size() && k < 5; ++k) named += (k ? ", " : "") + std::to_string(accepted[k]);
    if (accepted.size() > 5) named += ", ...";
    const bool one = accepted.size() == 1;
    return Classification{DivergenceClass::FanWalk,
                          reference + "'s walk around input vert" + (one ? "ex " : "ices ") + named +
                          " (a face names " + (one ? "it" : "each") + " twice, not in a row) takes " + (one ? "its" : "their") +
                          " fans of faces for one, a manifold vertex refined by a ring with an edge taken twice, where "
                          "core keeps " + (one ? "it as a non-manifold corner" : "them as non-manifold corners") + ": all " +
                          std::to_string(d->differing) + " vertices that differ (by up to " + detail::sci(max_rel) +
                          ") lie where they reach (" + std::to_string(d->reached) + " of " +
                          std::to_string(ours.num_vertices()) + " vertices)" + isolated_too(d->isolated)};
}

std::optional<Classification> split_fans_handling(const PolyMesh& input, const PolyMesh& ref,
                                                  const std::function<std::optional<PolyMesh>(const PolyMesh&)>& core_refine,
                                                  double tolerance, const std::string& reference) {
    std::vector<int> original;
    const PolyMesh split = split_vertex_fans(input, &original);
    if (split.num_vertices() == input.num_vertices()) return std::nullopt;
    const std::optional<PolyMesh> ours = core_refine(split);
    if (!ours || ours->num_vertices() != ref.num_vertices()) return std::nullopt;
    const Correspondence c = match_nearest_and_faces(*ours, ref);
    if (c.method == MatchMethod::None) return std::nullopt;
    const MeshComparison m = compare_meshes(*ours, ref, c.ref_to_ours);
    if (!m.topology_equal() || !(m.max_rel <= tolerance)) return std::nullopt;
    std::vector<char> split_vertex(static_cast<size_t>(input.num_vertices()), 0);
    for (size_t v = static_cast<size_t>(input.num_vertices()); v < original.size(); ++v) split_vertex[static_cast<size_t>(original[v])] = 1;
    const auto vertices = std::count(split_vertex.begin(), split_vertex.end(), 1);
    return Classification{DivergenceClass::NonManifoldHandling,
                          reference + " splits each vertex whose faces form more than one fan into one vertex per fan (" +
                              std::to_string(vertices) + (vertices == 1 ? " vertex into " : " vertices into ") +
                              std::to_string(vertices + split.num_vertices() - input.num_vertices()) +
                              ") and refines the result as a manifold: it agrees with core on that split mesh (max "
                              "relative error " + detail::sci(m.max_rel) + " <= " + detail::sci(tolerance) +
                              "), where core follows OpenSubdiv's non-manifold rules on the input itself"};
}

std::optional<Classification> rounding_among_near_vertices(const PolyMesh& ours, const PolyMesh& ref, double tolerance) {
    const size_t n = ours.positions.size();
    if (n == 0 || ref.positions.size() != n || ref.num_faces() != ours.num_faces() ||
        ref.face_vertices.size() != ours.face_vertices.size())
        return std::nullopt;
    const double reach = tolerance * bounding_box_diagonal(ours.positions);
    if (!(reach > 0)) return std::nullopt;
    const NearestPoints index(ours.positions);
    constexpr size_t k = NearestPoints::kMaxNeighbours;
    unsigned near[k];
    double d2[k];
    // Our vertices with another within the rounding: where a match by position may err.
    int close = 0;
    for (size_t v = 0; v < n; ++v)
        close += index.nearest(ours.positions[v], 2, near, d2) == 2 && d2[1] <= reach * reach;
    if (close == 0) return std::nullopt;
    // Both ways: every vertex of each within the rounding of one of the other's.
    double farthest = 0;
    for (const Vec3& p : ref.positions) {
        if (index.nearest(p, 1, near, d2) != 1 || !(d2[0] <= reach * reach)) return std::nullopt;
        farthest = std::max(farthest, std::sqrt(d2[0]));
    }
    const NearestPoints ref_index(ref.positions);
    for (const Vec3& p : ours.positions)
        if (ref_index.nearest(p, 1, near, d2) != 1 || !(d2[0] <= reach * reach)) return std::nullopt;
    // Our faces around each vertex, in compressed rows.
    std::vector<int> first(n + 1, 0), around(ours.face_vertices.size());
    for (int v : ours.face_vertices) ++first[static_cast<size_t>(v) + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    {
        std::vector<int> fill(first.begin(), first.end() - 1);
        for (int f = 0; f < ours.num_faces(); ++f)
            for (int c = 0; c < ours.face_size(f); ++c) around[static_cast<size_t>(fill[static_cast<size_t>(ours.face(f)[c])]++)] = f;
    }
    // Each face of ref on one of ours not yet taken whose corners, in the same cycle, each lie
    // within the rounding of its own, found among the faces around our vertices near its first.
    std::vector<char> taken(static_cast<size_t>(ours.num_faces()), 0);
    const auto within = [&](int u, int r) {
        return (ours.positions[static_cast<size_t>(u)] - ref.positions[static_cast<size_t>(r)]).squaredNorm() <= reach * reach;
    };
    for (int g = 0; g < ref.num_faces(); ++g) {
        const int m = ref.face_size(g);
        const int* rg = ref.face(g);
        const size_t found = index.nearest(ref.positions[static_cast<size_t>(rg[0])], k, near, d2);
        int partner = -1;
        for (size_t i = 0; i < found && partner < 0 && d2[i] <= reach * reach; ++i)
            for (int a = first[near[i]]; a < first[near[i] + 1] && partner < 0; ++a) {
                const int f = around[static_cast<size_t>(a)];
                if (taken[static_cast<size_t>(f)] || ours.face_size(f) != m) continue;
                const int* of = ours.face(f);
                for (int j = 0; j < m && partner < 0; ++j) {
                    if (of[j] != static_cast<int>(near[i])) continue;
                    bool same = true;
                    for (int c = 1; c < m && same; ++c) same = within(of[(j + c) % m], rg[c]);
                    if (same) partner = f;
                }
            }
        // None: not core's face, or core's beyond the nearest listed (more lie that near): no test.
        if (partner < 0) return std::nullopt;
        taken[static_cast<size_t>(partner)] = 1;
    }
    return Classification{DivergenceClass::Rounding,
                          "the same vertices and faces up to its rounding (" + detail::sci(reach) +
                              "): every vertex within " + detail::sci(farthest) +
                              " of one of core's, and every face on one of core's whose corners lie as near, in the same "
                              "cycle; " + std::to_string(close) +
                              " of core's vertices have another within that distance, which a match by position cannot "
                              "tell apart"};
}

bool measured_topology_difference(const TopologyCounts& ours, const TopologyCounts& ref, bool face_sets_equal,
                                  MatchMethod method) {
    if (!(ours == ref)) return true;
    return !face_sets_equal && (method == MatchMethod::Order || method == MatchMethod::Topology);
}

DivergenceClass input_handling_class(const PolyMesh& input) {
    for (const MeshIssue& issue : check_mesh(input)) {
        if (issue.severity != Severity::Error) continue;
        if (issue.kind == MeshIssueKind::NonManifoldEdge || issue.kind == MeshIssueKind::NonManifoldVertex)
            return DivergenceClass::NonManifoldHandling;
        if (issue.kind == MeshIssueKind::InconsistentOrientation) return DivergenceClass::OrientationHandling;
        if (issue.kind == MeshIssueKind::RepeatedVertex || issue.kind == MeshIssueKind::TooFewCorners)
            return DivergenceClass::DegenerateFaceHandling;
        return DivergenceClass::InvalidInputHandling;
    }
    return DivergenceClass::InvalidInputHandling;
}

}  // namespace crossdiv::verification
