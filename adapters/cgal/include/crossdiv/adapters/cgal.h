#pragma once
/// @file
/// CGAL 5.5 adapter: Subdivision_method_3::Loop_subdivision on
/// Surface_mesh<Simple_cartesian<double>::Point_3>. CGAL is included by two translation units (Loop, mesh checks).

#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::cgal {

/// Loop_mask_3 has Loop's weights, the midpoint border edge and the 1-6-1 border vertex
/// (our EdgeOnly); it has no corner rule.
bool supports(const LoopOptions& options);

/// `levels` Loop_subdivision calls of one iteration each, so that every level can be read.
/// @throws Rejected for options it lacks, or when Surface_mesh refuses a face (non-manifold
///         or inconsistently oriented), naming the face.
LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels);

/// The same refinement in the library's own structures, with nothing converted back: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as loop().
size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels);

/// What CGAL says about a triangle mesh as a closed surface.
struct ClosedMeshReport {
    bool built = false;           ///< Surface_mesh accepted every face
    std::string error;            ///< why not, naming the face
    bool valid = false;           ///< CGAL::is_valid_polygon_mesh
    bool closed = false;          ///< CGAL::is_closed (no border halfedge)
    bool outward = false;         ///< PMP::is_outward_oriented (only computed when closed)
    double volume = 0;            ///< PMP::volume (only computed when closed)
};
/// Builds a Surface_mesh and asks is_valid_polygon_mesh, is_closed, and, for a closed mesh,
/// PMP::is_outward_oriented and PMP::volume. Never throws for a bad mesh: a face Surface_mesh
/// refuses is reported in `error`.
ClosedMeshReport closed_mesh_report(const TriMesh& mesh);

/// "CGAL 5.5.1".
std::string version();

}  // namespace crossdiv::adapters::cgal
