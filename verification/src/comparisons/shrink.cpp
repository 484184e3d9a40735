#include "crossdiv/verification/comparisons/shrink.h"

#include <algorithm>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/ddmin.h"

namespace crossdiv::verification {
namespace {

/// The verdict the shrinking must keep: the single reference still diverges, same class.
/// A candidate core refuses (it became non-manifold) does not count.
bool still_diverges(const TriMesh& m, const LoopComparisonRequest& req, DivergenceClass cls, int& tests) {
    if (m.num_faces() == 0) return false;
    ++tests;
    try {
        loop_input_connectivity(m);
    } catch (const InputError&) {
        return false;
    }
    const LoopComparison c = compare_loop(m, "candidate", req);
    return c.runs.size() == 1 && c.runs[0].verdict == Verdict::Diverge && c.runs[0].divergence_class == cls;
}

/// Coarse vertices the level-`levels` vertex `v` descends from (through edge points' ends).
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
    if (req.references.size() != 1) throw InputError("shrinking compares against exactly one reference");
    ShrinkResult r;
    r.original = compare_loop(mesh, name, req);
    const ReferenceRun& run = r.original.runs.at(0);
    if (run.verdict != Verdict::Diverge)
        throw InputError(name + ": " + run.reference + " does not diverge from core (" + to_string(run.verdict) + ": " +
                         run.explanation + "); nothing to shrink");
    r.divergence_class = run.divergence_class;

    // 1. The neighbourhood: the smallest k-ring around the worst vertex's coarse ancestors
    //    that still shows the divergence (up to 4 rings; else the whole mesh).
    r.neighbourhood = mesh;
    if (!run.comparison.worst.empty()) {
        LoopRefiner refiner(mesh, req.options);
        refiner.refine(req.levels);
        const std::vector<int> seeds = coarse_ancestors(refiner, run.comparison.worst[0].ours_index);
        for (int k = 1; k <= 4; ++k) {
            TriMesh candidate = submesh(mesh, ring_faces(mesh, seeds, k));
            if (candidate.num_faces() >= mesh.num_faces()) break;
            if (still_diverges(candidate, req, r.divergence_class, r.tests)) {
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
        return still_diverges(submesh(r.neighbourhood, keep), req, r.divergence_class, r.tests);
    });
    r.minimal = submesh(r.neighbourhood, faces);
    r.minimal_comparison = compare_loop(r.minimal, "minimal", req);
    return r;
}

}  // namespace crossdiv::verification
