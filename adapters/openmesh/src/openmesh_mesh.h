#pragma once
// The OpenMesh mesh every OpenMesh translation unit builds from a TriMesh (internal header).
#include <OpenMesh/Core/Mesh/DefaultTriMesh.hh>

#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/poly_mesh.h"
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

/// The mesh as OpenMesh holds it after `steps` subdivision steps: its vertices and each face's
/// corners in OpenMesh's order. A face's vertex circulator walks next-halfedges until it is
/// back at the start, so it passes at most every halfedge once; one that walks further never
/// closes (OpenMesh 9's add_face stores a quad naming a vertex twice as such a face) and would
/// otherwise fill memory without end.
/// @throws InvalidResult naming the face and the step when a face's corners never close.
template <class M>
PolyMesh snapshot(const M& m, int steps) {
    PolyMesh out;
    out.positions.reserve(m.n_vertices());
    for (auto v : m.vertices()) {
        const auto& p = m.point(v);
        out.positions.emplace_back(p[0], p[1], p[2]);
    }
    const size_t most_corners = m.n_halfedges();
    for (auto f : m.faces()) {
        size_t corners = 0;
        for (auto v : m.fv_range(f)) {
            if (++corners > most_corners)
                throw InvalidResult("OpenMesh's face " + std::to_string(f.idx()) +
                                    (steps == 0 ? " of the input as add_face stored it"
                                                : " after " + std::to_string(steps) + " step(s)") +
                                    " has a vertex circulator that never closes (more corners than the mesh's " +
                                    std::to_string(most_corners) + " halfedges): its connectivity is broken");
            out.face_vertices.push_back(v.idx());
        }
        out.face_start.push_back(static_cast<int>(out.face_vertices.size()));
    }
    return out;
}

}  // namespace crossdiv::adapters::openmesh::detail
