#include "crossdiv/verification/comparisons/shared_topology.h"

#include <algorithm>
#include <numeric>

namespace crossdiv::verification {

MadeFaces made_faces(const PolyMesh& mesh, std::span<const int> to_core) {
    MadeFaces m;
    m.counts = topology_counts(mesh);
    if (to_core.size() != static_cast<size_t>(mesh.num_vertices())) return m;
    if (std::any_of(to_core.begin(), to_core.end(), [](int v) { return v < 0; })) return m;
    // Each face in core's numbering, rotated to start at its smallest corner.
    std::vector<int> rotated;
    rotated.reserve(mesh.face_vertices.size());
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int* face = mesh.face(f);
        const int n = mesh.face_size(f);
        int first = 0;
        for (int k = 1; k < n; ++k)
            if (to_core[face[k]] < to_core[face[first]]) first = k;
        for (int k = 0; k < n; ++k) rotated.push_back(to_core[face[(first + k) % n]]);
    }
    std::vector<int> start(mesh.face_start.begin(), mesh.face_start.end());
    auto corners_of = [&](int f) { return std::span<const int>(rotated).subspan(start[f], start[f + 1] - start[f]); };
    std::vector<int> order(static_cast<size_t>(mesh.num_faces()));
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        const auto x = corners_of(a), y = corners_of(b);
        return std::lexicographical_compare(x.begin(), x.end(), y.begin(), y.end());
    });
    m.face_start.reserve(order.size() + 1);
    m.face_start.push_back(0);
    m.corners.reserve(rotated.size());
    for (int f : order) {
        const auto c = corners_of(f);
        m.corners.insert(m.corners.end(), c.begin(), c.end());
        m.face_start.push_back(static_cast<int>(m.corners.size()));
    }
    m.in_core_numbering = true;
    return m;
}

bool same_faces(const MadeFaces& a, const MadeFaces& b) {
    if (a.in_core_numbering && b.in_core_numbering) return a.face_start == b.face_start && a.corners == b.corners;
    return a.counts == b.counts;
}

void require_shared_topology(std::vector<RefinementRun>& runs, const std::vector<std::optional<MadeFaces>>& made,
                             const std::string& under_test) {
    const size_t n = std::min(runs.size(), made.size());
    std::vector<std::vector<std::string>> sharing(n);  // the other references that make run i's faces
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j)
            if (i != j && made[i] && made[j] && same_faces(*made[i], *made[j])) sharing[i].push_back(runs[j].reference);
    for (size_t i = 0; i < n; ++i) {
        RefinementRun& run = runs[i];
        if (run.verdict != Verdict::Diverge || run.divergence_class != DivergenceClass::Topology) continue;
        run.divergence_class = DivergenceClass::Unexplained;
        if (sharing[i].empty()) {
            run.explanation += "; no other reference makes " + run.reference + "'s faces, so the difference is " +
                               run.reference + "'s alone, not a topology class";
        } else {
            std::string others;
            for (const std::string& s : sharing[i]) others += (others.empty() ? "" : ", ") + s;
            run.explanation += "; " + others + " make" + (sharing[i].size() == 1 ? "s" : "") + " the same faces as " +
                               run.reference + ", and " + under_test + " alone differs";
        }
    }
}

}  // namespace crossdiv::verification
