#include "crossdiv/verification/harness/correspondence.h"

#include "harness/point_cloud.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>

#include "crossdiv/verification/harness/mesh_topology.h"

namespace crossdiv::verification {
namespace {

uint64_t pair_key(int a, int b) {
    const uint64_t lo = static_cast<uint32_t>(std::min(a, b)), hi = static_cast<uint32_t>(std::max(a, b));
    return lo << 32 | hi;
}

/// Recovers level k+1 of the reference from level k's map; returns a reason on failure.
std::string match_next_level(const std::vector<int>& prev, const std::vector<VertexOrigin>& origins,
                             const PolyMesh& ref_fine, std::vector<int>& next) {
    const int n_old = static_cast<int>(prev.size());
    if (ref_fine.num_vertices() != static_cast<int>(origins.size()))
        return "reference has " + std::to_string(ref_fine.num_vertices()) + " vertices, ours " +
               std::to_string(origins.size());
    std::unordered_map<uint64_t, int> our_edge_point;  // verification, not a kernel: a hash is fine here
    our_edge_point.reserve(origins.size());
    for (size_t i = 0; i < origins.size(); ++i)
        if (origins[i].is_edge_point()) our_edge_point.emplace(pair_key(origins[i].a, origins[i].b), static_cast<int>(i));

    const MeshTopology topo = mesh_topology(ref_fine);
    std::vector<std::array<int, 2>> old_neighbors(ref_fine.num_vertices(), {-1, -1});
    std::vector<int> old_count(ref_fine.num_vertices(), 0);
    for (auto [a, b] : topo.edge_list) {
        if (a < n_old && b < n_old) return "old vertices " + std::to_string(a) + " and " + std::to_string(b) + " are adjacent";
        for (auto [v, w] : {std::pair{a, b}, std::pair{b, a}})
            if (v >= n_old && w < n_old && old_count[v]++ < 2) old_neighbors[v][old_count[v] - 1] = w;
    }
    next.assign(ref_fine.num_vertices(), -1);
    std::vector<char> used(origins.size(), 0);
    for (int v = 0; v < ref_fine.num_vertices(); ++v) {
        int ours = -1;
        if (v < n_old) {
            ours = prev[v];  // old vertices keep their index in our numbering too
        } else {
            if (old_count[v] != 2)
                return "new vertex " + std::to_string(v) + " has " + std::to_string(old_count[v]) + " old neighbours";
            auto it = our_edge_point.find(pair_key(prev[old_neighbors[v][0]], prev[old_neighbors[v][1]]));
            if (it == our_edge_point.end()) return "new vertex " + std::to_string(v) + " sits on an edge we do not have";
            ours = it->second;
        }
        if (used[ours]) return "two reference vertices map to our vertex " + std::to_string(ours);
        used[ours] = 1;
        next[v] = ours;
    }
    return "";
}

}  // namespace

const char* to_string(MatchMethod method) {
    switch (method) {
        case MatchMethod::Order: return "order";
        case MatchMethod::Topology: return "topology";
        case MatchMethod::Nearest: return "nearest";
        case MatchMethod::NearestAndFaces: return "nearest+faces";
        case MatchMethod::None: return "none";
    }
    return "unknown";
}

Correspondence match_nearest(const std::vector<Vec3>& ours, const std::vector<Vec3>& ref) {
    Correspondence c;
    c.method = MatchMethod::None;
    if (ours.size() != ref.size()) {
        c.note = "vertex counts differ (" + std::to_string(ref.size()) + " vs " + std::to_string(ours.size()) + ")";
        return c;
    }
    PointCloud cloud{ours};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    c.ref_to_ours.resize(ref.size());
    std::vector<char> used(ours.size(), 0);
    for (size_t i = 0; i < ref.size(); ++i) {
        unsigned idx = 0;  // the tree's default index type
        double d2 = 0;
        tree.knnSearch(ref[i].data(), 1, &idx, &d2);
        if (used[idx]) {
            c.note = "nearest-neighbour matching is not one-to-one (our vertex " + std::to_string(idx) + " is nearest to two)";
            c.ref_to_ours.clear();
            return c;
        }
        used[idx] = 1;
        c.ref_to_ours[i] = static_cast<int>(idx);
    }
    c.method = MatchMethod::Nearest;
    return c;
}

Correspondence match_nearest_and_faces(const PolyMesh& ours, const PolyMesh& ref) {
    Correspondence c = match_nearest(ours.positions, ref.positions);
    if (c.method != MatchMethod::None || ours.num_vertices() != ref.num_vertices()) return c;
    const std::string nearest_failed = c.note;
    const size_t n = ref.positions.size();

    // Closest pairs first.
    PointCloud cloud{ours.positions};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    std::vector<unsigned> nearest(n);
    std::vector<double> d2(n);
    for (size_t i = 0; i < n; ++i) tree.knnSearch(ref.positions[i].data(), 1, &nearest[i], &d2[i]);
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return d2[a] < d2[b]; });
    // Only mutual nearest neighbours: a reference vertex that moved far may sit nearest to
    // one of ours whose own twin moved too, and must not take it.
    PointCloud ref_cloud{ref.positions};
    PointTree ref_tree(3, ref_cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    ref_tree.buildIndex();
    const auto mutual = [&](int i) {
        unsigned back = 0;
        double back_d2 = 0;
        ref_tree.knnSearch(ours.positions[nearest[i]].data(), 1, &back, &back_d2);
        return back_d2 >= d2[i];  // i is (one of) the nearest to its nearest
    };
    std::vector<int> map(n, -1), taken_by(n, -1);
    for (int i : order)
        if (taken_by[nearest[i]] < 0 && mutual(i)) {
            map[i] = static_cast<int>(nearest[i]);
            taken_by[nearest[i]] = i;
        }

    // Our faces by their directed edges, to find the face a reference face maps to.
    std::unordered_map<std::uint64_t, int> face_of_edge;
    const auto key = [](int a, int b) { return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b); };
    for (int f = 0; f < ours.num_faces(); ++f)
        for (int k = 0, m = ours.face_size(f); k < m; ++k) face_of_edge[key(ours.face(f)[k], ours.face(f)[(k + 1) % m])] = f;
    for (bool placed = true; placed;) {
        placed = false;
        for (int f = 0; f < ref.num_faces(); ++f) {
            const int m = ref.face_size(f);
            const int* rf = ref.face(f);
            int unmatched = 0, edge = -1;  // edge: a corner k with k and k+1 matched
            for (int k = 0; k < m; ++k) {
                if (map[rf[k]] < 0) ++unmatched;
                else if (edge < 0 && map[rf[(k + 1) % m]] >= 0) edge = k;
            }
            if (unmatched == 0 || edge < 0) continue;
            // The matched edge names our face; its corners at the unmatched places must be free.
            const int a = map[rf[edge]], b = map[rf[(edge + 1) % m]];
            const auto it = face_of_edge.find(key(a, b));
            if (it == face_of_edge.end() || ours.face_size(it->second) != m) continue;
            const int* of = ours.face(it->second);
            int at = 0;
            while (of[at] != a) ++at;
            for (int k = 0; k < m; ++k) {
                if (map[rf[k]] >= 0) continue;
                const int candidate = of[(at + k - edge + m) % m];
                if (taken_by[candidate] >= 0) continue;
                map[rf[k]] = candidate;
                taken_by[candidate] = rf[k];
                placed = true;
            }
        }
    }
    std::vector<int> left_ref, left_ours;
    for (size_t i = 0; i < n; ++i) {
        if (map[i] < 0) left_ref.push_back(static_cast<int>(i));
        if (taken_by[i] < 0) left_ours.push_back(static_cast<int>(i));
    }
    if (left_ref.size() == 1 && left_ours.size() == 1) map[left_ref[0]] = left_ours[0];
    else if (!left_ref.empty()) {
        c.note = nearest_failed + "; " + std::to_string(left_ref.size()) + " vertices left unplaced by the faces";
        return c;
    }
    c.method = MatchMethod::NearestAndFaces;
    c.ref_to_ours = std::move(map);
    c.note = nearest_failed;
    return c;
}

