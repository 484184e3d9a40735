// The second of the two translation units that include CGAL: closed-mesh checks
// (Polygon_mesh_processing's orientation and volume on a Surface_mesh).
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <string>
#include <vector>

#include "crossdiv/adapters/cgal.h"

namespace crossdiv::adapters::cgal {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
}  // namespace

ClosedMeshReport closed_mesh_report(const TriMesh& mesh) {
    ClosedMeshReport r;
    Mesh sm;
    std::vector<Mesh::Vertex_index> v;
    v.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) v.push_back(sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Triangle& t = mesh.triangles[f];
        if (sm.add_face(v[t[0]], v[t[1]], v[t[2]]) == Mesh::null_face()) {
            r.error = "Surface_mesh refused face " + std::to_string(f) + " (" + std::to_string(t[0]) + " " +
                      std::to_string(t[1]) + " " + std::to_string(t[2]) + "): non-manifold or inconsistently oriented";
            return r;
        }
    }
    r.built = true;
    r.valid = CGAL::is_valid_polygon_mesh(sm);
    r.closed = CGAL::is_closed(sm);
    if (r.closed && r.valid) {
        namespace PMP = CGAL::Polygon_mesh_processing;
        r.outward = PMP::is_outward_oriented(sm);
        r.volume = PMP::volume(sm);
    }
    return r;
}

}  // namespace crossdiv::adapters::cgal
