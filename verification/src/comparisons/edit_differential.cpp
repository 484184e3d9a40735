#include "crossdiv/verification/comparisons/edit_differential.h"

#include <algorithm>
#include <random>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/halfedge_validity.h"
#include "crossdiv/verification/harness/ddmin.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {

std::string to_string(const ResolvedEdit& op) {
    return std::string(op.kind == EditKind::Flip ? "flip " : "split ") + std::to_string(op.a) + "-" + std::to_string(op.b);
}

std::vector<EditOp> random_edit_ops(uint64_t seed, int count, double flip_share) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<EditOp> ops(static_cast<size_t>(count));
    for (EditOp& op : ops) {
        op.kind = unit(rng) < flip_share ? EditKind::Flip : EditKind::Split;
        op.selector = rng();
    }
    return ops;
}

std::vector<Triangle> canonical_faces(std::vector<Triangle> faces) {
    for (Triangle& t : faces) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    std::sort(faces.begin(), faces.end());
    return faces;
}

FlipFunction our_flip() {
    return [](HalfedgeMesh& m, EdgeId e) { return m.flip(e); };
}

SplitFunction our_split() {
    return [](HalfedgeMesh& m, std::vector<Vec3>& positions, EdgeId e) { return split_at_midpoint(m, positions, e); };
}

namespace {

std::string face_name(const Triangle& t) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "(" + std::string&&.
    std::string s(1, '(');
    for (int k = 0; k < 3; ++k) s.append(k ? ", " : "").append(std::to_string(t[k]));
    return s + ")";
}

/// What differs between two canonical face lists, naming one face.
std::string face_difference(const std::vector<Triangle>& ours, const std::vector<Triangle>& theirs, const std::string& name) {
    std::vector<Triangle> only_ours, only_theirs;
    std::set_difference(ours.begin(), ours.end(), theirs.begin(), theirs.end(), std::back_inserter(only_ours));
    std::set_difference(theirs.begin(), theirs.end(), ours.begin(), ours.end(), std::back_inserter(only_theirs));
    std::string s = std::to_string(ours.size()) + " faces in ours, " + std::to_string(theirs.size()) + " in " + name;
    if (!only_ours.empty()) s += "; ours has " + face_name(only_ours[0]) + " (and " + std::to_string(only_ours.size() - 1) + " more) that " + name + " lacks";
    if (!only_theirs.empty()) s += "; " + name + " has " + face_name(only_theirs[0]) + " (and " + std::to_string(only_theirs.size() - 1) + " more) that ours lacks";
    return s;
}

