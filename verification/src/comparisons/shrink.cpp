#include "crossdiv/verification/comparisons/shrink.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <span>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/harness/ddmin.h"

namespace crossdiv::verification {
namespace {

/// Whether `m` still shows `symptom` (a candidate core refuses does not).
bool still_shows(const PolyMesh& m, const RefinementRequest& req, const ShrinkSymptom& symptom, int& tests) {
    if (m.num_faces() == 0) return false;
    ++tests;
    return symptom_of(compare_refinement(m, "candidate", req)) == symptom;
}

/// The coarse vertices that vertex `v` of the last level of `core` descends from (through
/// edge points' ends and face points' corners).
std::vector<int> coarse_ancestors(const Refinement& core, int v) {
    std::vector<int> current = {v};
    for (size_t l = core.births.size(); l-- > 0;) {
        std::vector<int> parents;
        for (int u : current) {
            const VertexBirth& birth = core.births[l][static_cast<size_t>(u)];
            if (birth.kind == VertexBirth::Kind::Face) {
                const PolyMesh& coarse = core.levels[l];
                parents.insert(parents.end(), coarse.face(birth.a), coarse.face(birth.a) + coarse.face_size(birth.a));
                continue;
            }
            parents.push_back(birth.a);
            if (birth.kind == VertexBirth::Kind::Edge) parents.push_back(birth.b);
        }
        std::sort(parents.begin(), parents.end());
        parents.erase(std::unique(parents.begin(), parents.end()), parents.end());
        current = std::move(parents);
    }
    return current;
}

/// Where the symptom shows, as (level, vertex in core's numbering at that level): the worst
/// vertex of the diverging reference, or of the vertex class no named rule fits worst. None
/// for a subject that fails (its failure has no place).
std::optional<std::pair<int, int>> symptom_site(const RefinementComparison& c, const ShrinkSymptom& s) {
    if (s.kind == ShrinkSymptom::Kind::ReferenceDiverges && !c.runs.empty() && !c.runs[0].comparison.worst.empty())
        return std::pair{c.levels, c.runs[0].comparison.worst[0].ours_index};
    if (s.kind == ShrinkSymptom::Kind::ReferenceUvDiverges && !c.runs.empty() && c.runs[0].uv &&
        c.runs[0].uv->comparison.worst_vertex >= 0)
        return std::pair{c.levels, c.runs[0].uv->comparison.worst_vertex};
    if (s.kind == ShrinkSymptom::Kind::SubjectFollowsNoRule && c.rules && c.rules->classified_level > 0) {
        const VertexClassRow* worst = nullptr;
        double worst_fit = -1;
        for (const VertexClassRow& row : c.rules->rows) {
            if (std::any_of(row.fits.begin(), row.fits.end(), [](const RuleFit& f) { return f.fits; })) continue;
            const double best = std::min_element(row.fits.begin(), row.fits.end(), [](const RuleFit& a, const RuleFit& b) {
                                    return a.max_rel < b.max_rel;
                                })->max_rel;
            if (best > worst_fit && row.worst_vertex >= 0) {
                worst_fit = best;
                worst = &row;
            }
        }
        if (worst) return std::pair{c.rules->classified_level, worst->worst_vertex};
    }
    return std::nullopt;
}

/// The corners of face f.
std::span<const int> corners(const PolyMesh& m, int f) { return {m.face(f), static_cast<size_t>(m.face_size(f))}; }

/// The vertices the listed faces use, in their order, appended to `positions`; returns each
/// vertex's new index, -1 for the vertices left out.
std::vector<int> kept_vertices(const PolyMesh& mesh, const std::vector<int>& faces, std::vector<Vec3>& positions,
                               const std::vector<int>& also_vertices = {}) {
    std::vector<int> remap(static_cast<size_t>(mesh.num_vertices()), -1);
    for (int v : also_vertices) remap[static_cast<size_t>(v)] = 0;
    for (int f : faces)
        for (int v : corners(mesh, f)) remap[static_cast<size_t>(v)] = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (remap[static_cast<size_t>(v)] == 0) {
            remap[static_cast<size_t>(v)] = static_cast<int>(positions.size());
            positions.push_back(mesh.positions[static_cast<size_t>(v)]);
        }
    return remap;
}

/// Faces with a vertex within k rings of `seeds`.
std::vector<int> ring_faces(const PolyMesh& m, const std::vector<int>& seeds, int k) {
    std::vector<char> in(static_cast<size_t>(m.num_vertices()), 0);
    for (int s : seeds) in[s] = 1;
    std::vector<int> faces;
    for (int ring = 0; ring < k; ++ring) {
        faces.clear();
        for (int f = 0; f < m.num_faces(); ++f)
            for (int v : corners(m, f))
                if (in[v]) {
                    faces.push_back(f);
                    break;
                }
        if (ring + 1 < k)
            for (int f : faces)
                for (int v : corners(m, f)) in[v] = 1;
    }
    return faces;
}

/// The vertices no face uses. Shrinking keeps them while it removes faces (an isolated vertex
/// is what some references fail on: CGAL's Loop, and removing faces never makes one), then
/// removes those the symptom does not need.
std::vector<int> unused_vertices(const PolyMesh& m) {
    std::vector<char> used(static_cast<size_t>(m.num_vertices()), 0);
    for (int v : m.face_vertices) used[static_cast<size_t>(v)] = 1;
    std::vector<int> unused;
    for (int v = 0; v < m.num_vertices(); ++v)
        if (!used[static_cast<size_t>(v)]) unused.push_back(v);
    return unused;
}

/// Step 1 of shrinking: the smallest k-ring around `seeds` (up to 4 rings) that still shows
/// the symptom, into `neighbourhood`; returns k, or 0 when the whole mesh was needed.
template <class StillShows>
int shrink_to_neighbourhood(const PolyMesh& mesh, const std::vector<int>& seeds, StillShows&& shows, PolyMesh& neighbourhood) {
    neighbourhood = mesh;
    if (seeds.empty()) return 0;
    const std::vector<int> isolated = unused_vertices(mesh);
    for (int k = 1; k <= 4; ++k) {
        PolyMesh candidate = submesh(mesh, ring_faces(mesh, seeds, k), isolated);
        if (candidate.num_faces() >= mesh.num_faces()) break;
        if (shows(candidate)) {
            neighbourhood = std::move(candidate);
            return k;
        }
    }
    return 0;
}

/// Step 2: ddmin over the neighbourhood's faces: try keeping only the complement of one of n
/// chunks; on success shrink n, else refine the split, until chunks are single faces.
template <class StillShows, class OutOfTime>
PolyMesh shrink_faces(const PolyMesh& neighbourhood, StillShows&& shows, OutOfTime&& out_of_time) {
    std::vector<int> all(static_cast<size_t>(neighbourhood.num_faces()));
    std::iota(all.begin(), all.end(), 0);
    std::vector<int> isolated = unused_vertices(neighbourhood);
    const std::vector<int> faces = ddmin(std::move(all), [&](const std::vector<int>& keep) {
        return !out_of_time() && shows(submesh(neighbourhood, keep, isolated));
    });
    // Then the isolated vertices the symptom does not need (a model may have hundreds): ddmin
    // over them with the faces found, keeping at least one, as ddmin keeps at least one face.
    if (isolated.size() > 1)
        isolated = ddmin(std::move(isolated), [&](const std::vector<int>& keep) {
            return !out_of_time() && shows(submesh(neighbourhood, faces, keep));
        });
    return submesh(neighbourhood, faces, isolated);
}

/// Whether a reference's failure is one to shrink: a crash, an exception, a lie about its
/// result. Not a refusal (a verdict on the input) nor a timeout (each candidate would wait
/// out the time limit).
bool shrinkable_failure(RunStatus status) {
    return status != RunStatus::Ok && status != RunStatus::Rejected && status != RunStatus::Timeout &&
           status != RunStatus::Unavailable;
}

/// The symptom of one reference's run: it diverges with a class, or fails in a shrinkable way.
std::optional<ShrinkSymptom> reference_symptom(const RefinementRun& run) {
    ShrinkSymptom s;
    if (run.verdict == Verdict::Diverge) {
        s.kind = ShrinkSymptom::Kind::ReferenceDiverges;
        s.divergence_class = run.divergence_class;
        return s;
    }
    if (run.verdict == Verdict::Agree && run.uv && run.uv->compared() && run.uv->outcome.verdict == Verdict::Diverge) {
        s.kind = ShrinkSymptom::Kind::ReferenceUvDiverges;
        s.divergence_class = run.uv->outcome.cls;
        return s;
    }
    if (!shrinkable_failure(run.outcome.status)) return std::nullopt;
    s.kind = ShrinkSymptom::Kind::ReferenceFails;
    s.status = run.outcome.status;
    return s;
}

/// The coarse vertex nearest `at`.
std::vector<int> nearest_coarse_vertex(const PolyMesh& mesh, const Vec3& at) {
    if (mesh.num_vertices() == 0) return {};
    int best = 0;
    for (int v = 1; v < mesh.num_vertices(); ++v)
        if ((mesh.positions[v] - at).squaredNorm() < (mesh.positions[best] - at).squaredNorm()) best = v;
    return {best};
}

}  // namespace

std::string describe(const ShrinkSymptom& s, const std::string& subject, const std::string& reference) {
    switch (s.kind) {
        case ShrinkSymptom::Kind::ReferenceDiverges:
            return reference + " diverges from " + subject + " (" + to_string(s.divergence_class) + ")";
        case ShrinkSymptom::Kind::ReferenceFails: return reference + " fails (" + std::string(to_string(s.status)) + ")";
        case ShrinkSymptom::Kind::SubjectFails: return subject + " fails (" + std::string(to_string(s.status)) + ")";
        case ShrinkSymptom::Kind::SubjectUnmatched: return subject + "'s vertices match none of core's";
        case ShrinkSymptom::Kind::SubjectTopology: return subject + "'s faces are not core's";
        case ShrinkSymptom::Kind::SubjectFollowsNoRule: return "no named rule fits " + subject;
        case ShrinkSymptom::Kind::ReferenceUvDiverges:
            return reference + "'s texture coordinates diverge from " + subject + "'s (" + to_string(s.divergence_class) + ")";
    }
    return "unknown";
}

std::string symptom_explanation(const RefinementComparison& c) {
    if (c.runs.empty()) return "";
    const RefinementRun& r = c.runs[0];
    const bool uv = r.verdict == Verdict::Agree && r.uv && r.uv->compared() && r.uv->outcome.verdict == Verdict::Diverge;
    return uv ? r.uv->explanation : r.explanation;
}

std::optional<ShrinkSymptom> symptom_of(const RefinementComparison& c) {
    if (!c.core_error.empty()) return std::nullopt;
    ShrinkSymptom s;
    if (c.subject_outcome.status != RunStatus::Ok) {
        s.kind = ShrinkSymptom::Kind::SubjectFails;
        s.status = c.subject_outcome.status;
        return s;
    }
    if (!c.subject_unmatched.empty()) {
        s.kind = ShrinkSymptom::Kind::SubjectUnmatched;
        return s;
    }
    if (!c.subject_topology.empty()) {
        s.kind = ShrinkSymptom::Kind::SubjectTopology;
        return s;
    }
    if (!c.runs.empty()) {
        if (c.runs.size() != 1) return std::nullopt;
        return reference_symptom(c.runs[0]);
    }
    if (c.rules && !c.rules->rule) {
        s.kind = ShrinkSymptom::Kind::SubjectFollowsNoRule;
        return s;
    }
    return std::nullopt;
}

PolyMesh submesh(const PolyMesh& mesh, const std::vector<int>& faces, const std::vector<int>& also_vertices) {
    PolyMesh out;
    const std::vector<int> remap = kept_vertices(mesh, faces, out.positions, also_vertices);
    if (!mesh.colors.empty())
        for (int v = 0; v < mesh.num_vertices(); ++v)
            if (remap[static_cast<size_t>(v)] >= 0) out.colors.push_back(mesh.colors[static_cast<size_t>(v)]);
    std::vector<char> hole(static_cast<size_t>(mesh.num_faces()), 0);
    for (int f : mesh.creases.holes) hole[static_cast<size_t>(f)] = 1;
    for (int f : faces) {
        if (hole[static_cast<size_t>(f)]) out.creases.holes.push_back(out.num_faces());
        for (int v : corners(mesh, f)) out.face_vertices.push_back(remap[static_cast<size_t>(v)]);
        out.face_start.push_back(static_cast<int>(out.face_vertices.size()));
    }
    for (const SharpEdge& e : mesh.creases.edges)
        if (remap[static_cast<size_t>(e.a)] >= 0 && remap[static_cast<size_t>(e.b)] >= 0)
            out.creases.edges.push_back({remap[static_cast<size_t>(e.a)], remap[static_cast<size_t>(e.b)], e.sharpness});
    for (const SharpVertex& c : mesh.creases.vertices)
        if (remap[static_cast<size_t>(c.v)] >= 0) out.creases.vertices.push_back({remap[static_cast<size_t>(c.v)], c.sharpness});
    std::sort(out.creases.holes.begin(), out.creases.holes.end());
    // Hierarchical edits of the kept faces, renumbered: a path depends on its base face's
    // corner order only, which is kept; the edits of dropped faces go with them.
    if (!mesh.creases.edits.empty()) {
        std::vector<int> renumbered(static_cast<size_t>(mesh.num_faces()), -1);
        for (size_t i = 0; i < faces.size(); ++i) renumbered[static_cast<size_t>(faces[i])] = static_cast<int>(i);
        for (HierarchicalEdit e : mesh.creases.edits)
            if ((e.face = renumbered[static_cast<size_t>(e.face)]) >= 0) out.creases.edits.push_back(std::move(e));
    }
    // Face-varying channels: the values the kept faces' corners use, in their order, renumbered
    // (a minimal mesh of a textured model would otherwise carry all of its thousands of values).
    for (const FaceVaryingChannel& ch : mesh.face_varying) {
        FaceVaryingChannel& kept = out.face_varying.emplace_back();
        kept.name = ch.name;
        kept.dimension = ch.dimension;
        std::vector<int> value_remap(static_cast<size_t>(ch.num_values()), -1);
        for (int f : faces)
            for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) value_remap[static_cast<size_t>(ch.corner_values[c])] = 0;
        int next = 0;
        for (int i = 0; i < ch.num_values(); ++i)
            if (value_remap[static_cast<size_t>(i)] == 0) {
                value_remap[static_cast<size_t>(i)] = next++;
                kept.values.insert(kept.values.end(), ch.value(i), ch.value(i) + ch.dimension);
            }
        for (int f : faces)
            for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c)
                kept.corner_values.push_back(value_remap[static_cast<size_t>(ch.corner_values[c])]);
    }
    out.creases.face_varying = mesh.creases.face_varying;
    out.creases.method = mesh.creases.method;
    out.creases.boundary = mesh.creases.boundary;
    out.creases.smooth_triangles = mesh.creases.smooth_triangles;
    return out;
}

