#include "crossdiv/mesh/vertex_fans.h"

#include <algorithm>
#include <numeric>

namespace crossdiv {
namespace {

/// Union-find over corners, with path halving.
int find(std::vector<int>& parent, int c) {
    while (parent[static_cast<size_t>(c)] != c) {
        parent[static_cast<size_t>(c)] = parent[static_cast<size_t>(parent[static_cast<size_t>(c)])];
        c = parent[static_cast<size_t>(c)];
    }
    return c;
}

}  // namespace

PolyMesh split_vertex_fans(const PolyMesh& mesh, std::vector<int>* original) {
    const int corners = static_cast<int>(mesh.face_vertices.size());
    std::vector<int> next(static_cast<size_t>(corners));
    for (int f = 0; f < mesh.num_faces(); ++f)
        for (int c = mesh.face_start[f], end = mesh.face_start[f + 1]; c < end; ++c) next[static_cast<size_t>(c)] = c + 1 < end ? c + 1 : mesh.face_start[f];

    // Half-edges by their undirected edge: an edge with exactly two, running opposite ways,
    // joins the corners at each of its ends.
    struct HalfEdge {
        int lo, hi, corner;
    };
    std::vector<HalfEdge> half(static_cast<size_t>(corners));
    for (int c = 0; c < corners; ++c) {
        const int a = mesh.face_vertices[static_cast<size_t>(c)], b = mesh.face_vertices[static_cast<size_t>(next[static_cast<size_t>(c)])];
        half[static_cast<size_t>(c)] = {std::min(a, b), std::max(a, b), c};
    }
    std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.corner < y.corner;
    });
    std::vector<int> parent(static_cast<size_t>(corners));
    std::iota(parent.begin(), parent.end(), 0);
    const auto join = [&](int x, int y) { parent[static_cast<size_t>(find(parent, x))] = find(parent, y); };
    for (size_t i = 0; i < half.size();) {
        size_t j = i;
        while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
        if (j - i == 2) {
            const int c1 = half[i].corner, c2 = half[i + 1].corner;  // c1: a -> b; c2 should run b -> a
            if (mesh.face_vertices[static_cast<size_t>(c1)] != mesh.face_vertices[static_cast<size_t>(c2)]) {
                join(c1, next[static_cast<size_t>(c2)]);  // both at a
                join(c2, next[static_cast<size_t>(c1)]);  // both at b
            }
        }
        i = j;
    }

    PolyMesh out = mesh;
    std::vector<int> vertex_of_root(static_cast<size_t>(corners), -1);
    std::vector<char> taken(static_cast<size_t>(mesh.num_vertices()), 0);
    if (original) {
        original->resize(static_cast<size_t>(mesh.num_vertices()));
        std::iota(original->begin(), original->end(), 0);
    }
    for (int c = 0; c < corners; ++c) {
        const int v = mesh.face_vertices[static_cast<size_t>(c)];
        int& copy = vertex_of_root[static_cast<size_t>(find(parent, c))];
        if (copy < 0) {
            if (!taken[static_cast<size_t>(v)]) {
                taken[static_cast<size_t>(v)] = 1;
                copy = v;
            } else {
                copy = out.num_vertices();
                out.positions.push_back(mesh.positions[static_cast<size_t>(v)]);
                if (!out.colors.empty()) out.colors.push_back(mesh.colors[static_cast<size_t>(v)]);
                if (original) original->push_back(v);
            }
        }
        out.face_vertices[static_cast<size_t>(c)] = copy;
    }
    out.derived = {};
    return out;
}

}  // namespace crossdiv
