// The second of the two translation units that include CGAL: closed-mesh checks
// (Polygon_mesh_processing's orientation and volume on a Surface_mesh).
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/boost/graph/helpers.h>

#include "cgal_surface_mesh.h"
#include "crossdiv/adapters/cgal.h"

namespace crossdiv::adapters::cgal {

ClosedMeshReport closed_mesh_report(const TriMesh& mesh) {
    ClosedMeshReport r;
    const detail::Mesh sm = detail::to_surface_mesh(mesh, r.error);
    if (!r.error.empty()) return r;
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
