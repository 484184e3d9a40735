#include "crossdiv/verification/properties/butterfly_properties.h"

#include <algorithm>
#include <cmath>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/butterfly.h"

namespace crossdiv::verification {
namespace {

/// Whether the eight-point stencil of corner c's edge lies inside the mesh with valence 6 at
/// both ends: then every variant must use the published weights.
bool regular_interior_stencil(const PolyConnectivity& conn, int c) {
    const int t = conn.twin[c];
    if (t < 0) return false;
    for (int w : {conn.next[c], conn.prev[c], conn.next[t], conn.prev[t]})
        if (conn.twin[w] < 0) return false;
    for (int v : {conn.corner_vertex[c], conn.head(c)})
        if (conn.is_boundary_vertex(v) || conn.fan(v).faces != 6) return false;
    return true;
}

}  // namespace

ButterflyProperties check_butterfly_properties(const PolyMesh& mesh, const std::string& name, ButterflyVariant variant,
                                               int levels) {
    ButterflyProperties p;
    p.input = name;
    p.variant = variant;
    p.levels = levels;
    try {
        // Interpolation and the stencil, level by level.
        PolyMesh current = mesh;
        for (int l = 0; l < levels; ++l) {
            const PolyConnectivity conn = build_poly_connectivity(current);
            const RefinementStep step = butterfly_step(current, conn, variant);
            if (l == 0) {
                const Eigen::SparseMatrix<double, Eigen::RowMajor> S = step.stencils.matrix();
                const std::vector<double> published{kButterflyC, kButterflyC, kButterflyC, kButterflyC,
                                                    kButterflyB, kButterflyB, kButterflyA, kButterflyA};
                for (int e = 0; e < conn.num_edges(); ++e) {
                    if (!regular_interior_stencil(conn, conn.edge_corner[e])) continue;
                    ++p.regular_edges;
                    std::vector<double> w;
                    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(S, current.num_vertices() + e); it; ++it)
                        if (it.value() != 0.0) w.push_back(it.value());
                    std::sort(w.begin(), w.end());
                    p.regular_edges_published += w == published;
                }
            }
            const PolyMesh next = apply_step(step, current);
            for (int v = 0; v < current.num_vertices(); ++v)
                p.max_interpolation_move = std::max(p.max_interpolation_move, (next.positions[v] - current.positions[v]).norm());
            current = next;
        }
        // Plane reproduction: the same connectivity with every vertex moved onto a plane
        // that is not a coordinate plane.
        PolyMesh planar = mesh;
        const auto plane = [](const Vec3& q) { return 0.3 * q.x() - 0.7 * q.y() + 0.25; };
        for (Vec3& q : planar.positions) q.z() = plane(q);
        const PolyMesh refined = butterfly_subdivide(planar, variant, levels);
        const double diagonal = bounding_box_diagonal(refined.positions);
        for (const Vec3& q : refined.positions)
            p.max_plane_residual = std::max(p.max_plane_residual, std::abs(q.z() - plane(q)) / diagonal);
    } catch (const InputError& e) {
        p.core_error = e.what();
    }
    return p;
}

nlohmann::json to_json(const ButterflyProperties& p) {
    return {{"input", p.input},
            {"scheme", std::string(to_string(p.variant))},
            {"levels", p.levels},
            {"core_error", p.core_error},
            {"max_interpolation_move", p.max_interpolation_move},
            {"max_plane_residual", p.max_plane_residual},
            {"regular_edges", p.regular_edges},
            {"regular_edges_published", p.regular_edges_published}};
}

}  // namespace crossdiv::verification
