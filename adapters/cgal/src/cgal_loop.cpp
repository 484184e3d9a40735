// The only translation unit that includes CGAL (it costs ~1 GB and tens of seconds to compile).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version.h>

#include <string>

#include "crossdiv/adapters/cgal.h"

namespace crossdiv::adapters::cgal {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

PolyMesh snapshot(const Mesh& m) {
    PolyMesh out;
    // Surface_mesh indices are dense here (nothing is removed), so idx() is the vertex number.
    out.positions.resize(m.number_of_vertices());
    for (Mesh::Vertex_index v : m.vertices()) {
        const auto& p = m.point(v);
        out.positions[v.idx()] = Vec3(p.x(), p.y(), p.z());
    }
    for (Mesh::Face_index f : m.faces()) {
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) out.face_vertices.push_back(static_cast<int>(v.idx()));
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
    Mesh m;
    std::vector<Mesh::Vertex_index> vh;
    vh.reserve(static_cast<size_t>(mesh.num_vertices()));
    for (const Vec3& p : mesh.positions) vh.push_back(m.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Triangle& t = mesh.triangles[f];
        if (m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]) == Mesh::null_face())
            throw Rejected("CGAL Surface_mesh could not add face " + std::to_string(f) + " (" + std::to_string(t[0]) +
                           ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                           "): non-manifold or inconsistently oriented");
    }
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

}  // namespace crossdiv::adapters::cgal
