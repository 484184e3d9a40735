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

/// The mesh as emitted: every face that is not a hole, in order, with its source line;
/// every vertex kept, as Far keeps them, so that vertex numbers stay those of the refinement
/// (a vertex only holes use is then unreferenced). The hole tags are dropped.
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
