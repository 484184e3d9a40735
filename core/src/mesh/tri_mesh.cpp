#include "crossdiv/mesh/tri_mesh.h"

#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

TriMesh to_tri_mesh(const PolyMesh& mesh, const char* scheme) {
    if (!mesh.creases.empty())
        throw InputError((mesh.source.file.empty() ? std::string("the mesh") : mesh.source.file) +
                         " has " + mesh.creases.describe() + "; " + scheme +
                         " works on a triangle mesh, which has no tags (only Loop and Catmull-Clark on the "
                         "polygon mesh honour them)");
    TriMesh tri;
    tri.positions = mesh.positions;
    tri.colors = mesh.colors;
    tri.source = mesh.source;
    tri.triangles.reserve(static_cast<size_t>(mesh.num_faces()));
    for (int f = 0; f < mesh.num_faces(); ++f) {
        if (mesh.face_size(f) != 3)
            throw InputError(mesh.source.describe_face(f) + ": has " + std::to_string(mesh.face_size(f)) +
                             " corners; " + scheme + " needs triangles (the mesh is not triangulated for you)");
        const int* v = mesh.face(f);
        tri.triangles.push_back({v[0], v[1], v[2]});
    }
    return tri;
}

PolyMesh to_poly_mesh(const TriMesh& mesh) {
    PolyMesh poly;
    poly.positions = mesh.positions;
    poly.colors = mesh.colors;
    poly.source = mesh.source;
    poly.face_vertices.reserve(3 * mesh.triangles.size());
    poly.face_start.reserve(mesh.triangles.size() + 1);
    for (const Triangle& t : mesh.triangles) poly.add_face(t);
    return poly;
}

double bounding_box_diagonal(const std::vector<Vec3>& positions) {
    if (positions.empty()) return 0.0;
    Vec3 lo = positions.front(), hi = positions.front();
    for (const Vec3& p : positions) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    // Halves and a scaled norm: the extent of coordinates near DBL_MAX does not overflow;
    // the result is inf only when the diagonal itself exceeds the range of double.
    return 2.0 * (0.5 * hi - 0.5 * lo).stableNorm();
}

}  // namespace crossdiv
