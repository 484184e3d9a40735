#pragma once
// The Surface_mesh both CGAL translation units build from a TriMesh (internal header: it
// pulls in CGAL, so only the adapter's .cpp files include it).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv::adapters::cgal::detail {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

/// The mesh as a Surface_mesh with the same vertex and face numbering, or, when add_face
/// refuses a triangle, why (naming the face and its corners).
inline Mesh to_surface_mesh(const TriMesh& mesh, std::string& refused) {
    Mesh m;
    std::vector<Mesh::Vertex_index> vh;
    vh.reserve(static_cast<size_t>(mesh.num_vertices()));
    for (const Vec3& p : mesh.positions) vh.push_back(m.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Triangle& t = mesh.triangles[f];
        if (m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]) == Mesh::null_face()) {
            refused = "CGAL Surface_mesh could not add face " + std::to_string(f) + " (" + std::to_string(t[0]) + ", " +
                      std::to_string(t[1]) + ", " + std::to_string(t[2]) + "): non-manifold or inconsistently oriented";
            break;
        }
    }
    return m;
}

/// The polygon mesh as a Surface_mesh, same numbering, or why add_face refused a face.
inline Mesh to_surface_mesh(const PolyMesh& mesh, std::string& refused) {
    Mesh m;
    std::vector<Mesh::Vertex_index> vh;
    vh.reserve(static_cast<size_t>(mesh.num_vertices()));
    for (const Vec3& p : mesh.positions) vh.push_back(m.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    std::vector<Mesh::Vertex_index> corners;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        corners.clear();
        for (int k = 0; k < mesh.face_size(f); ++k) corners.push_back(vh[mesh.face(f)[k]]);
        if (m.add_face(corners) == Mesh::null_face()) {
            refused = "CGAL Surface_mesh could not add face " + std::to_string(f) +
                      ": non-manifold or inconsistently oriented";
            break;
        }
    }
    return m;
}

}  // namespace crossdiv::adapters::cgal::detail
