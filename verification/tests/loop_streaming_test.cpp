// The streaming Loop driver against the ring-walk driver (loop_subdivide) on the catalog, under
// every weight family and both boundary rules: the same triangles; at the first level the same
// edge points and boundary vertex points bit for bit and the interior vertex points within the
// rounding of another summation order; at every level within a few ulps of the coordinates.
#include <gtest/gtest.h>

#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {
namespace {

/// One ulp of the largest coordinate magnitude of `p`: the scale of a summation order's rounding.
double coordinate_ulp(const std::vector<Vec3>& p) {
    double magnitude = 0;
    for (const Vec3& q : p) magnitude = std::max(magnitude, q.cwiseAbs().maxCoeff());
    return std::nextafter(magnitude, INFINITY) - magnitude;
}

TEST(LoopStreaming, EqualsTheRingWalkDriverOnTheCatalog) {
    int meshes = 0;
    double worst_first_level_ulps = 0, worst_ulps = 0;
    std::vector<datasets::BundledMesh> catalog = datasets::catalog_meshes();
    for (const datasets::EdgeCase& e : datasets::edge_cases()) catalog.push_back({e.name, e.description, e.mesh});
    for (const datasets::BundledMesh& b : catalog) {
        if (!b.mesh.all_triangles()) continue;
        const TriMesh base = to_tri_mesh(b.mesh, "test");
        TriConnectivity conn;
        try {
            conn = build_tri_connectivity(base);
        } catch (const NonManifoldInput&) {
            // Not a manifold: both drivers refuse it alike.
            EXPECT_THROW(loop_subdivide_streaming(base, {}, 1), NonManifoldInput) << b.name;
            continue;
        }
        ++meshes;
        for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren, LoopWeights::Regularity, LoopWeights::Continuity})
            for (LoopBoundary bd : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
                const LoopOptions o{w, bd};
                for (int levels = 1; levels <= 3; ++levels) {
                    const TriMesh ring = loop_subdivide(base, o, levels), stream = loop_subdivide_streaming(base, o, levels);
                    ASSERT_EQ(ring.triangles, stream.triangles) << b.name << " levels " << levels;
                    ASSERT_EQ(ring.positions.size(), stream.positions.size());
                    // Another summation order of the same stencils: a few ulps of the coordinates
                    // (tolerances::kRoundingUlps, the harness's rounding class), compounding over
                    // the levels. Relative to the diagonal this is 1e-9 on a mesh far from the
                    // origin, so the bound is in ulps, as the harness states rounding.
                    const double ulp = coordinate_ulp(ring.positions);
                    for (size_t v = 0; v < ring.positions.size(); ++v) {
                        const double d = (ring.positions[v] - stream.positions[v]).cwiseAbs().maxCoeff();
                        EXPECT_LE(d, tolerances::kRoundingUlps * ulp) << b.name << " levels " << levels << " vertex " << v;
                        worst_ulps = std::max(worst_ulps, d / ulp);
                        if (levels != 1) continue;
                        // At the first level the inputs are the same: an edge point, a boundary or
                        // corner vertex point (two terms) and an isolated vertex are the same sums.
                        const bool same_sums = v >= base.positions.size() || conn.vertex_corner[v] < 0 ||
                                               conn.is_boundary_vertex(static_cast<int>(v));
                        if (same_sums) EXPECT_EQ(ring.positions[v], stream.positions[v]) << b.name << " vertex " << v;
                        else worst_first_level_ulps = std::max(worst_first_level_ulps, d / ulp);
                    }
                }
            }
    }
    EXPECT_GE(meshes, 50);
    // Measured: 59 manifold meshes, 1 ulp at the first level, 3 ulps over three levels.
    std::printf("streaming vs ring walk: %d manifold meshes, first level %.3g ulps, three levels %.3g ulps\n", meshes,
                worst_first_level_ulps, worst_ulps);
}

}  // namespace
}  // namespace crossdiv::verification
