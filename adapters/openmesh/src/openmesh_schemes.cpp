// Catmull-Clark, sqrt3 and modified Butterfly through OpenMesh's uniform subdividers.
#include <OpenMesh/Core/Mesh/DefaultPolyMesh.hh>
#include <OpenMesh/Core/Mesh/DefaultTriMesh.hh>  // first: the Subdivider headers rely on what it brings in
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include <string>

#include "crossdiv/adapters/openmesh.h"
#include "openmesh_mesh.h"

namespace crossdiv::adapters::openmesh {
namespace {

using Poly = OpenMesh::PolyMesh;  // DefaultTraitsDouble

using detail::snapshot;

Poly to_poly(const PolyMesh& mesh) {
    reject_crease_tags(mesh, "OpenMesh");
    Poly m;
    std::vector<Poly::VertexHandle> vh;
    for (const Vec3& p : mesh.positions) vh.push_back(m.add_vertex(Poly::Point(p.x(), p.y(), p.z())));
    std::vector<Poly::VertexHandle> corners;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        corners.clear();
        for (int k = 0; k < mesh.face_size(f); ++k) corners.push_back(vh[mesh.face(f)[k]]);
        if (!m.add_face(corners).is_valid())
            throw Rejected("OpenMesh could not add face " + std::to_string(f) + ": complex edge or vertex");
    }
    return m;
}

/// Every level of `levels` calls of one step of `Subdivider`.
template <class Subdivider, class M>
LevelTrace per_level(M m, int levels) {
    LevelTrace trace{snapshot(m, 0)};
    Subdivider sub;
    for (int l = 1; l <= levels; ++l) {
        sub.attach(m);
        sub(1);
        sub.detach();
        trace.push_back(snapshot(m, l));
    }
    return trace;
}

}  // namespace

LevelTrace catmull_clark(const PolyMesh& mesh, int levels) {
    return per_level<OpenMesh::Subdivider::Uniform::CatmullClarkT<Poly>>(to_poly(mesh), levels);
}

size_t catmull_clark_native(const PolyMesh& mesh, int levels) {
    Poly m = to_poly(mesh);
    OpenMesh::Subdivider::Uniform::CatmullClarkT<Poly> sub;
    sub.attach(m);
    sub(static_cast<size_t>(levels));
    sub.detach();
    return m.n_faces();
}

LevelTrace sqrt3(const TriMesh& mesh, int levels, bool one_call) {
    using Sqrt3 = OpenMesh::Subdivider::Uniform::Sqrt3T<detail::Mesh>;
    detail::Mesh base = detail::to_openmesh(mesh);
    if (!one_call) return per_level<Sqrt3>(base, levels);
    LevelTrace trace{snapshot(base, 0)};
    for (int l = 1; l <= levels; ++l) {
        detail::Mesh m = base;
        Sqrt3 sub;
        sub.attach(m);
        sub(static_cast<size_t>(l));
        sub.detach();
        trace.push_back(snapshot(m, l));
    }
    return trace;
}

LevelTrace modified_butterfly(const TriMesh& mesh, int levels) {
    return per_level<OpenMesh::Subdivider::Uniform::ModifiedButterflyT<detail::Mesh>>(detail::to_openmesh(mesh), levels);
}

}  // namespace crossdiv::adapters::openmesh
