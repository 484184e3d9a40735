#include "crossdiv/datasets/bundled.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/datasets/data_paths.h"
#include "shapes.h"

namespace crossdiv::datasets {
using namespace shapes;
namespace {

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

std::vector<BundledMesh> polygon_meshes() {
    std::vector<BundledMesh> all = {
        {"quad-cube", "closed, six quads, every vertex of valence 3", quad_cube()},
        {"quad-grid", "4x4 quads, open, saddle-bent: boundary and four one-face corners", quad_grid(4, 0.6)},
        {"quad-torus", "closed genus-1, 12x8 quads, every vertex of valence 4", quad_torus(12, 8)},
        {"prism-5", "closed: two pentagons and five quads", prism(5)},
    };
    for (int n : {3, 5, 7})
        all.push_back({"quad-fan-" + std::to_string(n),
                       "n quads around one interior vertex of valence " + std::to_string(n) + ", open", quad_fan(n)});
    for (BundledMesh& b : all) b.mesh.source.file = "bundled:" + b.name;
    return all;
}

std::vector<BundledMesh> catalog_meshes() {
    std::vector<BundledMesh> all = polygon_meshes();
    for (BundledMesh& b : bundled_meshes()) all.push_back(std::move(b));
    return all;
}

PolyMesh bundled_mesh(const std::string& name) {
    std::string known;
    std::vector<BundledMesh> all = catalog_meshes();
    for (BundledMesh& b : crease_meshes()) all.push_back(std::move(b));
    for (const BundledMesh& b : all) {
        if (b.name == name) return b.mesh;
        known += (known.empty() ? "" : ", ") + b.name;
    }
    throw InputError("unknown bundled mesh '" + name + "' (known: " + known + ")");
}

std::vector<std::string> cgal_mesh_files() { return files_in(datasets_dir() / "cgal", ".off"); }
std::vector<std::string> opensubdiv_shape_files() { return files_in(datasets_dir() / "opensubdiv", ".obj"); }

std::vector<std::string> course_mesh_files() {
    return files_in(shared_data_dir() / "c3100" / "objs", ".obj");
}

std::vector<std::string> meshedit_mesh_files() {
    return files_in(shared_data_dir() / "meshedit" / "dae", ".dae");
}

}  // namespace crossdiv::datasets
