#include "crossdiv/verification/comparisons/invariance.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>

#include <Eigen/LU>

#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/nondeterminism.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/harness/corner_values.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/ddmin.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/mesh/disjoint_union.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/verification/harness/coincident_vertices.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "harness/sci.h"

namespace crossdiv::verification {

using detail::sci;

namespace {

/// Each vertex's face corners (a counting sort of the corners by vertex) and each corner's face.
struct VertexCorners {
    std::vector<int> first;   ///< vertex v's corners are corners[first[v] .. first[v + 1])
    std::vector<int> corners;
    std::vector<int> face;    ///< of each corner
    explicit VertexCorners(const PolyMesh& mesh)
        : first(static_cast<size_t>(mesh.num_vertices()) + 1, 0), corners(mesh.face_vertices.size()),
          face(mesh.face_vertices.size()) {
        for (int f = 0; f < mesh.num_faces(); ++f)
            for (int k = mesh.face_start[f]; k < mesh.face_start[f + 1]; ++k) face[static_cast<size_t>(k)] = f;
        for (int v : mesh.face_vertices) ++first[static_cast<size_t>(v) + 1];
        for (size_t v = 0; v + 1 < first.size(); ++v) first[v + 1] += first[v];
        std::vector<int> fill(first.begin(), first.end() - 1);
        for (size_t k = 0; k < mesh.face_vertices.size(); ++k)
            corners[static_cast<size_t>(fill[static_cast<size_t>(mesh.face_vertices[k])]++)] = static_cast<int>(k);
    }
};

/// The fans of vertex `v`: its corners joined across each edge (v, w) that exactly two of its
/// corners of one group use (group: what must agree for two corners to be one fan, such as
/// their texture coordinate; `group` maps a corner to it). Returns, for each of v's corners in
/// VertexCorners order, the slot of its fan's first corner.
template <class Group>
std::vector<int> fans_of(const PolyMesh& mesh, const VertexCorners& vc, int v, Group group) {
    const int lo = vc.first[static_cast<size_t>(v)], count = vc.first[static_cast<size_t>(v) + 1] - lo;
    std::vector<int> parent(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) parent[static_cast<size_t>(i)] = i;
    const auto root = [&](int x) {
        while (parent[static_cast<size_t>(x)] != x) x = parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
        return x;
    };
    std::vector<std::array<int, 3>> ends;  // (group, the other end of an edge at v, slot)
    ends.reserve(static_cast<size_t>(2 * count));
    for (int i = 0; i < count; ++i) {
        const int k = vc.corners[static_cast<size_t>(lo + i)];
        const int f = vc.face[static_cast<size_t>(k)];
        const int b = mesh.face_start[f], size = mesh.face_size(f);
        const int g = group(k);
        ends.push_back({g, mesh.face_vertices[static_cast<size_t>(b + (k - b + 1) % size)], i});
        ends.push_back({g, mesh.face_vertices[static_cast<size_t>(b + (k - b + size - 1) % size)], i});
    }
    std::sort(ends.begin(), ends.end());
    for (size_t a = 0, e = 0; a < ends.size(); a = e) {
        while (e < ends.size() && ends[e][0] == ends[a][0] && ends[e][1] == ends[a][1]) ++e;
        if (e - a == 2) parent[static_cast<size_t>(root(ends[a][2]))] = root(ends[a + 1][2]);
    }
    // Each fan named by its first slot, so that the first fan is the one that keeps the element.
    std::vector<int> first_slot(static_cast<size_t>(count), -1), out(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        int& f = first_slot[static_cast<size_t>(root(i))];
        if (f < 0) f = i;
        out[static_cast<size_t>(i)] = f;
    }
    return out;
}

/// `mesh` with each boundary loop of three edges closed by a cap of three triangles around a
/// new vertex (beyond the loop, a mean edge length from its centroid against the loop's
/// faces), and how many loops were; `mesh` itself when it is not a manifold the connectivity
/// takes. A cap of one triangle would make two triangles back to back out of a lone triangle.
PolyMesh with_short_boundary_loops_capped(const PolyMesh& mesh, int& capped) {
    capped = 0;
    PolyMesh out = mesh;
    out.face_varying.clear();  // the Butterflies refine none; new faces would leave the channels short
    PolyConnectivity conn;
    try {
        conn = build_poly_connectivity(mesh);
    } catch (const InputError&) {
        return out;
    }
    // The boundary half-edge leaving each boundary vertex: one per vertex on a manifold.
    std::vector<int> next(static_cast<size_t>(mesh.num_vertices()), -1);
    for (int c = 0; c < conn.num_corners(); ++c)
        if (conn.twin[c] < 0) next[static_cast<size_t>(conn.corner_vertex[c])] = conn.head(c);
    for (int a = 0; a < mesh.num_vertices(); ++a) {
        const int b = next[static_cast<size_t>(a)];
        if (b < 0) continue;
        const int w = next[static_cast<size_t>(b)];
        // Each loop a -> b -> w -> a once, from its smallest vertex.
        if (w < 0 || next[static_cast<size_t>(w)] != a || b < a || w < a) continue;
        const Vec3 &pa = mesh.positions[static_cast<size_t>(a)], &pb = mesh.positions[static_cast<size_t>(b)],
                   &pw = mesh.positions[static_cast<size_t>(w)];
        const Vec3 normal = (pb - pa).cross(pw - pa);
        const double length = ((pb - pa).norm() + (pw - pb).norm() + (pa - pw).norm()) / 3;
        const int apex = out.num_vertices();
        out.positions.push_back((pa + pb + pw) / 3 - (normal.norm() > 0 ? normal.normalized() : Vec3::UnitZ()) * length);
        if (!out.colors.empty()) out.colors.push_back(Vec3::Zero());
        out.add_face({b, a, apex});
        out.add_face({w, b, apex});
        out.add_face({a, w, apex});
        ++capped;
    }
    return out;
}

/// `mesh` with each vertex of `split` given one copy per fan (fans_of, every corner one group):
/// a bowtie vertex comes apart into its fans, and the faces around a non-manifold edge get a
/// copy of each end apiece, so that no vertex or edge of the split mesh is non-manifold where
/// the input's were. The first fan keeps the vertex and its tags.
PolyMesh with_fans_split(const PolyMesh& mesh, const std::vector<int>& split) {
    PolyMesh out = mesh;
    const VertexCorners vc(mesh);
    for (int v : split) {
        const std::vector<int> fan = fans_of(mesh, vc, v, [](int) { return 0; });
        std::vector<int> copy(fan.size(), -1);
        for (size_t i = 0; i < fan.size(); ++i) {
            if (fan[i] == fan[0]) continue;
            int& c = copy[static_cast<size_t>(fan[i])];
            if (c < 0) {
                out.positions.push_back(mesh.positions[static_cast<size_t>(v)]);
                c = out.num_vertices() - 1;
            }
            out.face_vertices[static_cast<size_t>(vc.corners[static_cast<size_t>(vc.first[static_cast<size_t>(v)]) + i])] = c;
        }
    }
    return out;
}

/// `mesh` with each face-varying value that is a bowtie at a vertex (its corners there form
/// several fans: faces of one value alternating with faces of another around the vertex) given
/// one copy per fan; the number of values so split is added to `split`.
PolyMesh with_value_fans_split(const PolyMesh& mesh, int& split) {
    PolyMesh out = mesh;
    const VertexCorners vc(mesh);
    for (size_t ch = 0; ch < mesh.face_varying.size(); ++ch) {
        const FaceVaryingChannel& in = mesh.face_varying[ch];
        FaceVaryingChannel& channel = out.face_varying[ch];
        for (int v = 0; v < mesh.num_vertices(); ++v) {
            const std::vector<int> fan = fans_of(mesh, vc, v, [&](int k) { return in.corner_values[static_cast<size_t>(k)]; });
            const int lo = vc.first[static_cast<size_t>(v)];
            // Each fan holds one value; a value's first fan keeps it, each other fan gets a copy.
            const auto value_at = [&](size_t i) { return in.corner_values[static_cast<size_t>(vc.corners[static_cast<size_t>(lo) + i])]; };
            std::vector<std::pair<int, int>> fans;  // (value, first slot)
            for (size_t i = 0; i < fan.size(); ++i)
                if (fan[i] == static_cast<int>(i)) fans.emplace_back(value_at(i), static_cast<int>(i));
            std::sort(fans.begin(), fans.end());
            std::vector<int> renamed(fan.size(), -1);
            for (size_t j = 1; j < fans.size(); ++j) {
                if (fans[j].first != fans[j - 1].first) continue;
                channel.values.insert(channel.values.end(), in.value(fans[j].first), in.value(fans[j].first) + in.dimension);
                renamed[static_cast<size_t>(fans[j].second)] = channel.num_values() - 1;
                ++split;
            }
            for (size_t i = 0; i < fan.size(); ++i)
                if (const int r = renamed[static_cast<size_t>(fan[i])]; r >= 0)
                    channel.corner_values[static_cast<size_t>(vc.corners[static_cast<size_t>(lo) + i])] = r;
        }
    }
    return out;
}

/// `mesh` cut along the seams of its first face-varying channel: each vertex whose corners hold
/// several values gets one copy per value (the first keeps the vertex and its tags), so that a
/// seam becomes a boundary on each side; the number of copies made is added to `split`.
PolyMesh with_seams_cut(const PolyMesh& mesh, int& split) {
    PolyMesh out = mesh;
    if (mesh.face_varying.empty()) return out;
    const std::vector<int>& values = mesh.face_varying.front().corner_values;
    std::vector<std::pair<std::pair<int, int>, int>> keyed(values.size());  // ((vertex, value), corner)
    for (size_t c = 0; c < values.size(); ++c) keyed[c] = {{mesh.face_vertices[c], values[c]}, static_cast<int>(c)};
    std::sort(keyed.begin(), keyed.end());
    int copy = -1;
    for (size_t k = 0; k < keyed.size(); ++k) {
        const auto [v, value] = keyed[k].first;
        if (k > 0 && keyed[k - 1].first.first == v && keyed[k - 1].first.second != value) {
            out.positions.push_back(mesh.positions[static_cast<size_t>(v)]);
            if (!out.colors.empty()) out.colors.push_back(mesh.colors[static_cast<size_t>(v)]);
            copy = out.num_vertices() - 1;
            ++split;
        } else if (k == 0 || keyed[k - 1].first.first != v) {
            copy = v;
        }
        out.face_vertices[static_cast<size_t>(keyed[k].second)] = copy;
    }
    return out;
}

/// The refinement of the input, transformed as the input was: what the refinement of the
/// transformed input must equal.
PolyMesh mapped_as_the_input(const PolyMesh& refined, const TransformedInput& transformed) {
    PolyMesh expected = refined;
    for (Vec3& p : expected.positions) p = transformed.linear * p + transformed.offset;
    if (transformed.reversed)
        for (int f = 0; f < expected.num_faces(); ++f) {
            std::reverse(expected.face_vertices.begin() + expected.face_start[f] + 1,
                         expected.face_vertices.begin() + expected.face_start[f + 1]);
            for (FaceVaryingChannel& ch : expected.face_varying)
                std::reverse(ch.corner_values.begin() + expected.face_start[f] + 1,
                             ch.corner_values.begin() + expected.face_start[f + 1]);
        }
    return expected;
}


/// The first face with fewer than 3 distinct corners, in the words of the mesh checker.
std::optional<std::string> first_degenerate_face(const PolyMesh& mesh) {
    for (const MeshIssue& issue : check_mesh(mesh))
        if (issue.kind == MeshIssueKind::RepeatedVertex || issue.kind == MeshIssueKind::TooFewCorners) return issue.message;
    return std::nullopt;
}

/// Edges that a mesh written as faces cannot state, in the words of the mesh checker: edges
/// that more than two faces share, and faces naming a vertex twice. The refinement may hold
/// several edges there (the children of back-to-back faces, each face's own interior edges);
/// written out and read back, they are one. None when the mesh states its edges
/// (PolyMesh::derived).
std::vector<std::string> unstated_edges(const PolyMesh& mesh) {
    std::vector<std::string> out;
    if (!mesh.derived.empty()) return out;
    for (const MeshIssue& issue : check_mesh(mesh))
        if (issue.kind == MeshIssueKind::NonManifoldEdge || issue.kind == MeshIssueKind::RepeatedVertex ||
            issue.kind == MeshIssueKind::TooFewCorners)
            out.push_back(issue.message);
    return out;
}

/// The second run of a check: the implementation on the input written otherwise, or run
/// otherwise on the input (runs_otherwise); with `not_compared` saying why there is none.
struct SecondRun {
    TransformedInput transformed;
    IsolatedTrace run;
    std::string not_compared;
};

/// A failed run of one of several, its message saying which.
IsolatedTrace failed_part(IsolatedTrace run, const std::string& which) {
    run.outcome.message = which + ": " + run.outcome.message;
    run.trace.reset();
    return run;
}

SecondRun run_second(const Implementation& impl, const PolyMesh& input, const RefineRequest& request, InputTransformation t,
                     std::uint64_t seed, double timeout_seconds, bool isolate) {
    SecondRun out;
    out.transformed = transform_input(input, t, seed);
    // Hierarchical edits name faces, corners and positions of the input as written; no
    // transformation here carries them, so only the same input run again is compared.
    if (!input.creases.edits.empty() && t != InputTransformation::Repeat) {
        out.not_compared = "the input has " + std::to_string(input.creases.edits.size()) +
                           " hierarchical edit(s), whose paths and values name the input as written: the transformed input "
                           "would carry them to other faces";
        return out;
    }
    if (t == InputTransformation::SplitComponents) {
        const std::vector<PolyMesh> parts = connected_components(input);
        if (parts.size() < 2) {
            out.not_compared = "one connected component: the whole is its only part";
            return out;
        }
        std::vector<PolyMesh> refined;
        refined.reserve(parts.size());
        for (size_t i = 0; i < parts.size(); ++i) {
            IsolatedTrace r = refine_isolated(impl, parts[i], request, timeout_seconds, isolate);
            out.run.outcome.seconds += r.outcome.seconds;
            if (r.outcome.status != RunStatus::Ok || !r.trace) {
                out.run = failed_part(std::move(r), "component " + std::to_string(i + 1) + " of " + std::to_string(parts.size()));
                return out;
            }
            refined.push_back(std::move(r.trace->back()));
        }
        out.run.trace = adapters::LevelTrace{input, disjoint_union(refined)};
        return out;
    }
    if (t == InputTransformation::LevelByLevel) {
        if (request.levels < 2) {
            out.not_compared = "one level: nothing to run level by level";
            return out;
        }
        if (!input.creases.empty()) {
            out.not_compared = "the input has sharpness, corner or hole tags (" + input.creases.describe() +
                               "), which the levels an implementation returns do not carry";
            return out;
        }
        if (request.scheme == Scheme::Sqrt3 && request.rule.sqrt3.parity == Sqrt3Parity::CountFromInput &&
            mesh_topology(input).boundary_edges > 0) {
            out.not_compared = "sqrt3 counted from the input trisects the boundary every second level: one level run "
                               "twice is not two levels (restart-each-level is)";
            return out;
        }
        if (const std::optional<std::string> face = first_degenerate_face(input)) {
            out.not_compared = "the input has a degenerate face (" + *face +
                               "): the halves of its edge from a vertex to itself are separate edges of the refinement, "
                               "which a face list cannot state";
            return out;
        }
        RefineRequest one = request;
        one.levels = 1;
        adapters::LevelTrace levels{input};
        const size_t unstated_in_input = unstated_edges(input).size();
        for (int level = 1; level <= request.levels; ++level) {
            // A level whose refinement made edges a face list cannot state (more than the
            // children of the input's own, two per edge and level) is read back as another mesh.
            if (const std::vector<std::string> unstated = level > 1 ? unstated_edges(levels.back()) : std::vector<std::string>{};
                unstated.size() > (unstated_in_input << (level - 1))) {
                out.not_compared = "level " + std::to_string(level - 1) + "'s result has " + std::to_string(unstated.size()) +
                                   " edges that more than two faces share, or faces naming a vertex twice (the input " +
                                   std::to_string(unstated_in_input) + "; first: " + unstated[0] +
                                   "): written as faces, the next run cannot tell the refinement's separate edges there apart";
                return out;
            }
            IsolatedTrace r = refine_isolated(impl, levels.back(), one, timeout_seconds, isolate);
            out.run.outcome.seconds += r.outcome.seconds;
            if (r.outcome.status != RunStatus::Ok || !r.trace) {
                out.run = failed_part(std::move(r), "level " + std::to_string(level) + " run on level " +
                                                        std::to_string(level - 1) + "'s result");
                return out;
            }
            levels.push_back(std::move(r.trace->back()));
        }
        out.run.trace = std::move(levels);
        return out;
    }
    out.run = refine_isolated(impl, out.transformed.mesh, request, timeout_seconds, isolate,
                              t == InputTransformation::Repeat ? kSecondHeapFill : kHeapFill);
    return out;
}

/// What two float results may part by, relative to `size`: `float_ulps` ulps of the largest
/// magnitude either holds, for each of the two (positions over the diagonal, texture
/// coordinates over the UV box).
double float_tier_bar(float largest, double float_ulps, double size) {
    const double ulp = static_cast<double>(std::nextafter(largest, INFINITY)) - largest;
    return 2 * float_ulps * ulp / size;
}

}  // namespace

const char* to_string(InvarianceResult r) {
    switch (r) {
        case InvarianceResult::Invariant: return "invariant";
        case InvarianceResult::NotInvariant: return "not-invariant";
        case InvarianceResult::Nondeterministic: return "nondeterministic";
        case InvarianceResult::NotCompared: return "not-compared";
    }
    return "?";
}

nlohmann::json to_json(const InvarianceCheck& c) {
    return {{"transformation", to_string(c.transformation)},
            {"result", to_string(c.result)},
            {"exact", c.exact},
            {"bit_identical", c.bit_identical},
            {"faces_equal", c.faces_equal},
            {"point_sets", c.point_sets},
            {"uv_only", c.uv_only},
            {"max_rel", finite_or_null(c.max_rel)},
            {"uv_max_rel", finite_or_null(c.uv_max_rel)},
            {"worst_vertex", c.worst_vertex},
            {"worst_valence", c.worst_valence},
            {"worst_boundary", c.worst_boundary},
            {"explanation", c.explanation}};
}

bool InvarianceReport::invariant() const {
    return std::none_of(checks.begin(), checks.end(), [](const InvarianceCheck& c) { return c.finding(); });
}

InvarianceCheck measure_invariance(const PolyMesh& refined, const PolyMesh& refined_transformed,
                                   const TransformedInput& transformed, double tolerance, double float_ulps) {
    InvarianceCheck out;
    out.exact = transformed.exact;
    const PolyMesh expected = mapped_as_the_input(refined, transformed);
    // Far from the origin two summation orders of the same stencils (or a translated or rotated
    // input's own rounding) part by a few ulps of the coordinates, more than a relative
    // tolerance of a small diagonal: the same allowance as the comparisons' (kRoundingUlps).
    const double diagonal = std::max(bounding_box_diagonal(expected.positions), 1e-300);
    const double rounding = tolerances::kRoundingUlps *
                            std::max(ulp_of_largest_coordinate(expected), ulp_of_largest_coordinate(refined_transformed)) / diagonal;
    double bar = std::max(tolerance, rounding);
    if (float_ulps > 0) {
        float largest = 0;
        for (const PolyMesh* m : {static_cast<const PolyMesh*>(&expected), &refined_transformed})
            for (const Vec3& p : m->positions) largest = std::max(largest, static_cast<float>(p.cwiseAbs().maxCoeff()));
        bar = std::max(bar, float_tier_bar(largest, float_ulps, diagonal));
    }
    // The same faces on the same vertex numbers (a moved, scaled or rotated input keeps its
    // order, and so does a deterministic implementation): vertex i is first paired with vertex i,
    // since positions alone cannot pair float results whose vertices lie closer than their
    // rounding (slivers). Where that pairing differs, the faces may have a symmetry the
    // implementation numbered otherwise (a triangle from rotated corners): then by position.
    const bool same_numbering = expected.num_vertices() == refined_transformed.num_vertices() &&
                                expected.face_start == refined_transformed.face_start &&
                                expected.face_vertices == refined_transformed.face_vertices;
    Correspondence m;
    std::optional<MeshComparison> c;
    if (same_numbering) {
        m.method = MatchMethod::Order;
        m.ref_to_ours.resize(static_cast<size_t>(expected.num_vertices()));
        std::iota(m.ref_to_ours.begin(), m.ref_to_ours.end(), 0);
        c = compare_meshes(expected, refined_transformed, m.ref_to_ours);
        if (!c->topology_equal() || c->max_rel > bar) {
            Correspondence by_position = match_nearest_and_faces(expected, refined_transformed);
            if (by_position.method != MatchMethod::None) {
                m = std::move(by_position);
                c = compare_meshes(expected, refined_transformed, m.ref_to_ours);
            }
        }
    } else {
        m = match_nearest_and_faces(expected, refined_transformed);
        if (m.method != MatchMethod::None) c = compare_meshes(expected, refined_transformed, m.ref_to_ours);
    }
    // Vertices at one position (a face naming a vertex twice, two faces on the same corners, or
    // within the bar of each other)
    // cannot be told apart by position, so neither can the faces that use them: such a pair is
    // compared as point sets, and its faces are not compared.
    // Float results put two vertices at one place a rounding apart (the face points of two
    // polygons back to back): within the bar is at one position.
    if ((!c || !c->topology_equal()) && has_vertices_within(refined.positions, bar * diagonal)) {
        out.max_rel = hausdorff_vertex_sets(expected.positions, refined_transformed.positions) / diagonal;
        out.point_sets = true;
        const bool same_points = out.max_rel <= bar && expected.num_vertices() == refined_transformed.num_vertices();
        out.result = same_points ? InvarianceResult::NotCompared : InvarianceResult::NotInvariant;
        out.explanation = std::string(same_points ? "the same points" : "the point sets part") + " (Hausdorff " +
                          sci(out.max_rel) + " of the diagonal, " + std::to_string(expected.num_vertices()) + " and " +
                          std::to_string(refined_transformed.num_vertices()) +
                          " vertices); the refinement has vertices at one position, which positions cannot tell apart, "
                          "so its faces were not compared";
        return out;
    }
    if (!c) {
        // Too far apart to match: the size of the difference is the distance between the point sets.
        out.result = InvarianceResult::NotInvariant;
        out.max_rel = hausdorff_vertex_sets(expected.positions, refined_transformed.positions) / diagonal;
        out.explanation = "the two refinements do not match vertex for vertex (" + m.note + "); their vertices are " +
                          sci(out.max_rel) + " of the diagonal apart (Hausdorff)";
        return out;
    }
    out.faces_equal = c->topology_equal();
    out.max_rel = c->max_rel;
    out.bit_identical = out.faces_equal && c->max_abs == 0.0;
    if (!c->worst.empty()) {
        out.worst_vertex = c->worst[0].ours_index;
        out.worst_valence = c->worst[0].valence;
        out.worst_boundary = c->worst[0].boundary;
    }
    const std::string where = out.worst_vertex < 0 ? std::string()
                                                   : " (worst: vertex " + std::to_string(out.worst_vertex) + ", valence " +
                                                         std::to_string(out.worst_valence) +
                                                         (out.worst_boundary ? ", boundary)" : ", interior)");
    if (!out.faces_equal) {
        out.result = InvarianceResult::NotInvariant;
        out.explanation = "the faces differ: " + std::to_string(c->faces_only_in_ours) + " only in the refinement of the input, " +
                          std::to_string(c->faces_only_in_ref) + " only in that of the transformed input";
    } else if (out.bit_identical) {
        out.result = InvarianceResult::Invariant;
        out.explanation = "bit for bit";
    } else if (out.exact) {
        // Floating point makes this transformation exact: any difference is the implementation's.
        out.result = InvarianceResult::NotInvariant;
        out.explanation = "not bit for bit where the transformation is exact in floating point: " + sci(out.max_rel) +
                          " of the diagonal" + where;
    } else if (out.max_rel <= bar) {
        out.result = InvarianceResult::Invariant;
        out.explanation = "within " + sci(out.max_rel) + " of the diagonal (<= " + sci(bar) +
                          (bar > tolerance ? ", the rounding of coordinates far from the origin" : "") +
                          "), not bit for bit (strict tier: not invariant)";
    } else {
        out.result = InvarianceResult::NotInvariant;
        out.explanation = sci(out.max_rel) + " of the diagonal > " + sci(bar) + where;
    }
    // Texture coordinates, corner by corner through the same vertices (no map moves them).
    if (!expected.face_varying.empty() && !refined_transformed.face_varying.empty()) {
        const CornerValueComparison uv = compare_corner_values(expected, refined_transformed, m.ref_to_ours);
        out.uv_max_rel = uv.compared() ? uv.max_rel : INFINITY;
        // An implementation that keeps its values in float (Hbr's face-varying data) rounds them
        // by the same float tier as positions, of its largest value over the UV box.
        double uv_bar = tolerance;
        if (float_ulps > 0 && uv.compared() && uv.uv_box > 0) {
            float largest = 0;
            for (const PolyMesh* mesh : {&expected, &refined_transformed})
                for (double x : mesh->face_varying.front().values) largest = std::max(largest, std::abs(static_cast<float>(x)));
            uv_bar = std::max(uv_bar, float_tier_bar(largest, float_ulps, uv.uv_box));
        }
        const bool uv_ok = uv.compared() && (out.exact ? uv.max_abs == 0.0 : uv.max_rel <= uv_bar);
        if (!uv_ok) {
            out.uv_only = out.result == InvarianceResult::Invariant;
            out.result = InvarianceResult::NotInvariant;
            out.explanation += "; texture coordinates " +
                               (uv.compared() ? sci(uv.max_rel) + " of the UV box apart" + (out.exact ? " (exact: bit for bit expected)" : "")
                                              : "not compared: " + uv.not_compared);
        } else {
            out.explanation += uv.max_abs == 0.0 ? "; texture coordinates bit for bit"
                                                 : "; texture coordinates within " + sci(uv.max_rel) + " of the UV box" +
                                                       (uv_bar > tolerance ? " (<= " + sci(uv_bar) + ", the float tier)" : "");
        }
    }
    return out;
}

InvarianceReport check_invariance(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                  const std::vector<InputTransformation>& transformations, std::uint64_t seed,
                                  double tolerance, double timeout_seconds, bool isolate) {
    InvarianceReport out;
    out.implementation = impl.name();
    const IsolatedTrace first = refine_isolated(impl, input, request, timeout_seconds, isolate);
    out.outcome = first.outcome;
    const double float_ulps = impl.capabilities().precision == Precision::Float
                                  ? tolerances::kFloatAgreementUlps + 0.5 * (longest_float_sum(input) + 2) * request.levels
                                  : 0.0;
    for (InputTransformation t : transformations) {
        InvarianceCheck check;
        check.transformation = t;
        if (first.outcome.status != RunStatus::Ok || !first.trace) {
            check.explanation = "the run on the input: " + first.outcome.summary();
            out.checks.push_back(std::move(check));
            continue;
        }
        // Run again; for repeat its heap is filled otherwise (isolate.h): a result that reads
        // memory it never wrote changes with it.
        const SecondRun again = run_second(impl, input, request, t, seed, timeout_seconds, isolate);
        const IsolatedTrace& second = again.run;
        if (!again.not_compared.empty()) {
            check.explanation = again.not_compared;
            out.checks.push_back(std::move(check));
            continue;
        }
        if (t == InputTransformation::Repeat) {
            // Every level, bit for bit, as the comparisons' determinism reruns read it.
            check.exact = true;
            if (const std::optional<std::string> diff = first_difference(first, second)) {
                check.result = InvarianceResult::Nondeterministic;
                check.explanation = "the same input run again (its heap filled otherwise): " + *diff;
            } else {
                check.result = InvarianceResult::Invariant;
                check.faces_equal = check.bit_identical = true;
                check.max_rel = 0;
                if (!first.trace->back().face_varying.empty()) check.uv_max_rel = 0;
                check.explanation = "identical bytes";
            }
            out.checks.push_back(std::move(check));
            continue;
        }
        if (second.outcome.status != RunStatus::Ok || !second.trace) {
            // Refusing the input written otherwise, or crashing on it, is a dependence on how
            // it is written too.
            check.result = InvarianceResult::NotInvariant;
            check.explanation = std::string(runs_otherwise(t) ? "the run on a part: " : "the run on the transformed input: ") +
                                second.outcome.summary();
            out.checks.push_back(std::move(check));
            continue;
        }
        check = measure_invariance(first.trace->back(), second.trace->back(), again.transformed, tolerance, float_ulps);
        check.transformation = t;
        out.checks.push_back(std::move(check));
    }
    return out;
}

std::vector<InvarianceCause> explain_findings(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                              const std::vector<InvarianceCheck>& findings, std::uint64_t seed,
                                              double tolerance, double timeout_seconds, bool isolate) {
    std::vector<InvarianceCause> causes(findings.size());
    std::vector<size_t> pending(findings.size());  // the findings no removal has explained yet
    for (size_t i = 0; i < pending.size(); ++i) pending[i] = i;
    const auto explain_rest = [&](DivergenceClass cls, const std::string& why) {
        for (size_t i : pending) causes[i] = {cls, why};
        pending.clear();
        return causes;
    };
    // Each removal is checked once for every finding still pending: one run of the mesh without
    // it, and one per transformation. `why(as_points)` words the cause; a finding made on point
    // sets (vertices at one position: its faces not compared) is gone when the removal leaves the
    // same points, compared as it was.
    const auto explained_on = [&](const PolyMesh& mesh, DivergenceClass cls, const auto& why) {
        std::vector<InputTransformation> ts;
        for (size_t i : pending) ts.push_back(findings[i].transformation);
        const InvarianceReport r = check_invariance(impl, mesh, request, ts, seed, tolerance, timeout_seconds, isolate);
        if (r.checks.size() != pending.size()) return;
        std::vector<size_t> still;
        for (size_t k = 0; k < pending.size(); ++k) {
            const InvarianceCheck& c = r.checks[k];
            const bool as_points = findings[pending[k]].point_sets && c.point_sets && c.result == InvarianceResult::NotCompared;
            if (c.result == InvarianceResult::Invariant || as_points)
                causes[pending[k]] = {cls, why(as_points)};
            else
                still.push_back(pending[k]);
        }
        pending = std::move(still);
    };
    const auto once = [](bool as_points, const std::string& removals) {
        return (as_points ? "the same points (its faces not compared: vertices at one position) once " : "invariant once ") +
               removals;
    };
    std::vector<int> all_faces(static_cast<size_t>(input.num_faces()));
    for (size_t f = 0; f < all_faces.size(); ++f) all_faces[f] = static_cast<int>(f);
    const PolyMesh used = submesh(input, all_faces);  // drops the vertices no face uses
    const int isolated = input.num_vertices() - used.num_vertices();
    // Points and no face (a point cloud among real models): every vertex is one no face uses,
    // so that is all that can differ, and removing them leaves nothing to run.
    if (isolated > 0 && used.num_faces() == 0)
        return explain_rest(DivergenceClass::IsolatedVertexHandling,
                            "the input has no faces: all " + std::to_string(isolated) + " of its vertices are ones no face uses");
    // The removals are made one after another, each kept for the next: a real model may have
    // vertices no face uses and a bowtie, and an implementation that mishandles both (OpenMesh's
    // Catmull-Clark moves each by other weights than the affine ones) is invariant only once both
    // are gone. The class is the removal that makes it invariant; the why names those before it.
    PolyMesh cleaned = input;
    std::vector<int> input_vertex;  // cleaned's vertex v is the input's input_vertex[v], once vertices are removed
    std::string removed;            // the removals kept so far, as clauses ending in ", "
    if (isolated > 0) {
        const std::string clause = "its " + std::to_string(isolated) + " vertices no face uses are removed";
        explained_on(used, DivergenceClass::IsolatedVertexHandling, [&](bool as_points) { return once(as_points, clause); });
        if (pending.empty()) return causes;
        std::vector<char> in_use(static_cast<size_t>(input.num_vertices()), 0);
        for (int v : input.face_vertices) in_use[static_cast<size_t>(v)] = 1;
        for (int v = 0; v < input.num_vertices(); ++v)
            if (in_use[static_cast<size_t>(v)]) input_vertex.push_back(v);
        cleaned = used;
        removed = clause + ", ";
    }
    const auto input_index = [&](int v) { return input_vertex.empty() ? v : input_vertex[static_cast<size_t>(v)]; };
    std::vector<int> nonmanifold;
    try {
        nonmanifold = nonmanifold_vertices(cleaned);
    } catch (const InputError&) {
        // A face the steps refuse (a repeated corner): the degenerate test below names it.
    }
    if (!nonmanifold.empty()) {
        PolyMesh split = with_fans_split(cleaned, nonmanifold);
        const std::string clause = "its " + std::to_string(nonmanifold.size()) +
                                   " non-manifold vertices are split into their fans (vertex " +
                                   std::to_string(input_index(nonmanifold[0])) + (nonmanifold.size() > 1 ? ", ...)" : ")");
        explained_on(split, DivergenceClass::NonManifoldHandling, [&](bool as_points) { return once(as_points, removed + clause); });
        if (pending.empty()) return causes;
        cleaned = std::move(split);
        removed += clause + ", ";
    }
    // The Butterflies' four-point rule on a boundary loop of three edges, whose two outer
    // points are one vertex (VTK reads another point there, which does not move with the mesh).
    if (request.scheme == Scheme::Butterfly || request.scheme == Scheme::ModifiedButterfly) {
        int capped = 0;
        const PolyMesh closed = with_short_boundary_loops_capped(cleaned, capped);
        if (capped > 0)
            explained_on(closed, DivergenceClass::ShortBoundaryLoop, [&](bool as_points) {
                return once(as_points, removed + "its " + std::to_string(capped) +
                                           " boundary loop(s) of three edges are capped: there the four-point rule's two "
                                           "outer points are one vertex");
            });
        if (pending.empty()) return causes;
    }
    if (!cleaned.face_varying.empty()) {
        int split = 0;
        const PolyMesh apart = with_value_fans_split(cleaned, split);
        if (split > 0)
            explained_on(apart, DivergenceClass::FaceOrderDependence, [&](bool as_points) {
                return "its texture coordinates depend on the order of the faces at a UV bowtie (a value whose faces "
                       "alternate with another's around a vertex): " +
                       once(as_points, removed + "its " + std::to_string(split) + " bowtie values are split, one per fan");
            });
        if (pending.empty()) return causes;
    }
    // Findings in the texture coordinates alone under an order of faces, corners or vertices,
    // on a mesh whose UV layout has seams: invariant once the mesh is cut along them, the values
    // along a seam were read off that order (Hbr's, on two triangles that meet at a seam).
    if (!cleaned.face_varying.empty()) {
        int split = 0;
        const PolyMesh cut = with_seams_cut(cleaned, split);
        const auto rest = std::stable_partition(pending.begin(), pending.end(), [&](size_t i) {
            return findings[i].uv_only && reorders(findings[i].transformation);
        });
        std::vector<size_t> others(rest, pending.end());
        pending.erase(rest, pending.end());
        if (split > 0 && !pending.empty())
            explained_on(cut, DivergenceClass::FaceOrderDependence, [&](bool as_points) {
                return "its texture coordinates depend on the order of the faces along a UV seam: " +
                       once(as_points, removed + "it is cut along its seams (" + std::to_string(split) +
                                           " vertex copies, one per value)");
            });
        pending.insert(pending.end(), others.begin(), others.end());
        if (pending.empty()) return causes;
    }
    // What no removal tests: the same for every finding left.
    const SchemeSupport* support = impl.support(request.scheme);
    if (const int valence = max_valence(input); support && support->max_valence > 0 && valence > support->max_valence)
        return explain_rest(DivergenceClass::ValenceLimit, "a vertex of valence " + std::to_string(valence) +
                                                               " lies past its weight table, which ends at valence " +
                                                               std::to_string(support->max_valence) + " (" +
                                                               support->valence_table + ")");
    if (const std::optional<std::string> face = first_degenerate_face(input))
        return explain_rest(DivergenceClass::DegenerateFaceHandling, "the input has a degenerate face: " + *face);
    const IsolatedTrace run = refine_isolated(impl, input, request, timeout_seconds, isolate);
    if (run.trace)
        for (size_t level = 1; level < run.trace->size(); ++level)
            if (const std::optional<std::string> face = first_degenerate_face((*run.trace)[level]))
                return explain_rest(DivergenceClass::DegenerateFaceHandling,
                                    "its refinement has a degenerate face at level " + std::to_string(level) + ": " + *face);
    return explain_rest(DivergenceClass::Unexplained,
                        "not explained by isolated vertices, non-manifold vertices, a weight table or a degenerate face");
}

InvarianceCause explain_not_invariant(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                      const InvarianceCheck& finding, std::uint64_t seed, double tolerance,
                                      double timeout_seconds, bool isolate) {
    return explain_findings(impl, input, request, {finding}, seed, tolerance, timeout_seconds, isolate).front();
}

std::vector<std::optional<InvarianceCause>> causes_of(const Implementation& impl, const PolyMesh& input,
                                                      const RefineRequest& request, const InvarianceReport& report,
                                                      std::uint64_t seed, double tolerance, double timeout_seconds,
                                                      bool isolate) {
    std::vector<InvarianceCheck> findings;
    for (const InvarianceCheck& c : report.checks)
        if (c.finding()) findings.push_back(c);
    std::vector<std::optional<InvarianceCause>> out(report.checks.size());
    if (findings.empty()) return out;
    std::vector<InvarianceCause> causes = explain_findings(impl, input, request, findings, seed, tolerance, timeout_seconds, isolate);
    for (size_t i = 0, k = 0; i < report.checks.size(); ++i)
        if (report.checks[i].finding()) out[i] = std::move(causes[k++]);
    return out;
}

std::optional<DivergenceView> invariance_view(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                            InputTransformation t, std::uint64_t seed, double timeout_seconds, bool isolate) {
    const IsolatedTrace first = refine_isolated(impl, input, request, timeout_seconds, isolate);
    const SecondRun again = run_second(impl, input, request, t, seed, timeout_seconds, isolate);
    const TransformedInput& transformed = again.transformed;
    const IsolatedTrace& second = again.run;
    if (!first.trace || !second.trace || first.trace->size() < 2) return std::nullopt;
    const PolyMesh& theirs = second.trace->back();
    const Correspondence m = match_nearest_and_faces(mapped_as_the_input(first.trace->back(), transformed), theirs);
    if (m.method == MatchMethod::None) return std::nullopt;
    DivergenceView view;
    view.levels = *first.trace;
    view.births.resize(view.levels.size() - 1);  // no provenance: the levels are the implementation's own
    // The other run's last level, mapped back through the inverse of the transformation into
    // the numbering of the first; earlier levels have no vertex map (empty), unmatched vertices NaN.
    const Eigen::Matrix3d inverse = transformed.linear.inverse();
    std::vector<Vec3> back(static_cast<size_t>(view.levels.back().num_vertices()), Vec3::Constant(NAN));
    for (size_t i = 0; i < m.ref_to_ours.size(); ++i)
        if (const int v = m.ref_to_ours[i]; v >= 0 && v < static_cast<int>(back.size()))
            back[static_cast<size_t>(v)] = inverse * (theirs.positions[i] - transformed.offset);
    std::vector<std::vector<Vec3>> levels(view.levels.size());
    levels.back() = std::move(back);
    view.references[invariance_view_label(impl.name(), t)] = std::move(levels);
    return view;
}

std::string invariance_view_label(const std::string& implementation, InputTransformation t) {
    return implementation + " under " + to_string(t);
}

InvarianceShrink shrink_not_invariant(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                      InputTransformation t, std::uint64_t seed, double tolerance, double timeout_seconds,
                                      bool isolate, const ShrinkLimits& limits) {
    const auto t0 = std::chrono::steady_clock::now();
    InvarianceShrink out;
    const auto shows = [&](const PolyMesh& mesh, InvarianceCheck& check) {
        ++out.tests;
        const InvarianceReport r = check_invariance(impl, mesh, request, {t}, seed, tolerance, timeout_seconds, isolate);
        const bool bad = r.checks.size() == 1 && r.checks[0].finding();
        if (bad) check = r.checks[0];
        return bad;
    };
    if (!shows(input, out.check))
        throw InputError(impl.name() + " is " + std::string(to_string(out.check.result)) + " under " + to_string(t) +
                         " on this input: nothing to shrink");
    // Past the time limit every further candidate counts as not showing it: ddmin then only
    // splits what it has until its chunks are single faces, running nothing.
    const auto out_of_time = [&] {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > limits.seconds) out.cut_short = true;
        return out.cut_short;
    };
    std::vector<int> all(static_cast<size_t>(input.num_faces()));
    std::iota(all.begin(), all.end(), 0);
    const std::vector<int> faces = ddmin(std::move(all), [&](const std::vector<int>& keep) {
        InvarianceCheck check;
        if (out_of_time() || !shows(submesh(input, keep), check)) return false;
        out.check = check;  // the last candidate kept is the minimal input
        return true;
    }, DdminSteps::SubsetsThenComplements);
    // Nothing removed: the input itself (submesh drops vertices no face uses, which the
    // symptom may need: an isolated vertex).
    out.minimal = faces.size() == static_cast<size_t>(input.num_faces()) ? input : submesh(input, faces);
    return out;
}

}  // namespace crossdiv::verification
