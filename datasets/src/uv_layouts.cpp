#include "crossdiv/datasets/uv_layouts.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace crossdiv::datasets {

std::array<double, 2> uv_of_position(const Vec3& p) {
    return {p.x() + 0.37 * p.y() * p.y() - 0.11 * p.z(), p.y() - 0.23 * p.x() * p.z() + 0.05 * p.x() * p.x()};
}

PolyMesh with_uv_regions(const PolyMesh& mesh, const std::vector<int>& face_region) {
    PolyMesh out = mesh;
    out.face_varying.clear();
    FaceVaryingChannel uv;
    uv.corner_values.resize(mesh.face_vertices.size());
    int regions = 1;
    for (int r : face_region) regions = std::max(regions, r + 1);
    std::vector<int> value(static_cast<size_t>(mesh.num_vertices()) * regions, -1);
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int r = face_region.at(static_cast<size_t>(f));
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
            const int v = mesh.face_vertices[c];
            int& slot = value[static_cast<size_t>(v) * regions + r];
            if (slot < 0) {
                const std::array<double, 2> t = uv_of_position(mesh.positions[v]);
                uv.values.push_back(t[0] + 0.5 * r);
                uv.values.push_back(t[1] + 0.3 * r);
                slot = uv.num_values() - 1;
            }
            uv.corner_values[c] = slot;
        }
    }
    out.face_varying.push_back(std::move(uv));
    return out;
}

namespace {

/// The 4 x 4 grid of unit quads in the plane z = 0 (vertex (i, j) is 5 j + i), faces row by
/// row; with `triangles`, each quad split along its diagonal from (i, j) to (i+1, j+1).
PolyMesh grid(bool triangles) {
    PolyMesh m;
    for (int j = 0; j <= 4; ++j)
        for (int i = 0; i <= 4; ++i) m.positions.emplace_back(i, j, 0.1 * ((i * i + 2 * j) % 3));
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const int a = 5 * j + i, b = a + 1, c = a + 6, d = a + 5;
            if (triangles) {
                m.add_face({a, b, c});
                m.add_face({a, c, d});
            } else {
                m.add_face({a, b, c, d});
            }
        }
    return m;
}

}  // namespace

std::vector<UvEdgeCase> uv_edge_cases() {
    // Regions per quad, row by row from y = 0 ('0'..'9'; 'x': every corner its own value).
    struct Layout {
        const char* name;
        const char* description;
        const char* regions;
        float crease;  ///< sharpness of the seam's edges (0: none), the seam being x = 2
    };
    const Layout layouts[] = {
        {"uv-seam", "a seam across the grid, boundary to boundary (x = 2)", "0011" "0011" "0011" "0011", 0},
        {"uv-dart", "a seam from the boundary ending inside the grid (a dart at (2, 2))", "0011" "0011" "0000" "0000", 0},
        {"uv-inner-seam", "a seam inside the grid only, ending in two darts", "0000" "0110" "0000" "0000", 0},
        {"uv-junction", "three UV regions meeting at an interior vertex (2, 2)", "0011" "0011" "2222" "2222", 0},
        {"uv-island", "a one-face UV island inside the grid: four UV corners", "0000" "0100" "0000" "0000", 0},
        {"uv-bowtie", "a region touching itself at one vertex only: a value of two disjoint spans", "0000" "0100" "0010" "0000", 0},
        {"uv-sharp-seam", "a seam along an infinitely sharp crease", "0011" "0011" "0011" "0011", 10},
        {"uv-semi-sharp-seam", "a seam along a semi-sharp crease (sharpness 2)", "0011" "0011" "0011" "0011", 2},
        {"uv-per-face", "one value per face corner: every edge a seam", "xxxx" "xxxx" "xxxx" "xxxx", 0},
    };
    std::vector<UvEdgeCase> out;
    for (bool triangles : {false, true})
        for (const Layout& l : layouts) {
            PolyMesh m = grid(triangles);
            std::vector<int> region;
            for (int f = 0; f < m.num_faces(); ++f) {
                const char r = l.regions[triangles ? f / 2 : f];
                region.push_back(r == 'x' ? f : r - '0');
            }
            m = with_uv_regions(m, region);
            if (l.crease > 0)
                for (int j = 0; j < 4; ++j) m.creases.edges.push_back({5 * j + 2, 5 * (j + 1) + 2, l.crease});
            const std::string name = std::string(l.name) + (triangles ? "-tri" : "");
            m.source.file = "edgecase:" + name;
            out.push_back({name, std::string(l.description) + (triangles ? ", on triangles" : ""), std::move(m)});
        }
    return out;
}

PolyMesh with_uv_layout(const PolyMesh& mesh, UvLayout layout) {
    PolyMesh out = mesh;
    out.face_varying.clear();
    FaceVaryingChannel uv;
    uv.name = "uv";
    uv.dimension = 2;
    uv.corner_values.resize(mesh.face_vertices.size());
    Vec3 centre = Vec3::Zero();
    for (const Vec3& p : mesh.positions) centre += p;
    if (mesh.num_vertices() > 0) centre /= mesh.num_vertices();
    auto region = [&](int f) {
        Vec3 c = Vec3::Zero();
        for (int k = 0; k < mesh.face_size(f); ++k) c += mesh.positions[mesh.face(f)[k]];
        c = c / mesh.face_size(f) - centre;
        if (layout == UvLayout::HalfSeam) return c.x() > 0 ? 1 : 0;
        const double angle = std::atan2(c.y(), c.x()) + std::numbers::pi;  // 0 .. 2 pi
        return std::min(2, static_cast<int>(angle / (2 * std::numbers::pi / 3)));
    };
    auto push = [&](const Vec3& p, int r) {
        const std::array<double, 2> t = uv_of_position(p);
        uv.values.push_back(t[0] + 0.5 * r);
        uv.values.push_back(t[1] + 0.3 * r);
        return uv.num_values() - 1;
    };
    if (layout == UvLayout::PerFace) {
        for (size_t c = 0; c < mesh.face_vertices.size(); ++c)
            uv.corner_values[c] = push(mesh.positions[mesh.face_vertices[c]], 0);
    } else {
        const int regions = layout == UvLayout::Welded ? 1 : layout == UvLayout::HalfSeam ? 2 : 3;
        std::vector<int> value(static_cast<size_t>(mesh.num_vertices()) * regions, -1);
        for (int f = 0; f < mesh.num_faces(); ++f) {
            const int r = layout == UvLayout::Welded ? 0 : region(f);
            for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
                const int v = mesh.face_vertices[c];
                int& slot = value[static_cast<size_t>(v) * regions + r];
                if (slot < 0) slot = push(mesh.positions[v], r);
                uv.corner_values[c] = slot;
            }
        }
    }
    out.face_varying.push_back(std::move(uv));
    return out;
}

}  // namespace crossdiv::datasets
