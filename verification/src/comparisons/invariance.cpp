#include "crossdiv/verification/comparisons/invariance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/nondeterminism.h"
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
            check.explanation = "the run on the transformed input: " + second.outcome.summary();
            out.checks.push_back(std::move(check));
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