ShrinkResult shrink_divergence(const PolyMesh& mesh, const std::string& name, const RefinementRequest& req,
                               const ShrinkLimits& limits) {
    const auto t0 = std::chrono::steady_clock::now();
    const bool no_reference = req.without_references;
    if (no_reference ? !req.subject : req.references.size() != 1)
        throw InputError("shrinking compares against exactly one reference, or a subject with none");
    ShrinkResult r;
    r.original = compare_refinement(mesh, name, req);
    if (!r.original.core_error.empty()) throw InputError(name + ": core refuses the input: " + r.original.core_error);
    const std::optional<ShrinkSymptom> symptom = symptom_of(r.original);
    if (!symptom) {
        std::string what = r.original.subject + " shows nothing to shrink";
        if (!r.original.runs.empty())
            what = r.original.runs[0].reference + " does not diverge from " + r.original.subject + " nor fail (" +
                   to_string(r.original.runs[0].verdict) + ": " + r.original.runs[0].explanation + ")";
        else if (r.original.rules && r.original.rules->rule)
            what = r.original.subject + " follows the named rule " + rule_name(req.scheme, *r.original.rules->rule);
        throw InputError(name + ": " + what + "; nothing to shrink");
    }
    r.symptom = *symptom;

    // Past the time limit every further candidate (or level count) counts as not showing it:
    // ddmin then only splits what it has until its chunks are single faces, running nothing.
    const auto out_of_time = [&] {
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > limits.seconds) r.cut_short = true;
        return r.cut_short;
    };

    // Fewer levels, where the whole input shows the same symptom at them: every candidate is
    // then refined fewer times (a reference that crashes at the first of three levels is shrunk
    // at one: its candidates that do not crash, most of them, refine once rather than three
    // times). The minimal mesh is stated with its levels.
    RefinementRequest shrink_req = req;
    std::optional<RefinementComparison> fewer;
    for (int levels = 1; levels < req.levels && !fewer && !out_of_time(); ++levels) {
        shrink_req.levels = levels;
        ++r.tests;
        RefinementComparison c = compare_refinement(mesh, name, shrink_req);
        if (symptom_of(c) == r.symptom) fewer = std::move(c);
    }
    if (!fewer) shrink_req.levels = req.levels;
    r.levels = shrink_req.levels;
    const RefinementComparison& whole = fewer ? *fewer : r.original;

    // 1. The neighbourhood of the symptom's coarse ancestors (through core's provenance, where
    // it has it, else the coarse vertex nearest the site); 2. ddmin over its faces.
    const auto shows = [&](const PolyMesh& candidate) {
        return !out_of_time() && still_shows(candidate, shrink_req, r.symptom, r.tests);
    };
    std::vector<int> seeds;
    if (const auto site = symptom_site(whole, r.symptom)) {
        const Refinement core = core_implementation().refine_with_provenance(mesh, {req.scheme, req.rule, site->first, req.face_varying});
        if (static_cast<int>(core.births.size()) == site->first)
            seeds = coarse_ancestors(core, site->second);
        else
            seeds = nearest_coarse_vertex(mesh, core.levels.back().positions[static_cast<size_t>(site->second)]);
    }
    r.k = shrink_to_neighbourhood(mesh, seeds, shows, r.neighbourhood);
    r.minimal = shrink_faces(r.neighbourhood, shows, out_of_time);
    r.minimal_comparison = compare_refinement(r.minimal, "minimal", shrink_req);
    return r;
}

}  // namespace crossdiv::verification