Correspondence match_loop_refinement(const std::vector<std::vector<VertexOrigin>>& our_origins,
                                     const std::vector<Vec3>& our_input, const adapters::LevelTrace& ref,
                                     const std::vector<Vec3>& our_last) {
    std::string why;
    std::vector<int> map;
    std::vector<std::vector<int>> level_maps;
    if (ref.empty() || ref.size() != our_origins.size() + 1) {
        why = "reference returned " + std::to_string(ref.size()) + " levels";
    } else if (ref[0].positions != our_input) {
        why = "reference's level 0 is not our input in our order";
    } else {
        map.resize(our_input.size());
        for (size_t i = 0; i < map.size(); ++i) map[i] = static_cast<int>(i);
        level_maps.push_back(map);
        for (size_t k = 0; k + 1 < ref.size() && why.empty(); ++k) {
            std::vector<int> next;
            why = match_next_level(map, our_origins[k], ref[k + 1], next);
            if (!why.empty()) why = "level " + std::to_string(k + 1) + ": " + why;
            map = std::move(next);
            level_maps.push_back(map);
        }
    }
    if (why.empty()) {
        Correspondence c;
        bool identity = true;
        for (size_t i = 0; i < map.size() && identity; ++i) identity = map[i] == static_cast<int>(i);
        c.method = identity ? MatchMethod::Order : MatchMethod::Topology;
        c.ref_to_ours = std::move(map);
        c.level_maps = std::move(level_maps);
        return c;
    }
    Correspondence c = match_nearest(our_last, ref.empty() ? std::vector<Vec3>{} : ref.back().positions);
    c.note = "topological matching failed (" + why + ")" + (c.note.empty() ? "" : "; " + c.note);
    return c;
}

