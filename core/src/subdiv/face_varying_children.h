#pragma once
// Where each child vertex and child face of one refinement step comes from, read off the
// step's faces (so that no scheme's vertex numbering is assumed beyond "old vertices keep
// their index"): shared by the face-varying refinements (face_varying_refinement.cpp under
// OpenSubdiv's rules, face_varying_legacy_rules.cpp under Hbr's). Internal to core.

#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/face_varying_refinement.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv::face_varying_children {

/// Where each child vertex comes from, read off the step's faces (so that no scheme's vertex
/// numbering is assumed beyond "old vertices keep their index").
struct ChildOrigins {
    std::vector<int> edge_of_child;  ///< the parent edge of an edge point, else -1
    std::vector<int> face_of_child;  ///< the parent face of a face point, else -1
    std::vector<int> parent_face;    ///< per child face
    /// Per child face, the parent corner whose vertex it keeps (-1 for Loop's middle
    /// triangle, which keeps none): an old vertex's corner in a child face is that one's.
    std::vector<int> parent_corner;
};

inline ChildOrigins child_origins(const PolyMesh& parent, const PolyConnectivity& conn, const RefinementStep& step,
                           FaceVaryingScheme scheme) {
    ChildOrigins o;
    const size_t child_nv = static_cast<size_t>(step.stencils.num_rows());
    o.edge_of_child.assign(child_nv, -1);
    o.face_of_child.assign(child_nv, -1);
    const int nc = conn.num_corners();
    const int child_faces = static_cast<int>(step.face_start.size()) - 1;
    o.parent_face.resize(static_cast<size_t>(child_faces));
    o.parent_corner.assign(static_cast<size_t>(child_faces), -1);
    if (scheme == FaceVaryingScheme::Loop) {
        if (child_faces != 4 * parent.num_faces())
            throw std::logic_error("refine_face_varying: a Loop step with " + std::to_string(child_faces) + " faces");
        for (int f = 0; f < parent.num_faces(); ++f) {
            const int c = parent.face_start[f];
            for (int k = 0; k < 3; ++k) {
                o.parent_face[static_cast<size_t>(4 * f + k)] = f;
                o.parent_corner[static_cast<size_t>(4 * f + k)] = c + k;
                const int m = step.face_vertices[static_cast<size_t>(3 * (4 * f + k) + 1)];
                o.edge_of_child[static_cast<size_t>(m)] = conn.corner_edge[c + k];
            }
            o.parent_face[static_cast<size_t>(4 * f + 3)] = f;
        }
    } else {
        if (child_faces != nc)
            throw std::logic_error("refine_face_varying: a quad step with " + std::to_string(child_faces) + " faces");
        for (int c = 0; c < nc; ++c) {
            o.parent_face[static_cast<size_t>(c)] = conn.corner_face[c];
            o.parent_corner[static_cast<size_t>(c)] = c;
            o.edge_of_child[static_cast<size_t>(step.face_vertices[static_cast<size_t>(4 * c + 1)])] = conn.corner_edge[c];
            o.face_of_child[static_cast<size_t>(step.face_vertices[static_cast<size_t>(4 * c + 2)])] = conn.corner_face[c];
        }
    }
    return o;
}

}  // namespace crossdiv::face_varying_children
