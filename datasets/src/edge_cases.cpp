#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/datasets/uv_layouts.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/disjoint_union.h"
#include "shapes.h"

namespace crossdiv::datasets {
using namespace shapes;
namespace {

std::vector<std::vector<int>> faces_of(const PolyMesh& m) {
    std::vector<std::vector<int>> f;
    for (int i = 0; i < m.num_faces(); ++i)
        f.emplace_back(m.face_vertices.begin() + m.face_start[i], m.face_vertices.begin() + m.face_start[i + 1]);
    return f;
}

PolyMesh transformed(PolyMesh m, double scale, const Vec3& offset) {
    for (Vec3& p : m.positions) p = p * scale + offset;
    return m;
}

/// `pages` triangles sharing the edge (0, 1): an open book, non-manifold for pages > 2.
PolyMesh book(int pages) {
    std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(0, 0, 1)};
    std::vector<std::vector<int>> f;
    for (int k = 0; k < pages; ++k) {
        const double a = 2 * M_PI * k / pages;
        p.emplace_back(std::cos(a), std::sin(a), 0.5);
        f.push_back(k % 2 ? std::vector<int>{0, 1, k + 2} : std::vector<int>{1, 0, k + 2});
    }
    return make(p, f);
}

/// `fans` fans of two triangles each, joined only at vertex 0 (the origin), each in its own
/// vertical plane around the z axis: a non-manifold vertex with `fans` fans.
PolyMesh bowtie(int fans) {
    std::vector<Vec3> p = {Vec3(0, 0, 0)};
    std::vector<std::vector<int>> f;
    for (int k = 0; k < fans; ++k) {
        const double a = 2 * M_PI * k / fans;
        const Vec3 out(std::cos(a), std::sin(a), 0);
        const int b = static_cast<int>(p.size());
        p.push_back(out + Vec3(0, 0, -0.5));
        p.push_back(out * 1.2);
        p.push_back(out + Vec3(0, 0, 0.5));
        f.push_back({0, b, b + 1});
        f.push_back({0, b + 1, b + 2});
    }
    return make(p, f);
}

/// Two open fans of four triangles, half discs on either side of the z axis with their
/// spokes bent alternately off the plane, joined only at vertex 0. Each fan's vertex 0 reads
/// as a boundary vertex of 4 faces, where the tuned Loop edge mask (loop_mask.h) departs
/// from Loop's on the middle spokes.
PolyMesh bowtie_of_open_fans() {
    std::vector<Vec3> p = {Vec3(0, 0, 0)};
    std::vector<std::vector<int>> f;
    for (const double side : {1.0, -1.0}) {
        const int b = static_cast<int>(p.size());
        for (int j = 0; j <= 4; ++j) {
            const double t = M_PI * (j / 4.0 - 0.5);
            // Unequal fans: no symmetry puts vertex 0 where another rule would.
            p.push_back(side > 0 ? Vec3(std::cos(t), 0.3 * (j % 2) + 0.1, std::sin(t))
                                 : Vec3(-0.8 * std::cos(t), 0.3 * (j % 2) - 0.25, 0.7 * std::sin(t) + 0.1));
        }
        for (int j = 0; j < 4; ++j) f.push_back({0, b + j, b + j + 1});
    }
    return make(p, f);
}

/// `sheets` strips of four triangles meeting along the bent seam p0-p1-p2: the two seam
/// edges are non-manifold, and p1 -- with more faces than edges and no boundary edge -- sits
/// on an interior non-manifold crease, which OpenSubdiv refines by the crease rule.
PolyMesh seam(int sheets) {
    std::vector<Vec3> p = {Vec3(0, 0, -1), Vec3(0.2, 0.1, 0), Vec3(0, 0, 1.3)};  // bent: crease and corner differ
    std::vector<std::vector<int>> f;
    for (int k = 0; k < sheets; ++k) {
        const double a = 2 * M_PI * k / sheets;
        const Vec3 d(std::cos(a), std::sin(a), 0);
        const int q = static_cast<int>(p.size());
        for (int i = 0; i < 3; ++i) p.push_back(p[static_cast<size_t>(i)] + d * (1.0 + 0.1 * i));
        f.push_back({0, 1, q + 1});
        f.push_back({0, q + 1, q});
        f.push_back({1, 2, q + 2});
        f.push_back({1, q + 2, q + 1});
    }
    return make(p, f);
}

PolyMesh with_faces_removed(const PolyMesh& m, const std::vector<int>& remove) {
    std::vector<std::vector<int>> f = faces_of(m);
    std::vector<std::vector<int>> kept;
    for (int i = 0; i < static_cast<int>(f.size()); ++i)
        if (std::find(remove.begin(), remove.end(), i) == remove.end()) kept.push_back(f[i]);
    return make(m.positions, kept);
}

}  // namespace

