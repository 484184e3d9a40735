#include "crossdiv/surfaces/surface_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

namespace {

using Cell = std::array<std::int64_t, 3>;

Cell cell_of(const Vec3& p, double h) {
    return {static_cast<std::int64_t>(std::floor(p.x() / h)), static_cast<std::int64_t>(std::floor(p.y() / h)),
            static_cast<std::int64_t>(std::floor(p.z() / h))};
}

int find(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

}  // namespace

std::vector<int> weld_classes(std::span<const Vec3> points, double tol) {
    const int n = static_cast<int>(points.size());
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    if (n == 0 || !(tol > 0)) return parent;
    const auto join = [&](int a, int b) {
        a = find(parent, a), b = find(parent, b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    };
    // Cells of side tol / 2: diameter tol * sqrt(3) / 2 < tol, and two points within tol lie
    // at most two cells apart on each axis.
    const double side = 0.5 * tol;
    std::vector<Cell> cells(n);
    for (int i = 0; i < n; ++i) cells[i] = cell_of(points[i], side);
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return cells[a] < cells[b] || (cells[a] == cells[b] && a < b); });
    // The distinct cells in order, each with its range in `order`.
    std::vector<Cell> cell_keys;
    std::vector<int> cell_start;
    for (int k = 0; k < n; ++k)
        if (k == 0 || cells[order[k]] != cells[order[k - 1]]) {
            cell_keys.push_back(cells[order[k]]);
            cell_start.push_back(k);
        }
    cell_start.push_back(n);
    const int num_cells = static_cast<int>(cell_keys.size());
    for (int c = 0; c < num_cells; ++c)
        for (int k = cell_start[c] + 1; k < cell_start[c + 1]; ++k) join(order[cell_start[c]], order[k]);
    const double tol2 = tol * tol;
    for (int c = 0; c < num_cells; ++c) {
        const Cell& key = cell_keys[c];
        for (std::int64_t dx = -2; dx <= 2; ++dx)
            for (std::int64_t dy = -2; dy <= 2; ++dy)
                for (std::int64_t dz = -2; dz <= 2; ++dz) {
                    const Cell other{key[0] + dx, key[1] + dy, key[2] + dz};
                    if (!(key < other)) continue;  // each pair of cells once
                    const auto it = std::lower_bound(cell_keys.begin() + c + 1, cell_keys.end(), other);
                    if (it == cell_keys.end() || *it != other) continue;
                    const int d = static_cast<int>(it - cell_keys.begin());
                    if (find(parent, order[cell_start[c]]) == find(parent, order[cell_start[d]])) continue;
                    // Each cell is one class: the first pair within tol joins them.
                    bool joined = false;
                    for (int a = cell_start[c]; a < cell_start[c + 1] && !joined; ++a)
                        for (int b = cell_start[d]; b < cell_start[d + 1] && !joined; ++b)
                            if ((points[order[a]] - points[order[b]]).squaredNorm() <= tol2) {
                                join(order[a], order[b]);
                                joined = true;
                            }
                }
    }
    for (int i = 0; i < n; ++i) parent[i] = find(parent, i);
    return parent;
}

void require_surface_size(long long triangles, long long limit, const std::string& what) {
    if (triangles > limit)
        throw InputError(what + " would have " + std::to_string(triangles) + " triangles, more than the limit of " +
                         std::to_string(limit) + " (--max-faces); use fewer steps or raise the limit");
}

double weld(SurfaceMesh& s, double tol) {
    TriMesh& m = s.mesh;
    // Every builder welds last: the one place to refuse a surface whose evaluation overflowed
    // (control points near DBL_MAX), before a NaN is written or an infinite tolerance welds
    // the whole model into one vertex.
    for (int v = 0; v < m.num_vertices(); ++v)
        if (!m.positions[v].allFinite())
            throw InputError("surface vertex " + std::to_string(v) + " is not finite: the model's coordinates overflow "
                             "double in the surface's sums, so scale it down");
    if (tol < 0) tol = kWeldRelative * bounding_box_diagonal(m.positions);
    if (!std::isfinite(tol))
        throw InputError("the surface's bounding box is larger than double can measure (its diagonal overflows): "
                         "scale the model down");
    const std::vector<int> cls = weld_classes(m.positions, tol);
    const int n = m.num_vertices();
    std::vector<int> new_index(n, -1);
    std::vector<Vec3> positions, normals;
    positions.reserve(n);
    normals.reserve(n);
    for (int v = 0; v < n; ++v) {
        if (cls[v] != v) continue;
        new_index[v] = static_cast<int>(positions.size());
        positions.push_back(m.positions[v]);
        normals.push_back(Vec3::Zero());
    }
    // The largest angle between normals averaged into one vertex, measured against the
    // class's first normal (enough to tell "these pieces meet smoothly" from "they do not").
    double max_angle = 0;
    for (int v = 0; v < n; ++v) {
        const int w = new_index[cls[v]];
        normals[w] += s.normals[v];
        if (cls[v] != v) {
            const Vec3& a = s.normals[cls[v]];
            const Vec3& b = s.normals[v];
            max_angle = std::max(max_angle, std::atan2(a.cross(b).norm(), a.dot(b)));
        }
    }
    for (Vec3& nv : normals) {
        const double len = nv.norm();
        if (len > 0) nv /= len;
    }
    std::vector<Triangle> triangles;
    triangles.reserve(m.triangles.size());
    for (const Triangle& t : m.triangles) {
        const Triangle u{new_index[cls[t[0]]], new_index[cls[t[1]]], new_index[cls[t[2]]]};
        if (u[0] == u[1] || u[1] == u[2] || u[2] == u[0]) {
            ++s.collapsed_triangles;
            continue;
        }
        triangles.push_back(u);
    }
    m.positions = std::move(positions);
    m.triangles = std::move(triangles);
    s.normals = std::move(normals);
    return max_angle;
}

std::vector<Vec3> face_normals(const TriMesh& mesh) {
    std::vector<Vec3> out(mesh.triangles.size(), Vec3::Zero());
    for (size_t f = 0; f < mesh.triangles.size(); ++f) {
        const Triangle& t = mesh.triangles[f];
        const Vec3 n = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
        const double len = n.norm();
        if (len > 0) out[f] = n / len;
    }
    return out;
}

double signed_volume(const TriMesh& mesh) {
    double six_v = 0;
    for (const Triangle& t : mesh.triangles)
        six_v += mesh.positions[t[0]].dot(mesh.positions[t[1]].cross(mesh.positions[t[2]]));
    return six_v / 6;
}

std::uint64_t edge_key(int a, int b) {
    return std::uint64_t{static_cast<std::uint32_t>(std::min(a, b))} << 32 | static_cast<std::uint32_t>(std::max(a, b));
}

int unpaired_edge_count(std::vector<std::uint64_t> edge_keys) {
    // After sorting, a key seen once is a boundary edge.
    std::sort(edge_keys.begin(), edge_keys.end());
    int unpaired = 0;
    for (size_t i = 0; i < edge_keys.size();) {
        size_t j = i;
        while (j < edge_keys.size() && edge_keys[j] == edge_keys[i]) ++j;
        unpaired += j - i == 1;
        i = j;
    }
    return unpaired;
}

int boundary_edge_count(const TriMesh& mesh) {
    std::vector<std::uint64_t> keys;
    keys.reserve(mesh.triangles.size() * 3);
    for (const Triangle& t : mesh.triangles)
        for (int j = 0; j < 3; ++j) keys.push_back(edge_key(t[j], t[(j + 1) % 3]));
    return unpaired_edge_count(std::move(keys));
}

}  // namespace crossdiv
