#include "crossdiv/verification/comparisons/shrink.h"

#include <algorithm>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/ddmin.h"

namespace crossdiv::verification {
namespace {

/// Whether `m` still shows `symptom`. A candidate core refuses (under the request's
/// non-manifold rule) does not count.
bool still_shows(const TriMesh& m, const LoopComparisonRequest& req, const ShrinkSymptom& symptom, int& tests) {
    if (m.num_faces() == 0) return false;
    ++tests;
    try {
        check_loop_input(m, req.options);
    } catch (const InputError&) {
        return false;
    }
    return symptom_of(compare_loop(m, "candidate", req)) == symptom;
}

/// Coarse vertices the vertex `v` of the refiner's last level descends from (through edge
/// points' ends).
std::vector<int> coarse_ancestors(const LoopRefiner& refiner, int v) {
    std::vector<int> current = {v};
    for (int l = refiner.num_levels() - 1; l >= 1; --l) {
        const std::vector<VertexOrigin> origins = refiner.origins(l);
        std::vector<int> parents;
        for (int u : current) {
            parents.push_back(origins[u].a);
            if (origins[u].is_edge_point()) parents.push_back(origins[u].b);
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
std::optional<std::pair<int, int>> symptom_site(const LoopComparison& c, const ShrinkSymptom& s) {
    if (s.kind == ShrinkSymptom::Kind::ReferenceDiverges && !c.runs.empty() && !c.runs[0].comparison.worst.empty())
        return std::pair{c.levels, c.runs[0].comparison.worst[0].ours_index};
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

/// Faces with a vertex within k rings of `seeds`.
std::vector<int> ring_faces(const TriMesh& m, std::vector<int> seeds, int k) {
    std::vector<char> in(static_cast<size_t>(m.num_vertices()), 0);
    for (int s : seeds) in[s] = 1;
    std::vector<int> faces;
    for (int ring = 0; ring < k; ++ring) {
        faces.clear();
        for (int f = 0; f < m.num_faces(); ++f)
            for (int v : m.triangles[f])
                if (in[v]) {
                    faces.push_back(f);
                    break;
                }
        if (ring + 1 < k)
            for (int f : faces)
                for (int v : m.triangles[f]) in[v] = 1;
    }
    return faces;
}

}  // namespace

std::string describe(const ShrinkSymptom& s, const std::string& subject, const std::string& reference) {
    switch (s.kind) {
        case ShrinkSymptom::Kind::ReferenceDiverges:
            return reference + " diverges from " + subject + " (" + to_string(s.divergence_class) + ")";
        case ShrinkSymptom::Kind::SubjectFails: return subject + " fails (" + std::string(to_string(s.subject_status)) + ")";
        case ShrinkSymptom::Kind::SubjectUnmatched: return subject + "'s vertices match none of core's";
        case ShrinkSymptom::Kind::SubjectFollowsNoRule: return "no named rule fits " + subject;
    }
    return "unknown";
}

std::optional<ShrinkSymptom> symptom_of(const LoopComparison& c) {
    ShrinkSymptom s;
    if (c.subject_outcome.status != RunStatus::Ok) {
        s.kind = ShrinkSymptom::Kind::SubjectFails;
        s.subject_status = c.subject_outcome.status;
        return s;
    }
    if (!c.subject_unmatched.empty()) {
        s.kind = ShrinkSymptom::Kind::SubjectUnmatched;
        return s;
    }
    if (!c.runs.empty()) {
        if (c.runs.size() != 1 || c.runs[0].verdict != Verdict::Diverge) return std::nullopt;
        s.kind = ShrinkSymptom::Kind::ReferenceDiverges;
        s.divergence_class = c.runs[0].divergence_class;
        return s;
    }
    if (c.rules && !c.rules->rule) {
        s.kind = ShrinkSymptom::Kind::SubjectFollowsNoRule;
        return s;
    }
    return std::nullopt;
}

TriMesh submesh(const TriMesh& mesh, const std::vector<int>& faces) {
    std::vector<int> remap(static_cast<size_t>(mesh.num_vertices()), -1);
    std::vector<char> used(remap.size(), 0);
    for (int f : faces)
        for (int v : mesh.triangles[f]) used[v] = 1;
    TriMesh out;
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (used[v]) {
            remap[v] = out.num_vertices();
            out.positions.push_back(mesh.positions[v]);
        }
    for (int f : faces) out.triangles.push_back({remap[mesh.triangles[f][0]], remap[mesh.triangles[f][1]], remap[mesh.triangles[f][2]]});
    return out;
}

ShrinkResult shrink_divergence(const TriMesh& mesh, const std::string& name, const LoopComparisonRequest& req) {
    const bool no_reference = req.without_references;
    if (no_reference ? !req.subject : req.references.size() != 1)
        throw InputError("shrinking compares against exactly one reference, or a subject with none");
    ShrinkResult r;
    r.original = compare_loop(mesh, name, req);
    const std::optional<ShrinkSymptom> symptom = symptom_of(r.original);
    if (!symptom) {
        std::string what = r.original.subject + " shows nothing to shrink";
        if (!r.original.runs.empty())
            what = r.original.runs[0].reference + " does not diverge from " + r.original.subject + " (" +
                   to_string(r.original.runs[0].verdict) + ": " + r.original.runs[0].explanation + ")";
        else if (r.original.rules && r.original.rules->rule)
            what = r.original.subject + " follows the named rule weights=" +
                   std::string(to_string(r.original.rules->rule->weights)) +
                   " boundary=" + std::string(to_string(r.original.rules->rule->boundary));
        throw InputError(name + ": " + what + "; nothing to shrink");
    }
    r.symptom = *symptom;

    // 1. The neighbourhood: the smallest k-ring around the symptom's coarse ancestors that
    //    still shows it (up to 4 rings; else the whole mesh).
    r.neighbourhood = mesh;
    if (const auto site = symptom_site(r.original, r.symptom)) {
        LoopRefiner refiner(mesh, req.options);
        refiner.refine(site->first);
        const std::vector<int> seeds = coarse_ancestors(refiner, site->second);
        for (int k = 1; k <= 4; ++k) {
            TriMesh candidate = submesh(mesh, ring_faces(mesh, seeds, k));
            if (candidate.num_faces() >= mesh.num_faces()) break;
            if (still_shows(candidate, req, r.symptom, r.tests)) {
                r.k = k;
                r.neighbourhood = std::move(candidate);
                break;
            }
        }
    }

    // 2. ddmin over the neighbourhood's faces: try keeping only the complement of one of n
    //    chunks; on success shrink n, else refine the split, until chunks are single faces.
    std::vector<int> all(static_cast<size_t>(r.neighbourhood.num_faces()));
    for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    const std::vector<int> faces = ddmin(std::move(all), [&](const std::vector<int>& keep) {
        return still_shows(submesh(r.neighbourhood, keep), req, r.symptom, r.tests);
    });
    r.minimal = submesh(r.neighbourhood, faces);
    r.minimal_comparison = compare_loop(r.minimal, "minimal", req);
    return r;
}

}  // namespace crossdiv::verification
