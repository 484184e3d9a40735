#include "crossdiv/verification/comparisons/invariance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/harness/corner_values.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "harness/sci.h"

namespace crossdiv::verification {

using detail::sci;

namespace {

/// Whether two vertices of `mesh` have the same position.
bool has_coincident_vertices(const PolyMesh& mesh) {
    std::vector<std::array<double, 3>> p;
    p.reserve(mesh.positions.size());
    for (const Vec3& x : mesh.positions) p.push_back({x.x(), x.y(), x.z()});
    std::sort(p.begin(), p.end());
    return std::adjacent_find(p.begin(), p.end()) != p.end();
}

/// The same input run twice: the same bytes, vertex for vertex and face for face, or
/// nondeterministic with the largest move of a vertex (by index).
InvarianceCheck compare_repeat(const PolyMesh& a, const PolyMesh& b) {
    InvarianceCheck out;
    out.transformation = InputTransformation::Repeat;
    out.exact = true;
    out.faces_equal = a.face_start == b.face_start && a.face_vertices == b.face_vertices;
    const bool same_count = a.positions.size() == b.positions.size();
    out.max_rel = same_count ? max_relative_distance(a, b, identity_map(a.positions.size())) : INFINITY;
    out.bit_identical = out.faces_equal && same_count && a.positions == b.positions;
    if (!a.face_varying.empty() || !b.face_varying.empty()) {
        // Texture coordinates: the same values at the same indices.
        const bool same_uv = a.face_varying.size() == b.face_varying.size() && !a.face_varying.empty() &&
                             a.face_varying[0].corner_values == b.face_varying[0].corner_values &&
                             a.face_varying[0].values == b.face_varying[0].values;
        out.uv_max_rel = same_uv ? 0.0 : INFINITY;
        out.bit_identical = out.bit_identical && same_uv;
    }
    if (out.bit_identical) {
        out.result = InvarianceResult::Invariant;
        out.explanation = "identical bytes";
        return out;
    }
    out.result = InvarianceResult::Nondeterministic;
    // The first vertex whose bytes differ (a NaN differs from itself: compared by bits).
    for (size_t v = 0; same_count && v < a.positions.size() && out.worst_vertex < 0; ++v)
        if (std::memcmp(a.positions[v].data(), b.positions[v].data(), sizeof(double) * 3) != 0) out.worst_vertex = static_cast<int>(v);
    const auto text = [](const Vec3& p) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", p.x(), p.y(), p.z());
        return std::string(buf);
    };
    out.explanation = "the same input run again (its heap filled otherwise) gives " +
                      (!same_count ? std::to_string(b.positions.size()) + " vertices, not " + std::to_string(a.positions.size())
                       : out.worst_vertex < 0
                           ? std::string(out.faces_equal ? "other texture coordinates" : "other faces")
                           : "vertex " + std::to_string(out.worst_vertex) + " at " +
                                 text(b.positions[static_cast<size_t>(out.worst_vertex)]) + ", not " +
                                 text(a.positions[static_cast<size_t>(out.worst_vertex)]) + " (largest move " +
                                 sci(out.max_rel) + " of the diagonal)");
    return out;
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

bool InvarianceReport::invariant() const {
    return std::none_of(checks.begin(), checks.end(), [](const InvarianceCheck& c) {
        return c.result == InvarianceResult::NotInvariant || c.result == InvarianceResult::Nondeterministic;
    });
}

InvarianceCheck measure_invariance(const PolyMesh& refined, const PolyMesh& refined_transformed,
                                   const TransformedInput& transformed, double tolerance) {
    InvarianceCheck out;
    out.exact = transformed.exact;
    // The refinement of the input, transformed as the input was.
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
    // Far from the origin two summation orders of the same stencils (or a translated or rotated
    // input's own rounding) part by a few ulps of the coordinates, more than a relative
    // tolerance of a small diagonal: the same allowance as the comparisons' (kRoundingUlps).
    const double diagonal = std::max(bounding_box_diagonal(expected.positions), 1e-300);
    const double rounding = tolerances::kRoundingUlps *
                            std::max(ulp_of_largest_coordinate(expected), ulp_of_largest_coordinate(refined_transformed)) / diagonal;
    const double bar = std::max(tolerance, rounding);
    const Correspondence m = match_nearest_and_faces(expected, refined_transformed);
    std::optional<MeshComparison> c;
    if (m.method != MatchMethod::None) c = compare_meshes(expected, refined_transformed, m.ref_to_ours);
    // Vertices at one position (a face naming a vertex twice, two faces on the same corners)
    // cannot be told apart by position, so neither can the faces that use them: such a pair is
    // compared as point sets, and its faces are not compared.
    if ((!c || !c->topology_equal()) && has_coincident_vertices(refined)) {
        out.max_rel = hausdorff_vertex_sets(expected.positions, refined_transformed.positions) / diagonal;
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
        out.result = InvarianceResult::NotInvariant;
        out.explanation = "the two refinements do not match vertex for vertex (" + m.note + ")";
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
        const bool uv_ok = uv.compared() && (out.exact ? uv.max_abs == 0.0 : uv.max_rel <= tolerance);
        if (!uv_ok) {
            out.result = InvarianceResult::NotInvariant;
            out.explanation += "; texture coordinates " +
                               (uv.compared() ? sci(uv.max_rel) + " of the UV box apart" + (out.exact ? " (exact: bit for bit expected)" : "")
                                              : "not compared: " + uv.not_compared);
        } else {
            out.explanation += uv.max_abs == 0.0 ? "; texture coordinates bit for bit"
                                                 : "; texture coordinates within " + sci(uv.max_rel) + " of the UV box";
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
    for (InputTransformation t : transformations) {
        InvarianceCheck check;
        check.transformation = t;
        if (first.outcome.status != RunStatus::Ok || !first.trace) {
            check.explanation = "the run on the input: " + first.outcome.summary();
            out.checks.push_back(std::move(check));
            continue;
        }
        const TransformedInput transformed = transform_input(input, t, seed);
        // Run again, its heap is filled otherwise (isolate.h): a result that reads memory it
        // never wrote changes with it.
        const IsolatedTrace second = refine_isolated(impl, transformed.mesh, request, timeout_seconds, isolate,
                                                     t == InputTransformation::Repeat ? kSecondHeapFill : kHeapFill);
        if (second.outcome.status != RunStatus::Ok || !second.trace) {
            // Refusing the input written otherwise, or crashing on it, is a dependence on how
            // it is written too.
            check.result = InvarianceResult::NotInvariant;
            check.explanation = "the run on the transformed input: " + second.outcome.summary();
            out.checks.push_back(std::move(check));
            continue;
        }
        if (t == InputTransformation::Repeat) {
            out.checks.push_back(compare_repeat(first.trace->back(), second.trace->back()));
            continue;
        }
        check = measure_invariance(first.trace->back(), second.trace->back(), transformed, tolerance);
        check.transformation = t;
        out.checks.push_back(std::move(check));
    }
    return out;
}

InvarianceShrink shrink_not_invariant(const Implementation& impl, const PolyMesh& input, const RefineRequest& request,
                                      InputTransformation t, std::uint64_t seed, double tolerance, double timeout_seconds,
                                      bool isolate) {
    InvarianceShrink out;
    const auto shows = [&](const PolyMesh& mesh, InvarianceCheck* check) {
        ++out.tests;
        const InvarianceReport r = check_invariance(impl, mesh, request, {t}, seed, tolerance, timeout_seconds, isolate);
        const bool bad = r.checks.size() == 1 && (r.checks[0].result == InvarianceResult::NotInvariant ||
                                                  r.checks[0].result == InvarianceResult::Nondeterministic);
        if (bad && check) *check = r.checks[0];
        return bad;
    };
    if (!shows(input, &out.check))
        throw InputError(impl.name() + " is " + std::string(to_string(out.check.result)) + " under " + to_string(t) +
                         " on this input: nothing to shrink");
    std::vector<int> faces(static_cast<size_t>(input.num_faces()));
    for (size_t f = 0; f < faces.size(); ++f) faces[f] = static_cast<int>(f);
    // ddmin: try each of n chunks alone, then each complement; on success restart coarser.
    size_t n = 2;
    while (faces.size() >= 2) {
        const size_t chunk = (faces.size() + n - 1) / n;
        bool reduced = false;
        for (size_t i = 0; i < n && !reduced; ++i) {
            const size_t lo = std::min(faces.size(), i * chunk), hi = std::min(faces.size(), lo + chunk);
            if (lo == hi) continue;
            const std::vector<int> part(faces.begin() + static_cast<std::ptrdiff_t>(lo), faces.begin() + static_cast<std::ptrdiff_t>(hi));
            std::vector<int> rest(faces.begin(), faces.begin() + static_cast<std::ptrdiff_t>(lo));
            rest.insert(rest.end(), faces.begin() + static_cast<std::ptrdiff_t>(hi), faces.end());
            InvarianceCheck check;
            if (shows(submesh(input, part), &check)) {
                faces = part;
                out.check = check;
                n = 2;
                reduced = true;
            } else if (n > 2 && shows(submesh(input, rest), &check)) {
                faces = rest;
                out.check = check;
                n = std::max<size_t>(n - 1, 2);
                reduced = true;
            }
        }
        if (!reduced) {
            if (n >= faces.size()) break;
            n = std::min(faces.size(), 2 * n);
        }
    }
    // Nothing removed: the input itself (submesh drops vertices no face uses, which the
    // symptom may need: an isolated vertex).
    out.minimal = faces.size() == static_cast<size_t>(input.num_faces()) ? input : submesh(input, faces);
    return out;
}

}  // namespace crossdiv::verification
