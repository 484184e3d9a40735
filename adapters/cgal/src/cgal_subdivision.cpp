// One of the two translation units that include CGAL (each costs ~1 GB and tens of seconds to
// compile): the subdivision methods.
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version.h>

#include <string>

#include "cgal_surface_mesh.h"
#include "crossdiv/adapters/cgal.h"

namespace crossdiv::adapters::cgal {
namespace {

using detail::Kernel;
using detail::Mesh;

PolyMesh snapshot(const Mesh& m) {
    PolyMesh out;
    // Vertices numbered in iteration order, which skips removed ones: Doo-Sabin's DQQ step
    // removes the old vertices and some faces, and leaves their slots as garbage, so idx()
    // is not a vertex number there (it is for the schemes that remove nothing).
    std::vector<int> number(m.num_vertices(), -1);
    out.positions.reserve(m.number_of_vertices());
    for (Mesh::Vertex_index v : m.vertices()) {
        const auto& p = m.point(v);
        number[v.idx()] = out.num_vertices();
        out.positions.emplace_back(p.x(), p.y(), p.z());
    }
    for (Mesh::Face_index f : m.faces()) {
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) out.face_vertices.push_back(number[v.idx()]);
        out.face_start.push_back(static_cast<int>(out.face_vertices.size()));
    }
    return out;
}

}  // namespace

bool supports(const LoopOptions& options) {
    return options.weights == LoopWeights::Loop && options.boundary == LoopBoundary::EdgeOnly;
}

std::string version() { return std::string("CGAL ") + CGAL_VERSION_STR; }

namespace {

Mesh build(const TriMesh& mesh, const LoopOptions& options) {
    if (!supports(options))
        throw Rejected("CGAL's Loop_subdivision has Loop weights and the edge-only boundary rule only");
    std::string refused;
    Mesh m = detail::to_surface_mesh(mesh, refused);
    if (!refused.empty()) throw Rejected(refused);
    return m;
}

}  // namespace

LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels) {
    Mesh m = build(mesh, options);
    LevelTrace trace{snapshot(m)};
    for (int l = 1; l <= levels; ++l) {
        CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
        trace.push_back(snapshot(m));
    }
    return trace;
}

size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels) {
    Mesh m = build(mesh, options);
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(levels));
    return m.number_of_faces();
}

namespace {

Mesh build_polygons(const PolyMesh& mesh) {
    reject_crease_tags(mesh, "CGAL");
    std::string refused;
    Mesh m = detail::to_surface_mesh(mesh, refused);
    if (!refused.empty()) throw Rejected(refused);
    return m;
}

/// Every level of `levels` calls of one iteration each of `method`.
template <class Method>
LevelTrace per_level(Mesh m, int levels, Method method) {
    LevelTrace trace{snapshot(m)};
    for (int l = 1; l <= levels; ++l) {
        method(m, 1);
        trace.push_back(snapshot(m));
    }
    return trace;
}

}  // namespace

LevelTrace catmull_clark(const PolyMesh& mesh, int levels) {
    return per_level(build_polygons(mesh), levels, [](Mesh& m, int n) {
        CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(n));
    });
}

size_t catmull_clark_native(const PolyMesh& mesh, int levels) {
    Mesh m = build_polygons(mesh);
    CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(levels));
    return m.number_of_faces();
}

LevelTrace doo_sabin(const PolyMesh& mesh, int levels) {
    return per_level(build_polygons(mesh), levels, [](Mesh& m, int n) {
        CGAL::Subdivision_method_3::DooSabin_subdivision(m, CGAL::parameters::number_of_iterations(n));
    });
}

LevelTrace sqrt3(const TriMesh& mesh, int levels, bool one_call) {
    auto method = [](Mesh& m, int n) {
        CGAL::Subdivision_method_3::Sqrt3_subdivision(m, CGAL::parameters::number_of_iterations(n));
    };
    std::string refused;
    const Mesh base = detail::to_surface_mesh(mesh, refused);
    if (!refused.empty()) throw Rejected(refused);
    if (!one_call) return per_level(base, levels, method);
    LevelTrace trace{snapshot(base)};
    for (int l = 1; l <= levels; ++l) {
        Mesh m = base;
        method(m, l);
        trace.push_back(snapshot(m));
    }
    return trace;
}

}  // namespace crossdiv::adapters::cgal
