#pragma once
/// @file
/// Hole faces as OpenSubdiv's Far treats them: a hole is refined like any other face (its
/// vertices keep their whole neighbourhood, so the surface around it is unchanged), its
/// children are holes, and it is not emitted. Holes come from `t hole` tags or from the
/// boundary rule `t interpolateboundary 0` (Sdc VTX_BOUNDARY_NONE).

#include <vector>

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// Calls `fn(f)` for every face of `mesh` that is not a hole, in order (the holes are sorted:
/// one merge pass).
template <class Fn>
void for_each_emitted_face(const PolyMesh& mesh, const Fn& fn) {
    const std::vector<int>& holes = mesh.creases.holes;
    size_t next_hole = 0;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        if (next_hole < holes.size() && holes[next_hole] == f) {
            ++next_hole;
            continue;
        }
        fn(f);
    }
}

/// The mesh as emitted: every face that is not a hole, in order, with its source line;
/// every vertex kept, as Far keeps them, so that vertex numbers stay those of the refinement
/// (a vertex only holes use is then unreferenced). The hole tags are dropped; face-varying
/// channels keep their values and the corners of the emitted faces.
PolyMesh without_hole_faces(const PolyMesh& mesh);

/// Sdc VTX_BOUNDARY_NONE, as TopologyRefinerFactoryBase::prepareComponentTagsAndSharpness
/// applies it before it sharpens the boundary: every face around a boundary vertex that has
/// a boundary edge not already tagged infinitely sharp becomes a hole. The refinement rule
/// itself is then the edge-only one (Far sharpens every boundary edge).
void tag_boundary_faces_as_holes(PolyMesh& mesh, const PolyConnectivity& conn);

/// The next level's holes when face f's children are the faces
/// [child_start(f), child_start(f + 1)): sorted, as `holes` is.
template <class ChildStart>
std::vector<int> child_holes(const std::vector<int>& holes, const ChildStart& child_start) {
    std::vector<int> out;
    for (int f : holes)
        for (int c = child_start(f); c < child_start(f + 1); ++c) out.push_back(c);
    return out;
}

}  // namespace crossdiv
