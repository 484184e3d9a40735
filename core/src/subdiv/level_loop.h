#pragma once
// N levels of a polygon scheme given its one-level step: the loop every RefinementStep
// scheme shares (connectivity rebuilt per level, positions and colors through the stencils).

#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/refinement.h"
#include "finite_level.h"

namespace crossdiv::detail {

/// `step(mesh, conn, level)` returns the RefinementStep of level `level` (0 = the first); build_poly_connectivity checks
/// the input (and throws InputError naming the element) before the first step.
template <class Step>
PolyMesh refine_levels(const PolyMesh& mesh, int levels, const Step& step) {
    if (levels < 0) throw InputError("number of levels must be >= 0, got " + std::to_string(levels));
    PolyMesh current = mesh;
    for (int l = 0; l < levels; ++l) {
        const PolyConnectivity conn = build_poly_connectivity(current);
        PolyMesh next = apply_step(step(current, conn, l), current);
        require_finite_level(next.positions, current.positions, l + 1);
        current = std::move(next);
    }
    if (levels == 0) build_poly_connectivity(current);  // the same checks as a refinement
    current.source = {};
    return current;
}

/// @throws InputError naming the first face that is not a triangle, for the schemes that
///         refine triangles only (sqrt3, the Butterflies).
inline void require_triangles(const PolyMesh& mesh, const char* scheme) {
    for (int f = 0; f < mesh.num_faces(); ++f)
        if (mesh.face_size(f) != 3)
            throw InputError(mesh.source.describe_face(f) + ": has " + std::to_string(mesh.face_size(f)) +
                             " corners; " + scheme + " refines triangles only");
}

/// @throws InputError for a mesh with crease, corner or hole tags, for the schemes without
///         those rules (sqrt3, Doo-Sabin, the Butterflies): dropping the tags would be a silent
///         wrong answer.
inline void require_no_creases(const PolyMesh& mesh, const char* scheme) {
    if (!mesh.creases.empty())
        throw InputError((mesh.source.file.empty() ? std::string("the mesh") : mesh.source.file) + " has " +
                         mesh.creases.describe() + "; " + scheme +
                         " has no crease or hole rules (Loop and Catmull-Clark have)");
}

}  // namespace crossdiv::detail
