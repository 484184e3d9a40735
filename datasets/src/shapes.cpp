#include "shapes.h"

#include <cmath>
#include <functional>

namespace crossdiv::datasets::shapes {

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

namespace {

// The unit cube's 8 corners and its 6 faces as outward quads (functions, not globals, so
// that test registration during static initialisation can already build the catalog).
std::vector<Vec3> cube_corners() {
    return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
            Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
}
std::vector<std::vector<int>> cube_quads() {
    return {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
}

}  // namespace

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

namespace {
/// Quad (a, b, c, d), counterclockwise, as two triangles split along a-c, or b-d if `other`.
void split_quad(std::vector<std::vector<int>>& f, int a, int b, int c, int d, bool other) {
    if (other) {
        f.push_back({a, b, d});
        f.push_back({b, c, d});
    } else {
        f.push_back({a, b, c});
        f.push_back({a, c, d});
    }
}
}  // namespace

PolyMesh grid_patch(int nx, int ny, const std::function<double(double, double)>& height, bool alternate_diagonals) {
    std::vector<Vec3> p;
    for (int i = 0; i <= nx; ++i)
        for (int j = 0; j <= ny; ++j) {
            const double x = double(i) / nx, y = double(j) / ny;
            p.emplace_back(x, y, height(x, y));
        }
    auto id = [ny](int i, int j) { return i * (ny + 1) + j; };
    std::vector<std::vector<int>> f;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j) {
            split_quad(f, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), alternate_diagonals && (i + j) % 2);
        }
    return make(p, f);
}

PolyMesh boundary_fan(int k) {
    // The ring spans 3/4 of a turn whatever k is, so the fan never closes up.
    std::vector<Vec3> p = {Vec3(0, 0, 0.3)};
    for (int i = 0; i <= k; ++i) {
        const double a = 1.5 * M_PI * i / k;
        p.emplace_back(std::cos(a), std::sin(a), 0.1 * std::cos(2.0 * a));
    }
    std::vector<std::vector<int>> f;
    for (int i = 0; i < k; ++i) f.push_back({0, 1 + i, 2 + i});
    return make(p, f);
}

PolyMesh pillow() {
    return make({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 1, 0.2)}, {{0, 1, 2}, {0, 2, 1}});
}

PolyMesh slab_with_holes(int holes) {
    // Cells (i, j) of a (2 holes + 1) x 3 grid; the holes are the cells (2h + 1, 1), each
    // surrounded by solid cells, so every vertex stays manifold.
    const int W = 2 * holes + 1, H = 3;
    auto solid = [&](int i, int j) { return i >= 0 && j >= 0 && i < W && j < H && !(j == 1 && i % 2 == 1); };
    auto id = [&](int i, int j, int z) { return (i * (H + 1) + j) * 2 + z; };
    std::vector<Vec3> p;
    for (int i = 0; i <= W; ++i)
        for (int j = 0; j <= H; ++j)
            for (int z = 0; z < 2; ++z) p.emplace_back(i, j, 0.8 * z);
    std::vector<std::vector<int>> f;
    auto quad = [&f](int a, int b, int c, int d) { split_quad(f, a, b, c, d, false); };
    for (int i = 0; i < W; ++i)
        for (int j = 0; j < H; ++j) {
            if (!solid(i, j)) continue;
            quad(id(i, j, 1), id(i + 1, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1));  // top, +z
            quad(id(i, j, 0), id(i, j + 1, 0), id(i + 1, j + 1, 0), id(i + 1, j, 0));  // bottom, -z
            // The cell's corners counterclockwise seen from above; a wall stands on every
            // side whose neighbour is not solid, facing away from this cell.
            const int ci[5] = {i, i + 1, i + 1, i, i}, cj[5] = {j, j, j + 1, j + 1, j};
            const int ni[4] = {i, i + 1, i, i - 1}, nj[4] = {j - 1, j, j + 1, j};
            for (int s = 0; s < 4; ++s)
                if (!solid(ni[s], nj[s]))
                    quad(id(ci[s], cj[s], 0), id(ci[s + 1], cj[s + 1], 0), id(ci[s + 1], cj[s + 1], 1),
                         id(ci[s], cj[s], 1));
        }
    return make(p, f);
}

PolyMesh irregular_torus(int nu, int nv) {
    std::vector<Vec3> p;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            const double r = 0.35 + 0.05 * std::sin(5 * u);
            p.emplace_back((1 + r * std::cos(v)) * std::cos(u), (1 + r * std::cos(v)) * std::sin(u), r * std::sin(v));
        }
    auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    std::vector<std::vector<int>> f;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            // A fixed hash picks the diagonal, so valences range over 4..8 as on scanned meshes.
            split_quad(f, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), (i * 7 + j * 13 + (i * j) % 5) % 3 == 0);
        }
    return make(p, f);
}

PolyMesh quad_cube() {
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    return make(p, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}});
}

PolyMesh quad_grid(int n, double bend) {
    std::vector<Vec3> p;
    std::vector<std::vector<int>> f;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = double(i) / n - 0.5, y = double(j) / n - 0.5;
            p.emplace_back(x, y, bend * (x * x - y * y));
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            f.push_back({a, a + 1, a + n + 2, a + n + 1});
        }
    return make(p, f);
}

PolyMesh quad_torus(int nu, int nv) {
    std::vector<Vec3> p;
    std::vector<std::vector<int>> f;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            const double r = 0.4 + 0.05 * std::sin(3 * u);  // not a surface of revolution: no symmetric ties
            p.emplace_back((1 + r * std::cos(v)) * std::cos(u), (1 + r * std::cos(v)) * std::sin(u), r * std::sin(v));
        }
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const int i1 = (i + 1) % nu, j1 = (j + 1) % nv;
            f.push_back({i * nv + j, i1 * nv + j, i1 * nv + j1, i * nv + j1});
        }
    return make(p, f);
}

PolyMesh prism(int n) {
    std::vector<Vec3> p;
    for (int z = 0; z < 2; ++z)
        for (int k = 0; k < n; ++k)
            p.emplace_back(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), z ? 1.3 : -0.7);
    std::vector<std::vector<int>> f;
    std::vector<int> bottom, top;
    for (int k = 0; k < n; ++k) {
        bottom.push_back(n - 1 - k);
        top.push_back(n + k);
        f.push_back({k, (k + 1) % n, n + (k + 1) % n, n + k});
    }
    f.push_back(bottom);
    f.push_back(top);
    return make(p, f);
}

PolyMesh quad_fan(int n) {
    std::vector<Vec3> p{Vec3(0, 0, 0.3)};
    std::vector<std::vector<int>> f;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * M_PI * k / n, b = a + M_PI / n;
        p.emplace_back(std::cos(a), std::sin(a), 0);                     // spoke end 1 + 2k
        p.emplace_back(1.2 * std::cos(b), 1.2 * std::sin(b), 0.1);      // rim between spokes 2 + 2k
    }
    for (int k = 0; k < n; ++k) f.push_back({0, 1 + 2 * k, 2 + 2 * k, 1 + 2 * ((k + 1) % n)});
    return make(p, f);
}

}  // namespace crossdiv::datasets::shapes