PolyMesh renumber(const PolyMesh& mesh, const std::vector<int>& to_ours) {
    PolyMesh out = mesh;
    for (size_t i = 0; i < to_ours.size(); ++i) out.positions[static_cast<size_t>(to_ours[i])] = mesh.positions[i];
    if (mesh.colors.size() == to_ours.size())
        for (size_t i = 0; i < to_ours.size(); ++i) out.colors[static_cast<size_t>(to_ours[i])] = mesh.colors[i];
    for (int& v : out.face_vertices) v = to_ours[static_cast<size_t>(v)];
    out.source = {};
    return out;
}

std::vector<VertexOrigin> split_origins(int coarse_vertices, const PolyMesh& fine, std::string& why) {
    std::vector<VertexOrigin> origins(static_cast<size_t>(fine.num_vertices()), VertexOrigin{-1, -1});
    std::vector<int> old_count(origins.size(), 0);
    for (int v = 0; v < std::min(coarse_vertices, fine.num_vertices()); ++v) origins[v].a = v;
    for (auto [a, b] : mesh_topology(fine).edge_list) {
        if (a < coarse_vertices && b < coarse_vertices) {
            why = "old vertices " + std::to_string(a) + " and " + std::to_string(b) + " are adjacent";
            return {};
        }
        for (auto [v, w] : {std::pair{a, b}, std::pair{b, a}}) {
            if (v < coarse_vertices || w >= coarse_vertices) continue;
            if (++old_count[v] == 1) origins[v].a = w;
            else origins[v].b = w;
        }
    }
    for (size_t v = static_cast<size_t>(coarse_vertices); v < origins.size(); ++v)
        if (old_count[v] != 2) {
            why = "new vertex " + std::to_string(v) + " has " + std::to_string(old_count[v]) + " old neighbours";
            return {};
        }
    return origins;
}

Correspondence match_split_refinement(const adapters::LevelTrace& ours, const adapters::LevelTrace& ref) {
    std::vector<std::vector<VertexOrigin>> origins;
    for (size_t l = 1; l < ours.size(); ++l) {
        std::string why;
        origins.push_back(split_origins(ours[l - 1].num_vertices(), ours[l], why));
        if (origins.back().empty()) {
            Correspondence c;
            c.note = "our level " + std::to_string(l) + " is not a numbered 1-to-4 split: " + why;
            return c;
        }
    }
    if (ours.empty()) return {};
    return match_loop_refinement(origins, ours.front().positions, ref, ours.back().positions);
}

}  // namespace crossdiv::verification
