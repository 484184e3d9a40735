#include "crossdiv/verification/comparisons/halfedge_checks.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_split_flip.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/harness/vector_angle.h"
#include "crossdiv/verification/implementations/registry.h"
#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? "no reference" : s;
}

/// The angle-weighted normals (Thuermer and Wuethrich 1998) written out: each unit face
/// normal times the face's interior angle at the vertex, summed and normalized; zero where
/// nothing is summed.
std::vector<Vec3> angle_weighted_normals(const TriMesh& m) {
    std::vector<Vec3> n(m.positions.size(), Vec3::Zero());
    for (const Triangle& t : m.triangles) {
        const Vec3 cross = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
        if (cross.norm() == 0) continue;
        const Vec3 unit = cross.normalized();
        for (int k = 0; k < 3; ++k) {
            const Vec3 a = m.positions[t[(k + 1) % 3]] - m.positions[t[k]], b = m.positions[t[(k + 2) % 3]] - m.positions[t[k]];
            n[t[k]] += std::atan2(a.cross(b).norm(), a.dot(b)) * unit;
        }
    }
    for (Vec3& v : n)
        if (v.norm() > 0) v.normalize();
    return n;
}

}  // namespace

CheckReport check_edits(const std::string& input, const OurEdits& ours) {
    CheckReport r;
    r.input = input;
    r.operation = "edits";
    const std::vector<std::string> refs = available_edit_references();
    TriMesh base;
    try {
        base = to_tri_mesh(load_input(input), "the edit differential");
    } catch (const InputError& e) {
        r.subjects.push_back(input);
        r.checks.push_back(count_check(input, "edit-differential", joined(refs), 1, e.what()));
        return r;
    }
    // Loop by local operations (split every edge, flip the new edges that join an old and a
    // new vertex) against the index-based refinement: the same vertices bit for bit, the same
    // faces, under each weight family.
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren}) {
        const LoopOptions o{w, LoopBoundary::EdgeOnly};
        const std::string subject = input + " loop " + std::string(to_string(w));
        r.subjects.push_back(subject);
        try {
            const TriMesh local = loop_by_split_and_flip(base, o), index = loop_subdivide(base, o, 1);
            int differing = local.num_vertices() == index.num_vertices() ? 0 : 1;
            for (int v = 0; differing == 0 && v < local.num_vertices(); ++v)
                differing += local.positions[static_cast<size_t>(v)] != index.positions[static_cast<size_t>(v)];
            const bool same_faces = canonical_faces(local.triangles) == canonical_faces(index.triangles);
            r.checks.push_back(count_check(subject, "loop-by-split-and-flip", "index-based loop", differing + !same_faces,
                                        std::to_string(differing) + " vertices differ in bits, faces " +
                                            (same_faces ? "equal" : "differ")));
        } catch (const InputError& e) {
            r.checks.push_back(count_check(subject, "loop-by-split-and-flip", "index-based loop", 1, e.what()));
        }
    }
    for (int seed = 1; seed <= kSuiteEditSeeds; ++seed) {
        const std::string subject = input + " seed " + std::to_string(seed);
        r.subjects.push_back(subject);
        const std::vector<EditOp> ops = random_edit_ops(static_cast<uint64_t>(seed), kSuiteEditOps, 0.6);
        try {
            const EditRunResult run = run_edit_differential(base, ops, refs, ours);
            if (!run.disagreement) {
                r.checks.push_back(count_check(subject, "edit-differential", joined(refs), 0,
                                            std::to_string(run.ops_run) + " operations (" + std::to_string(run.flips) +
                                                " flips, " + std::to_string(run.refused_flips) + " refused, " +
                                                std::to_string(run.splits) + " splits), valid and equal after each"));
                continue;
            }
            const ShrunkEdits s = shrink_edit_sequence(base, ops, refs, ours);
            std::string sequence;
            for (const ResolvedEdit& e : s.resolved) sequence += (sequence.empty() ? "" : ", ") + to_string(e);
            const EditDisagreement& d = s.disagreement;
            r.checks.push_back(count_check(subject, "edit-differential", joined(refs), 1,
                                        "operation " + std::to_string(run.disagreement->op_index + 1) + " of " +
                                            std::to_string(ops.size()) + ": " + d.subject + " " + d.kind + " (" + d.detail +
                                            "); shrunk to " + std::to_string(s.ops.size()) + ": " + sequence));
        } catch (const InputError& e) {
            r.checks.push_back(count_check(subject, "edit-differential", joined(refs), 1, e.what()));
        }
    }
    return r;
}

