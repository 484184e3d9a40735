#include "crossdiv/subdiv/midpoint.h"

#include <climits>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "level_loop.h"
#include "linear_rows.h"

namespace crossdiv {

RefinementStep midpoint_step(const PolyMesh& mesh) {
    detail::require_triangles(mesh, "midpoint subdivision");
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    if (12LL * nf > INT_MAX || static_cast<long long>(nv) + 3LL * nf > INT_MAX)
        throw InputError("the next midpoint level would have more than 2^31 corners; use fewer levels");
    RefinementStep step(nv);
    // Far's edges, whatever the mesh: the scheme needs no rule at a non-manifold edge or
    // vertex, only the edges themselves (nonmanifold.h).
    const std::vector<std::array<int, 2>> edges = add_triangle_split(mesh, step);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + edges.size(), static_cast<size_t>(nv) + 2 * edges.size());
    detail::add_kept_vertex_rows(st, nv);
    detail::add_edge_midpoint_rows(st, edges);
    return step;
}

PolyMesh midpoint_subdivide(const PolyMesh& mesh, int levels) {
    detail::require_no_hierarchical_edits(mesh, "midpoint subdivision");
    detail::require_no_creases(mesh, "midpoint subdivision");
    if (levels == 0) midpoint_step(mesh);  // the same checks as a refinement
    return detail::apply_levels(mesh, levels, [](const PolyMesh& m, int) { return midpoint_step(m); });
}

}  // namespace crossdiv
