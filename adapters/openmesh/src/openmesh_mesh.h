#pragma once
// The OpenMesh mesh every OpenMesh translation unit builds from a TriMesh (internal header).
#include <OpenMesh/Core/Mesh/DefaultTriMesh.hh>

#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv::adapters::openmesh::detail {

using Mesh = OpenMesh::TriMesh;  // DefaultTraitsDouble

/// The mesh in OpenMesh with the same vertex and face numbering.
/// @throws Rejected naming the face when add_face refuses it (complex edge or vertex).
inline Mesh to_openmesh(const TriMesh& mesh) {
    Mesh m;
    std::vector<Mesh::VertexHandle> vh;
    vh.reserve(static_cast<size_t>(mesh.num_vertices()));
    for (const Vec3& p : mesh.positions) vh.push_back(m.add_vertex(Mesh::Point(p.x(), p.y(), p.z())));
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Triangle& t = mesh.triangles[f];
        if (!m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]).is_valid())
            throw Rejected("OpenMesh could not add face " + std::to_string(f) + " (" + std::to_string(t[0]) + ", " +
                           std::to_string(t[1]) + ", " + std::to_string(t[2]) + "): complex edge or vertex");
    }
    return m;
}

}  // namespace crossdiv::adapters::openmesh::detail
