#include "crossdiv/datasets/analytic_surfaces.h"

#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "shapes.h"

namespace crossdiv::datasets {

TriMesh icosphere(int level) {
    if (level < 0 || level > 8) throw InputError("icosphere level " + std::to_string(level) + " outside 0..8");
    TriMesh mesh = to_tri_mesh(shapes::icosahedron());
    for (Vec3& p : mesh.positions) p.normalize();
    for (int l = 0; l < level; ++l) {
        const TriConnectivity conn = build_tri_connectivity(mesh);
        const int nv = mesh.num_vertices();
        for (const auto& [a, b] : conn.edge_vertices)
            mesh.positions.push_back((mesh.positions[a] + mesh.positions[b]).normalized());
        std::vector<Triangle> fine;
        fine.reserve(4 * mesh.triangles.size());
        for (int f = 0; f < mesh.num_faces(); ++f) {
            const Triangle& t = mesh.triangles[f];
            const auto& e = conn.tri_edges[f];  // edge j runs from corner j to corner j + 1
            const int m0 = nv + e[0], m1 = nv + e[1], m2 = nv + e[2];
            fine.push_back({t[0], m0, m2});
            fine.push_back({t[1], m1, m0});
            fine.push_back({t[2], m2, m1});
            fine.push_back({m0, m1, m2});
        }
        mesh.triangles = std::move(fine);
    }
    return mesh;
}

TriMesh regular_torus(int nu, int nv, double R, double r) {
    if (nu < 3 || nv < 3 || !(r > 0.0) || !(r < R))
        throw InputError("torus needs nu, nv >= 3 and 0 < r < R (got " + std::to_string(nu) + " x " +
                         std::to_string(nv) + ", R " + std::to_string(R) + ", r " + std::to_string(r) + ")");
    return to_tri_mesh(shapes::torus(nu, nv, R, r));
}

}  // namespace crossdiv::datasets