std::vector<EdgeCase> edge_cases() {
    std::vector<EdgeCase> all;
    auto add = [&all](std::string name, std::string description, bool valid, PolyMesh mesh) {
        mesh.source.file = "edgecase:" + name;
        all.push_back({std::move(name), std::move(description), valid, std::move(mesh)});
    };
    for (int n = 3; n <= 16; ++n)
        add("interior-fan-" + std::to_string(n), "one interior vertex of valence " + std::to_string(n), true, fan(n));
    add("interior-fan-360", "one interior vertex of valence 360", true, fan(360));
    for (int n : {8, 64, 360})
        add("pole-" + std::to_string(n), "closed, two poles of valence " + std::to_string(n), true, pole(n, 4));
    // The poles above have rings that are exact circles at one height, where the cos 2 theta
    // and cos 4 theta terms of the high-valence stencils (the modified Butterfly's, Loop's
    // beyond its table) sum to zero: an error in them cannot show. Here the rings are uneven.
    add("pole-7-uneven", "closed, two poles of valence 7 whose rings are not circles (radii and heights vary)", true, [] {
        PolyMesh m = pole(7, 4);
        for (size_t v = 1; v + 1 < m.positions.size(); ++v) {
            Vec3& p = m.positions[v];
            const double a = std::atan2(p.y(), p.x());
            p.x() *= 1.0 + 0.2 * std::cos(2.0 * a + 0.3);
            p.y() *= 1.0 + 0.15 * std::sin(3.0 * a);
            p.z() += 0.1 * std::cos(2.0 * a) + 0.05 * std::sin(a);
        }
        return m;
    }());
    for (int k = 1; k <= 8; ++k)
        add("boundary-fan-" + std::to_string(k),
            "one boundary vertex with " + std::to_string(k) + " incident face(s)" + (k == 1 ? " (a corner)" : ""), true,
            boundary_fan(k));
    add("corners-alternating", "3x3 quads, diagonals alternating: corners with one and with two faces", true,
        grid_patch(3, 3, [](double x, double y) { return 0.2 * x * y; }, true));
    add("single-triangle", "one triangle: three corners of one face each, no interior vertex", true,
        make({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.2, 1, 0.1)}, {{0, 1, 2}}));
    add("open-saddle", "8x8 quads on z = x^2 - y^2 (centred): an open saddle", true,
        grid_patch(8, 8, [](double x, double y) { return (x - 0.5) * (x - 0.5) - (y - 0.5) * (y - 0.5); }, false));
    add("monkey-saddle", "6x6 quads (interior valence 6) on the monkey saddle z = u^3 - 3uv^2", true,
        grid_patch(6, 6, [](double x, double y) {
            const double u = 2 * x - 1, v = 2 * y - 1;
            return u * u * u - 3 * u * v * v;
        }, false));
    add("valence-2", "two triangles back to back: closed, every vertex of valence 2", true, pillow());
    add("isolated-vertex", "tetrahedron plus one vertex no face uses", true, [] {
        PolyMesh m = tetrahedron();
        m.positions.emplace_back(3, 3, 3);
        return m;
    }());
    add("zero-area-triangle", "disc of three faces, one with three collinear vertices", true,
        make({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0.2)}, {{0, 2, 3}, {2, 1, 3}, {2, 0, 1}}));
    add("several-components", "two tetrahedra and an octahedron, apart", true,
        disjoint_union({tetrahedron(), transformed(tetrahedron(), 1.0, Vec3(4, 0, 0)), transformed(octahedron(), 1.0, Vec3(0, 4, 0))}));
    add("holes", "pole-8 sphere with three separate faces removed: three boundary loops", true,
        with_faces_removed(pole(8, 4), {0, 20, 45}));
    add("genus-3", "closed slab with three holes through it: Euler characteristic -4", true, slab_with_holes(3));
    add("slivers", "8x8 quads squeezed to 1e-6 in y: triangles of aspect ratio about 1e6", true, [] {
        PolyMesh m = grid_patch(8, 8, [](double x, double) { return 0.1 * x * x; }, false);
        for (Vec3& p : m.positions) p.y() *= 1e-6;
        return m;
    }());
    add("tiny-coordinates", "icosahedron scaled to 1e-8", true, transformed(icosahedron(), 1e-8, Vec3::Zero()));
    add("huge-coordinates", "icosahedron of size 1e8", true, transformed(icosahedron(), 1e8, Vec3::Zero()));
    add("far-from-origin", "unit icosahedron translated to (1e8, 1e8, 1e8): ulp(1e8) = 1.5e-8", true,
        transformed(icosahedron(), 1.0, Vec3(1e8, 1e8, 1e8)));
    add("near-coincident", "two tetrahedra whose nearest vertices are 1e-12 apart, not shared", true, [] {
        PolyMesh a = tetrahedron(), b = tetrahedron();
        const Vec3 offset = a.positions[0] - b.positions[3] + Vec3(1e-12, 0, 0);  // b's vertex 3 next to a's vertex 0
        return disjoint_union({a, transformed(b, 1.0, offset)});
    }());
    // Not manifold: core refines them by OpenSubdiv's non-manifold rules (nonmanifold.h), and
    // refuses them, naming the element, under NonManifoldRule::Refuse.
    for (int pages : {3, 4, 10, 100})
        add("nonmanifold-edge-" + std::to_string(pages), std::to_string(pages) + " triangles on one edge", false,
            book(pages));
    for (int fans : {3, 5})
        add("bowtie-" + std::to_string(fans), std::to_string(fans) + " fans of two triangles joined at one vertex", false,
            bowtie(fans));
    add("bowtie-open-fans", "two open fans of four triangles joined at one vertex: each fan read alone by the tuned edge mask",
        false, bowtie_of_open_fans());
    add("nonmanifold-seam", "three strips meeting along a two-edge seam: an interior non-manifold crease", false, seam(3));
    add("bowtie", "two fans joined at one vertex: a non-manifold vertex", false, [] {
        PolyMesh m = make({Vec3(0, 0, 0), Vec3(1, 0.5, 0), Vec3(1, -0.5, 0), Vec3(-1, 0.5, 0), Vec3(-1, -0.5, 0)},
                          {{0, 2, 1}, {0, 3, 4}});
        return m;
    }());
    add("duplicate-face", "tetrahedron with one face listed twice", false, [] {
        PolyMesh m = tetrahedron();
        m.add_face({0, 2, 1});
        return m;
    }());
    add("inconsistent-orientation", "4x4 grid with one interior triangle reversed", false, [] {
        std::vector<std::vector<int>> f = faces_of(open_patch(4));
        std::swap(f[10][1], f[10][2]);
        return make(open_patch(4).positions, f);
    }());
    add("repeated-vertex-triangle", "tetrahedron plus a triangle naming one vertex twice", false, [] {
        PolyMesh m = tetrahedron();
        m.add_face({0, 0, 1});
        return m;
    }());
    return all;
}

