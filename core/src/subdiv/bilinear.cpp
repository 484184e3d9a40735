#include "crossdiv/subdiv/bilinear.h"

#include <climits>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/bilinear_mask.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "level_loop.h"
#include "linear_rows.h"

namespace crossdiv {

RefinementStep bilinear_step(const PolyMesh& mesh) {
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    const long long nc = static_cast<long long>(mesh.face_vertices.size());
    for (int f = 0; f < nf; ++f)
        if (mesh.face_size(f) < 3)
            throw InputError(mesh.source.describe_face(f) + ": has " + std::to_string(mesh.face_size(f)) +
                             " corners; a face needs three");
    if (static_cast<long long>(nv) + nf + nc > INT_MAX || 4 * nc > INT_MAX)
        throw InputError("the next bilinear level would have " + std::to_string(nc) +
                         " faces, more than 32-bit indices address; use fewer levels");
    RefinementStep step(nv);
    // Far's topology, whatever the mesh: bilinear needs no rule at a non-manifold edge or
    // vertex, only its edges as Far counts them (nonmanifold.h).
    const std::vector<std::array<int, 2>> edges = add_quad_split(mesh, step);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + nf + edges.size(), static_cast<size_t>(nv + nc) + 2 * edges.size());
    detail::add_kept_vertex_rows(st, nv);
    for (int f = 0; f < nf; ++f) {
        const double w = bilinear_face_corner(mesh.face_size(f));
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) st.add(mesh.face_vertices[c], w);
        st.end_row();
    }
    detail::add_edge_midpoint_rows(st, edges);
    return step;
}

PolyMesh bilinear_subdivide(const PolyMesh& mesh, int levels) {
    detail::require_no_creases(mesh, "bilinear subdivision");
    if (levels == 0) bilinear_step(mesh);  // the same checks as a refinement
    return detail::apply_levels(mesh, levels, [](const PolyMesh& m, int) { return bilinear_step(m); });
}

}  // namespace crossdiv
