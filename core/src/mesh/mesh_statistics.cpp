#include "crossdiv/mesh/mesh_statistics.h"

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "crossdiv/error.h"

namespace crossdiv {
namespace {

/// Union-find with path halving over a flat array.
class DisjointSets {
public:
    explicit DisjointSets(int n) : parent_(static_cast<size_t>(n)) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int x) {
        while (parent_[static_cast<size_t>(x)] != x) x = parent_[static_cast<size_t>(x)] = parent_[static_cast<size_t>(parent_[static_cast<size_t>(x)])];
        return x;
    }
    void join(int a, int b) { parent_[static_cast<size_t>(find(a))] = find(b); }

private:
    std::vector<int> parent_;
};

/// One face side, its vertices in ascending order and whether the face runs it that way.
struct Side {
    int lo, hi, corner;
    bool ascending;
};

}  // namespace

MeshStatistics mesh_statistics(const PolyMesh& mesh) {
    MeshStatistics s;
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    s.vertices = nv;
    s.faces = nf;
    std::vector<char> proper(static_cast<size_t>(nf), 1), used(static_cast<size_t>(nv), 0);
    std::vector<int> scratch;
    for (int f = 0; f < nf; ++f) {
        const int* c = mesh.face(f);
        const int n = mesh.face_size(f);
        scratch.assign(c, c + n);
        for (int v : scratch)
            if (v < 0 || v >= nv)
                throw InputError("face " + std::to_string(f) + ": vertex index " + std::to_string(v) + " out of range (the mesh has " +
                                 std::to_string(nv) + " vertices)");
        std::sort(scratch.begin(), scratch.end());
        if (n < 3 || std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end()) {
            proper[static_cast<size_t>(f)] = 0;
            ++s.degenerate_faces;
        }
        if (n == 3) ++s.triangles;
        else if (n == 4) ++s.quads;
        else if (n > 4) ++s.larger_faces;
        for (int v : scratch) used[static_cast<size_t>(v)] = 1;
    }
    s.isolated_vertices = static_cast<int>(std::count(used.begin(), used.end(), 0));

    // Components: faces joined through their vertices.
    DisjointSets by_vertex(std::max(nv, 1));
    for (int f = 0; f < nf; ++f) {
        const int* c = mesh.face(f);
        for (int k = 1; k < mesh.face_size(f); ++k) by_vertex.join(c[0], c[k]);
    }
    std::vector<int> component(static_cast<size_t>(nv), -1);
    for (int v = 0; v < nv; ++v)
        if (used[static_cast<size_t>(v)]) {
            const int r = by_vertex.find(v);
            if (component[static_cast<size_t>(r)] < 0) component[static_cast<size_t>(r)] = s.components++;
            component[static_cast<size_t>(v)] = component[static_cast<size_t>(r)];
        }

    // Edges from the proper faces' sides, sorted by vertex pair.
    std::vector<Side> sides;
    for (int f = 0; f < nf; ++f) {
        if (!proper[static_cast<size_t>(f)]) continue;
        const int start = mesh.face_start[f], n = mesh.face_size(f);
        for (int k = 0; k < n; ++k) {
            const int a = mesh.face_vertices[start + k], b = mesh.face_vertices[start + (k + 1) % n];
            sides.push_back({std::min(a, b), std::max(a, b), start + k, a < b});
        }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi; });
    // Corners around a vertex in one fan: the corners of two faces across a two-sided edge, at
    // each of its ends, are joined.
    const int corners = static_cast<int>(mesh.face_vertices.size());
    DisjointSets fans(std::max(corners, 1));
    std::vector<int> corner_face(static_cast<size_t>(corners));
    for (int f = 0; f < nf; ++f)
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) corner_face[static_cast<size_t>(c)] = f;
    const auto next_corner = [&](int c) {
        const int f = corner_face[static_cast<size_t>(c)];
        return c + 1 < mesh.face_start[f + 1] ? c + 1 : mesh.face_start[f];
    };
    std::vector<int> edges_of(static_cast<size_t>(s.components), 0), boundary_at(static_cast<size_t>(nv), 0);
    DisjointSets loops(std::max(nv, 1));
    for (size_t i = 0; i < sides.size();) {
        size_t j = i;
        while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
        const int count = static_cast<int>(j - i);
        ++s.edges;
        ++edges_of[static_cast<size_t>(component[static_cast<size_t>(sides[i].lo)])];
        if (count == 1) {
            ++s.boundary_edges;
            ++boundary_at[static_cast<size_t>(sides[i].lo)];
            ++boundary_at[static_cast<size_t>(sides[i].hi)];
            loops.join(sides[i].lo, sides[i].hi);
        } else if (count > 2) {
            ++s.non_manifold_edges;
        } else {
            if (sides[i].ascending == sides[i + 1].ascending) ++s.inconsistent_edges;
            // The corner of each face at each end of the edge.
            const int c0 = sides[i].corner, c1 = sides[i + 1].corner;
            const int n0 = next_corner(c0), n1 = next_corner(c1);
            const int v0 = mesh.face_vertices[static_cast<size_t>(c0)], v1 = mesh.face_vertices[static_cast<size_t>(c1)];
            fans.join(c0, v0 == v1 ? c1 : n1);
            fans.join(n0, v0 == v1 ? n1 : c1);
        }
        i = j;
    }
    // Fans per vertex: the distinct roots among its corners.
    std::vector<std::pair<int, int>> vertex_fan;
    vertex_fan.reserve(static_cast<size_t>(corners));
    for (int f = 0; f < nf; ++f)
        if (proper[static_cast<size_t>(f)])
            for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c)
                vertex_fan.emplace_back(mesh.face_vertices[static_cast<size_t>(c)], fans.find(c));
    std::sort(vertex_fan.begin(), vertex_fan.end());
    vertex_fan.erase(std::unique(vertex_fan.begin(), vertex_fan.end()), vertex_fan.end());
    for (size_t i = 0; i + 1 < vertex_fan.size(); ++i)
        if (vertex_fan[i].first == vertex_fan[i + 1].first && (i == 0 || vertex_fan[i - 1].first != vertex_fan[i].first))
            ++s.non_manifold_vertices;

    // Euler characteristic, boundary loops and genus per component.
    std::vector<int> vertices_of(static_cast<size_t>(s.components), 0), faces_of(static_cast<size_t>(s.components), 0),
        loops_of(static_cast<size_t>(s.components), 0);
    std::vector<char> loop_counted(static_cast<size_t>(nv), 0);
    bool boundary_manifold = true;
    for (int v = 0; v < nv; ++v) {
        if (!used[static_cast<size_t>(v)]) continue;
        ++vertices_of[static_cast<size_t>(component[static_cast<size_t>(v)])];
        const int b = boundary_at[static_cast<size_t>(v)];
        if (b == 0) continue;
        if (b != 2) boundary_manifold = false;
        const int r = loops.find(v);
        if (!loop_counted[static_cast<size_t>(r)]) {
            loop_counted[static_cast<size_t>(r)] = 1;
            ++s.boundary_loops;
            ++loops_of[static_cast<size_t>(component[static_cast<size_t>(v)])];
        }
    }
    int proper_faces = 0;
    for (int f = 0; f < nf; ++f)
        if (proper[static_cast<size_t>(f)]) {
            ++proper_faces;
            ++faces_of[static_cast<size_t>(component[static_cast<size_t>(mesh.face(f)[0])])];
        }
    s.euler_characteristic = (nv - s.isolated_vertices) - s.edges + proper_faces;
    const bool surface = s.degenerate_faces == 0 && s.non_manifold_edges == 0 && s.non_manifold_vertices == 0 &&
                         s.inconsistent_edges == 0 && boundary_manifold;
    if (surface) {
        s.genus = 0;
        for (int k = 0; k < s.components; ++k) {
            const int twice = 2 - (vertices_of[static_cast<size_t>(k)] - edges_of[static_cast<size_t>(k)] + faces_of[static_cast<size_t>(k)]) -
                              loops_of[static_cast<size_t>(k)];
            if (twice < 0 || twice % 2 != 0) {
                s.genus = -1;
                break;
            }
            s.genus += twice / 2;
        }
    }
    return s;
}

}  // namespace crossdiv