std::vector<EdgeCase> polygon_edge_cases() {
    std::vector<EdgeCase> all;
    auto add = [&all](std::string name, std::string description, bool manifold, PolyMesh mesh) {
        mesh.source.file = "edgecase:" + name;
        all.push_back({std::move(name), std::move(description), manifold, std::move(mesh)});
    };
    add("back-to-back-quads", "two quads on the same four vertices, opposite orders: closed, face points coincide", true,
        make({Vec3(0, 0, 0), Vec3(1, 0, 0.1), Vec3(1, 1, 0), Vec3(0, 1, 0.2)}, {{0, 1, 2, 3}, {3, 2, 1, 0}}));
    add("back-to-back-pentagons", "two pentagons on the same five vertices, opposite orders", true, [] {
        std::vector<Vec3> p;
        for (int k = 0; k < 5; ++k) p.emplace_back(std::cos(2 * M_PI * k / 5), std::sin(2 * M_PI * k / 5), 0.1 * k);
        return make(p, {{0, 1, 2, 3, 4}, {4, 3, 2, 1, 0}});
    }());
    add("holes-beside-creases", "4x4 quads, an interior hole whose edges carry creases of 1.5, 3 and infinite "
                                "sharpness, and a crease of 2 from it to the boundary", true, [] {
        PolyMesh m = quad_grid(4, 0.6);  // vertex (i, j) = 5j + i; face 5 = (6, 7, 12, 11)
        m.creases.holes = {5};
        m.creases.edges = {{6, 7, 1.5f}, {7, 12, 3.0f}, {12, 11, 10.0f}, {11, 6, 1.5f}, {12, 13, 2.0f}, {13, 14, 2.0f}};
        return m;
    }());
    add("nonmanifold-quad-edge-3", "three quads on one edge", false,
        make({Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 0, 0), Vec3(-0.5, 0.8, 1), Vec3(-0.5, 0.8, 0),
              Vec3(-0.5, -0.8, 1), Vec3(-0.5, -0.8, 0)},
             {{1, 0, 3, 2}, {0, 1, 4, 5}, {1, 0, 7, 6}}));
    add("duplicate-quad", "quad cube with one face listed twice", false, [] {
        PolyMesh m = quad_cube();
        m.add_face(std::vector<int>(m.face(0), m.face(0) + m.face_size(0)));
        return m;
    }());
    add("repeated-vertex-quad", "2x2 quads plus a quad naming a corner twice in a row (a degenerate edge)", false, [] {
        PolyMesh m = quad_grid(2, 0.3);  // vertex (i, j) = 3j + i
        m.positions.emplace_back(0.0, -1.0, 0.0);
        m.add_face({1, 0, 0, 9});
        return m;
    }());
    return all;
}

EdgeCase edge_case(const std::string& name) {
    std::string known;
    std::vector<EdgeCase> all = edge_cases();
    for (EdgeCase& c : polygon_edge_cases()) all.push_back(std::move(c));
    for (UvEdgeCase& c : uv_edge_cases()) all.push_back({c.name, c.description, c.name.ends_with("-tri"), std::move(c.mesh)});
    for (EdgeCase& c : all) {
        if (c.name == name) return std::move(c);
        known += (known.empty() ? "" : ", ") + c.name;
    }
    throw InputError("unknown edge case '" + name + "' (known: " + known + ")");
}

PolyMesh benchmark_mesh(int faces) {
    const int n = std::max(3, static_cast<int>(std::lround(std::sqrt(faces / 2.0))));
    PolyMesh m = irregular_torus(n, n);
    m.source.file = "benchmark:torus-" + std::to_string(2 * n * n);
    return m;
}

}  // namespace crossdiv::datasets
