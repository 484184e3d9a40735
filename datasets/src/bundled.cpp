#include "crossdiv/datasets/bundled.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv::datasets {
namespace {

PolyMesh make(std::vector<Vec3> positions, const std::vector<std::vector<int>>& faces) {
    PolyMesh m;
    m.positions = std::move(positions);
    for (const auto& f : faces) m.add_face(f);
    return m;
}

PolyMesh tetrahedron() {
    return make({Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)},
                {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
}

PolyMesh octahedron() {
    return make({Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)},
                {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

PolyMesh icosahedron() {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    return make({Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0), Vec3(0, -1, t), Vec3(0, 1, t),
                 Vec3(0, -1, -t), Vec3(0, 1, -t), Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)},
                {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}});
}

// The unit cube's 8 corners and its 6 faces as outward quads (functions, not globals, so
// that test registration during static initialisation can already build the catalog).
std::vector<Vec3> cube_corners() {
    return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
            Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
}
std::vector<std::vector<int>> cube_quads() {
    return {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
}

PolyMesh cube_symmetric() {  // each face split into 4 triangles around its centre
    std::vector<Vec3> p = cube_corners();
    std::vector<std::vector<int>> f;
    for (const auto& q : cube_quads()) {
        const int c = static_cast<int>(p.size());
        p.push_back((p[q[0]] + p[q[1]] + p[q[2]] + p[q[3]]) / 4.0);
        for (int k = 0; k < 4; ++k) f.push_back({q[k], q[(k + 1) % 4], c});
    }
    return make(p, f);
}

PolyMesh cube_asymmetric() {  // each face split by one diagonal: valences 3 to 6
    std::vector<std::vector<int>> f;
    for (const auto& q : cube_quads()) {
        f.push_back({q[0], q[1], q[2]});
        f.push_back({q[0], q[2], q[3]});
    }
    return make(cube_corners(), f);
}

// A (n+1) x (n+1) grid over [0,1]^2 with a height field, quads split along one diagonal:
// two of its corners have one incident face and two have two.
PolyMesh open_patch(int n) {
    std::vector<Vec3> p;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double x = double(i) / n, y = double(j) / n;
            p.emplace_back(x, y, 0.3 * std::sin(3.0 * x) * std::cos(2.0 * y) + 0.1 * x * y);
        }
    std::vector<std::vector<int>> f;
    auto id = [n](int i, int j) { return i * (n + 1) + j; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            f.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return make(p, f);
}

PolyMesh torus(int nu, int nv, double R, double r) {
    std::vector<Vec3> p;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            p.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
        }
    std::vector<std::vector<int>> f;
    auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            f.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return make(p, f);
}

// One interior vertex of valence n (raised above its ring) and its ring on the unit circle,
// wobbled so that no symmetry hides an index error.
PolyMesh fan(int n) {
    std::vector<Vec3> p = {Vec3(0, 0, 0.5)};
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n;
        p.emplace_back(std::cos(a), std::sin(a), 0.1 * std::sin(3.0 * a + 0.5));
    }
    std::vector<std::vector<int>> f;
    for (int k = 0; k < n; ++k) f.push_back({0, 1 + k, 1 + (k + 1) % n});
    return make(p, f);
}

// A closed sphere-like mesh with two poles of valence n: n meridians, `rings` parallels.
PolyMesh pole(int n, int rings) {
    std::vector<Vec3> p = {Vec3(0, 0, 1)};
    for (int r = 1; r <= rings; ++r)
        for (int k = 0; k < n; ++k) {
            const double t = M_PI * r / (rings + 1), a = 2 * M_PI * k / n;
            p.emplace_back(std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t));
        }
    const int south = static_cast<int>(p.size());
    p.emplace_back(0, 0, -1);
    auto id = [n](int r, int k) { return 1 + (r - 1) * n + (k % n); };
    std::vector<std::vector<int>> f;
    for (int k = 0; k < n; ++k) f.push_back({0, id(1, k), id(1, k + 1)});
    for (int r = 1; r < rings; ++r)
        for (int k = 0; k < n; ++k) {
            f.push_back({id(r, k), id(r + 1, k), id(r + 1, k + 1)});
            f.push_back({id(r, k), id(r + 1, k + 1), id(r, k + 1)});
        }
    for (int k = 0; k < n; ++k) f.push_back({south, id(rings, k + 1), id(rings, k)});
    return make(p, f);
}

std::vector<std::string> files_in(const std::filesystem::path& dir, const std::string& ext) {
    std::vector<std::string> out;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return out;  // optional data: absent is fine
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.path().extension() == ext) out.push_back(e.path().lexically_normal().string());
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

std::vector<BundledMesh> bundled_meshes() {
    std::vector<BundledMesh> all = {
        {"tetrahedron", "closed, every vertex of valence 3", tetrahedron()},
        {"octahedron", "closed, every vertex of valence 4", octahedron()},
        {"icosahedron", "closed, every vertex of valence 5", icosahedron()},
        {"cube-symmetric", "closed cube, faces split in 4 around a centre: valences 4 and 6", cube_symmetric()},
        {"cube-asymmetric", "closed cube, faces split by one diagonal: valences 3 to 6", cube_asymmetric()},
        {"open-patch", "4x4-quad grid, triangulated: boundary, two one-face corners", open_patch(4)},
        {"torus", "closed genus-1 surface, regular (valence 6)", torus(12, 8, 1.0, 0.4)},
    };
    for (int n = 3; n <= 12; ++n)
        all.push_back({"fan-" + std::to_string(n), "one interior vertex of valence " + std::to_string(n) +
                                                       " inside a boundary ring", fan(n)});
    all.push_back({"pole-64", "closed, two poles of valence 64", pole(64, 6)});
    for (BundledMesh& b : all) b.mesh.source.file = "bundled:" + b.name;
    return all;
}

PolyMesh bundled_mesh(const std::string& name) {
    std::string known;
    for (BundledMesh& b : bundled_meshes()) {
        if (b.name == name) return std::move(b.mesh);
        known += (known.empty() ? "" : ", ") + b.name;
    }
    throw InputError("unknown bundled mesh '" + name + "' (known: " + known + ")");
}

std::vector<std::string> cgal_mesh_files() { return files_in(std::filesystem::path(CROSSDIV_DATASETS_DIR) / "cgal", ".off"); }

std::vector<std::string> course_mesh_files() {
    return files_in(std::filesystem::path(CROSSDIV_SHARED_DATA) / "c3100" / "objs", ".obj");
}

}  // namespace crossdiv::datasets