EditRunResult run(const TriMesh& base, const std::vector<EditOp>& ops, const std::vector<std::string>& references,
                  const OurEdits& our, std::vector<ResolvedEdit>* resolved) {
    HalfedgeMesh he = HalfedgeMesh::from_triangles(base);
    std::vector<Vec3> pos = base.positions;
    const long chi = he.num_vertices() - he.num_edges() + he.num_faces();
    auto refs = make_edit_references(base, references);
    EditRunResult r;
    auto stop = [&](int i, const ResolvedEdit& op, std::string subject, std::string kind, std::string detail) {
        r.disagreement = EditDisagreement{i, op, std::move(subject), std::move(kind), std::move(detail)};
    };

    for (int i = 0; i < static_cast<int>(ops.size()) && !r.disagreement; ++i) {
        const EditOp& op = ops[static_cast<size_t>(i)];
        const EdgeId e(static_cast<int>(op.selector % static_cast<uint64_t>(he.num_edges())));
        const HalfedgeId h = HalfedgeMesh::halfedge(e);
        const ResolvedEdit res{op.kind, he.origin(h).idx, he.target(h).idx};
        if (resolved) resolved->push_back(res);
        r.ops_run = i + 1;
        const std::vector<Triangle> before = op.kind == EditKind::Flip ? he.triangles() : std::vector<Triangle>{};

        int new_vertex = -1;
        bool flipped = false;
        if (op.kind == EditKind::Flip) {
            const FlipRefusal why = our.flip(he, e);
            flipped = why == FlipRefusal::None;
            ++(flipped ? r.flips : r.refused_flips);
            if (!flipped && he.triangles() != before) stop(i, res, "ours", "refusal", "refused (" + std::string(to_string(why)) + ") but changed the faces");
        } else {
            new_vertex = our.split(he, pos, e).idx;
            ++r.splits;
        }
        for (auto& ref : refs) {
            if (r.disagreement) break;
            try {
                if (op.kind == EditKind::Flip) {
                    const std::optional<bool> ok = ref.session->flip_ok(res.a, res.b);
                    if (ok && *ok != flipped) {
                        stop(i, res, ref.name, "refusal", std::string("ours ") + (flipped ? "flips" : "refuses") + ", " + ref.name +
                                                                  (*ok ? " would flip" : " refuses"));
                        break;
                    }
                    if (flipped) ref.session->flip(res.a, res.b);
                } else {
                    const int theirs = ref.session->split(res.a, res.b);
                    if (theirs != new_vertex)
                        stop(i, res, ref.name, "vertex-index", "new vertex " + std::to_string(theirs) + ", ours " + std::to_string(new_vertex));
                }
            } catch (const std::exception& ex) {
                stop(i, res, ref.name, "threw", ex.what());
            }
        }
        if (r.disagreement) break;

        if (const auto issues = check_halfedge_mesh(he); !issues.empty()) {
            stop(i, res, "ours", "invalid", std::string(to_string(issues[0].kind)) + ": " + issues[0].message);
            break;
        }
        if (he.num_vertices() - he.num_edges() + he.num_faces() != chi) {
            stop(i, res, "ours", "euler", "V - E + F changed from " + std::to_string(chi));
            break;
        }
        const std::vector<Triangle> ours = canonical_faces(he.triangles());
        for (auto& ref : refs) {
            const std::vector<std::string> msgs = ref.session->check();
            if (!msgs.empty()) {
                stop(i, res, ref.name, "invalid", msgs[0]);
                break;
            }
            const std::vector<Triangle> theirs = canonical_faces(ref.session->faces());
            if (theirs != ours) {
                stop(i, res, ref.name, "faces", face_difference(ours, theirs, ref.name));
                break;
            }
            if (new_vertex >= 0) {
                const std::vector<Vec3> p = ref.session->positions();
                if (p.size() != pos.size() || p.back() != pos.back()) {
                    stop(i, res, ref.name, "positions", "new vertex " + std::to_string(new_vertex) + " not at the same midpoint");
                    break;
                }
            }
        }
    }
    r.vertices = he.num_vertices();
    r.faces = he.num_faces();
    return r;
}

}  // namespace

std::vector<std::string> available_edit_references() {
    std::vector<std::string> names;
    for (const Implementation* i : references_with(&Capabilities::edits)) names.push_back(i->name());
    return names;
}

std::vector<EditReference> make_edit_references(const TriMesh& base, const std::vector<std::string>& names) {
    std::vector<EditReference> out;
    if (names.empty()) return out;  // ours alone
    for (const Implementation* ref : select_references(&Capabilities::edits, names, "edit"))
        out.push_back({ref->name(), ref->open_edit(base)});
    return out;
}

EditRunResult run_edit_differential(const TriMesh& base, const std::vector<EditOp>& ops,
                                    const std::vector<std::string>& references, const OurEdits& ours) {
    return run(base, ops, references, ours, nullptr);
}

ShrunkEdits shrink_edit_sequence(const TriMesh& base, const std::vector<EditOp>& ops,
                                 const std::vector<std::string>& references, const OurEdits& ours) {
    const EditRunResult first = run(base, ops, references, ours, nullptr);
    if (!first.disagreement) throw InputError("the sequence of " + std::to_string(ops.size()) + " operations does not fail: nothing to shrink");
    const EditDisagreement target = *first.disagreement;
    ShrunkEdits s;
    std::vector<EditOp> prefix(ops.begin(), ops.begin() + target.op_index + 1);
    s.ops = ddmin(std::move(prefix), [&](const std::vector<EditOp>& candidate) {
        ++s.runs;
        const EditRunResult r = run(base, candidate, references, ours, nullptr);
        return r.disagreement && r.disagreement->subject == target.subject && r.disagreement->kind == target.kind;
    });
    const EditRunResult last = run(base, s.ops, references, ours, &s.resolved);
    s.disagreement = *last.disagreement;
    return s;
}

}  // namespace crossdiv::verification
