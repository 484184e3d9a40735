// Crease-tagged meshes: the catalog of the crease comparison and of the crease-cube figure.
// Every tag names an edge by its two vertices, as OpenSubdiv's shape files do.
#include <algorithm>
#include <functional>
#include <utility>

#include "crossdiv/datasets/bundled.h"
#include "shapes.h"

namespace crossdiv::datasets {
namespace {

using namespace shapes;

/// Tags, once each, every edge of `m` whose two end positions satisfy `pick`.
void tag_edges(PolyMesh& m, const std::function<bool(const Vec3&, const Vec3&)>& pick, float s) {
    std::vector<std::pair<int, int>> edges;
    for (int f = 0; f < m.num_faces(); ++f)
        for (int k = 0; k < m.face_size(f); ++k) {
            const int a = m.face(f)[k], b = m.face(f)[(k + 1) % m.face_size(f)];
            if (pick(m.positions[a], m.positions[b])) edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (auto [a, b] : edges) m.creases.edges.push_back({a, b, s});
}

void tag_all_edges(PolyMesh& m, float s) {
    tag_edges(m, [](const Vec3&, const Vec3&) { return true; }, s);
}

BundledMesh entry(std::string name, std::string description, PolyMesh m) {
    m.source.file = "bundled:" + name;
    return {std::move(name), std::move(description), std::move(m)};
}

}  // namespace

PolyMesh crease_cube(CreaseCubeVariant variant) {
    PolyMesh m = quad_cube();
    switch (variant) {
        case CreaseCubeVariant::Smooth: break;
        case CreaseCubeVariant::SharpTop:
            tag_edges(m, [](const Vec3& a, const Vec3& b) { return a.z() == 1 && b.z() == 1; }, 10.0f);
            break;
        case CreaseCubeVariant::SemiSharp: tag_all_edges(m, 2.0f); break;
        case CreaseCubeVariant::Sharp: tag_all_edges(m, 10.0f); break;
    }
    return m;
}

std::vector<BundledMesh> crease_meshes() {
    std::vector<BundledMesh> all;
    // Catmull-Clark (any polygon).
    all.push_back(entry("crease-cube-sharp", "quad cube, all 12 edges infinitely sharp: every vertex a corner",
                        crease_cube(CreaseCubeVariant::Sharp)));
    all.push_back(entry("crease-cube-top", "quad cube, the 4 edges of the top face infinitely sharp",
                        crease_cube(CreaseCubeVariant::SharpTop)));
    all.push_back(entry("crease-cube-semi", "quad cube, all edges of sharpness 2: two sharp levels, then smooth",
                        crease_cube(CreaseCubeVariant::SemiSharp)));
    {
        PolyMesh m = quad_cube();
        tag_edges(m, [](const Vec3& a, const Vec3& b) { return a.z() == 1 && b.z() == 1; }, 0.5f);
        tag_edges(m, [](const Vec3& a, const Vec3& b) { return a.z() == -1 && b.z() == -1; }, 1.5f);
        tag_edges(m, [](const Vec3& a, const Vec3& b) { return a.z() != b.z(); }, 2.7f);
        m.creases.vertices.push_back({0, 1.5f});
        m.creases.vertices.push_back({6, 0.25f});
        all.push_back(entry("crease-cube-fractional",
                            "quad cube, edges of sharpness 0.5, 1.5 and 2.7, corners of 1.5 and 0.25: transitions",
                            std::move(m)));
    }
    {
        // Sharpness varying along the top loop (1, 2, 3, 4) and 1.2 next to 0.2 along the
        // bottom: under Chaikin decay the 1.2 edge turns smooth in one step.
        PolyMesh m = quad_cube();
        m.creases.edges = {{4, 5, 1.0f}, {5, 7, 2.0f}, {7, 6, 3.0f}, {6, 4, 4.0f},
                           {0, 1, 1.2f}, {1, 3, 0.2f}, {3, 2, 1.2f}, {2, 0, 0.2f}};
        all.push_back(entry("crease-cube-varying", "quad cube, sharpness varying along two crease loops", std::move(m)));
    }
    {
        PolyMesh m = quad_grid(4, 0.6);
        tag_edges(m, [](const Vec3& a, const Vec3& b) { return a.y() == 0 && b.y() == 0; }, 10.0f);
        tag_edges(m, [](const Vec3& a, const Vec3& b) {
            return a.y() == 0.25 && b.y() == 0.25 && std::max(a.x(), b.x()) == 0.25 && std::min(a.x(), b.x()) == 0;
        }, 3.0f);
        all.push_back(entry("crease-grid-line",
                            "open quad grid, a sharp line from border to border (corners where it meets the "
                            "border) and a sharp edge ending inside (darts)",
                            std::move(m)));
    }
    {
        PolyMesh m = quad_torus(12, 8);
        for (int j = 0; j < 8; ++j) m.creases.edges.push_back({j, (j + 1) % 8, 10.0f});
        for (int i = 0; i < 12; i += 2) m.creases.edges.push_back({i * 8, ((i + 1) % 12) * 8, 1.5f});
        all.push_back(entry("crease-torus-loops",
                            "quad torus, one meridian infinitely sharp and every other edge of a parallel at 1.5",
                            std::move(m)));
    }
    {
        PolyMesh m = prism(5);
        m.creases.vertices = {{0, 10.0f}, {3, 0.7f}};
        all.push_back(entry("crease-prism-corners", "pentagonal prism, one sharp corner and one of sharpness 0.7",
                            std::move(m)));
    }
    // Loop (triangles).
    {
        PolyMesh m = octahedron();
        tag_edges(m, [](const Vec3& a, const Vec3& b) { return a.z() == 0 && b.z() == 0; }, 10.0f);
        all.push_back(entry("crease-octahedron-equator", "octahedron, the equator infinitely sharp", std::move(m)));
    }
    {
        PolyMesh m = octahedron();
        tag_all_edges(m, 1.5f);
        m.creases.vertices.push_back({4, 2.0f});
        all.push_back(entry("crease-octahedron-semi", "octahedron, all edges 1.5 and a pole corner of 2", std::move(m)));
    }
    {
        PolyMesh m = icosahedron();
        m.creases.edges = {{0, 11, 0.3f}, {11, 5, 1.2f}, {5, 1, 2.5f}, {1, 0, 4.0f}};
        all.push_back(entry("crease-icosahedron-loop", "icosahedron, a crease loop of sharpness 0.3, 1.2, 2.5, 4",
                            std::move(m)));
    }
    {
        PolyMesh m = open_patch(6);
        tag_edges(m, [](const Vec3& a, const Vec3& b) { return a.x() == 0.5 && b.x() == 0.5; }, 2.0f);
        m.creases.edges.push_back({1 * 7 + 2, 2 * 7 + 3, 10.0f});  // a diagonal inside: darts
        all.push_back(entry("crease-patch-line", "open triangle patch, a line of sharpness 2 across it and a sharp "
                                                 "interior diagonal",
                            std::move(m)));
    }
    {
        PolyMesh m = torus(8, 6, 1.0, 0.35);
        for (int j = 0; j < 6; ++j) m.creases.edges.push_back({j, (j + 1) % 6, 10.0f});
        for (int i = 0; i < 8; ++i) m.creases.edges.push_back({i * 6, ((i + 1) % 8) * 6, 0.8f});
        all.push_back(entry("crease-torus-tri", "triangle torus, a sharp meridian crossing a parallel of 0.8",
                            std::move(m)));
    }
    return all;
}

}  // namespace crossdiv::datasets