CheckReport check_normals(const std::string& input, const NormalsFunction& ours) {
    CheckReport r;
    r.input = input;
    r.operation = "normals";
    r.subjects.push_back(input);
    TriMesh mesh;
    try {
        mesh = to_tri_mesh(load_input(input), "vertex normals");
    } catch (const InputError& e) {
        r.checks.push_back(count_check(input, "normals", "input", 1, e.what()));
        return r;
    }
    std::vector<std::string> refs;
    for (const Implementation* i : references_with(&Capabilities::vertex_normals)) refs.push_back(i->name());
    const NormalsComparison c = compare_normals(mesh, NormalWeighting::Area, refs, ours);
    // The library calls that implement one of our weightings (measured on the catalog).
    const auto weighting_of = [](const std::string& name) -> std::optional<NormalWeighting> {
        if (name == "openmesh-correct") return NormalWeighting::Area;
        if (name == "openmesh-fast") return NormalWeighting::Uniform;
        return std::nullopt;
    };
    for (const ReferenceNormals& ref : c.references) {
        if (!ref.error.empty()) {
            r.checks.push_back({input, "normals", ref.name, NAN, 0.0, "rad", ref.method + " refused: " + ref.error,
                                Outcome{Verdict::RefRejected, DivergenceClass::None}});
            continue;
        }
        if (const std::optional<NormalWeighting> w = weighting_of(ref.name)) {
            const size_t k = static_cast<size_t>(*w);
            r.checks.push_back({input, "normals " + std::string(to_string(*w)), ref.name, ref.max_angle[k],
                                tolerances::kNormalMatchRad, "rad",
                                ref.method + " against our " + std::string(to_string(*w)) + " weighting (worst vertex " +
                                    std::to_string(ref.worst_vertex[k]) + "); " + ref.classification});
        } else {
            // A call that implements none of our weightings (CGAL's most visible normal): it
            // agrees where it matches one of them, else its own rule, measured and named.
            const size_t k = static_cast<size_t>(std::min_element(ref.max_angle, ref.max_angle + 3) - ref.max_angle);
            const Outcome outcome = ref.matches.empty() ? Outcome{Verdict::Diverge, DivergenceClass::NormalRule}
                                                        : Outcome{Verdict::Agree, DivergenceClass::None};
            r.checks.push_back({input, "normals", ref.name, ref.max_angle[k], tolerances::kNormalMatchRad, "rad",
                                ref.method + ": " + std::to_string(ref.most_visible) + " most visible, " +
                                    std::to_string(ref.sine_weighted) + " sine-weighted, " +
                                    std::to_string(ref.unexplained) + " neither; " + ref.classification,
                                outcome});
        }
    }
    const std::vector<Vec3> angle = ours(mesh, NormalWeighting::Angle), oracle = angle_weighted_normals(mesh);
    double worst = 0;
    int worst_vertex = -1;
    for (size_t v = 0; v < angle.size() && v < oracle.size(); ++v) {
        const bool both_zero = angle[v].norm() == 0 && oracle[v].norm() == 0;
        const double a = both_zero ? 0.0 : vector_angle(angle[v], oracle[v]);
        if (!(a <= worst)) {
            worst = a;
            worst_vertex = static_cast<int>(v);
        }
    }
    if (angle.size() != oracle.size()) worst = INFINITY;
    r.checks.push_back({input, "normals angle", "oracle", worst, tolerances::kNormalMatchRad, "rad",
                        "our angle weighting against the angle-weighted sum written out (worst vertex " +
                            std::to_string(worst_vertex) + ", " + detail::sci(worst) + " rad)"});
    return r;
}

}  // namespace crossdiv::verification
