// Limit positions and normals: hand values on tiny meshes, and Loop's limit mask derived
// from the eigenvectors of the local subdivision matrix for both weight families.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/eigendecomposition.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/loop.h"

namespace crossdiv {
namespace {

// One interior vertex (index 0) of valence n inside a boundary ring: its 1-ring is the whole mesh.
TriMesh fan(int n) {
    TriMesh m;
    m.positions.emplace_back(0.1, -0.2, 0.7);
    for (int k = 0; k < n; ++k)
        m.positions.emplace_back(std::cos(2 * M_PI * k / n) * (1 + 0.1 * k), std::sin(2 * M_PI * k / n), 0.05 * k * k);
    for (int k = 0; k < n; ++k) m.triangles.push_back({0, 1 + k, 1 + (k + 1) % n});
    return m;
}

PolyMesh quad_cube() {
    PolyMesh m;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    for (auto f : {std::array{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}})
        m.add_face(f);
    return m;
}

TEST(LoopLimit, MaskIsTheLeftEigenvectorOfEigenvalueOneForBothFamilies) {
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren}) {
        for (int n = 3; n <= 12; ++n) {
            const TriMesh m = fan(n);
            const Eigen::SparseMatrix<double> S = loop_subdivision_matrix(m, {w, LoopBoundary::EdgeOnly});
            // Rows of the refined 1-ring: the centre (0) and the edge points of the spokes.
            const TriConnectivity conn = build_tri_connectivity(m);
            std::vector<int> rows{0};
            for (int k = 1; k <= n; ++k)
                for (int e = 0; e < conn.num_edges(); ++e)
                    if ((conn.edge_vertices[e][0] == 0 && conn.edge_vertices[e][1] == k) ||
                        (conn.edge_vertices[e][1] == 0 && conn.edge_vertices[e][0] == k))
                        rows.push_back(m.num_vertices() + e);
            ASSERT_EQ(static_cast<int>(rows.size()), n + 1);
            Eigen::MatrixXd L(n + 1, n + 1);
            const Eigen::MatrixXd dense(S);
            for (int r = 0; r <= n; ++r) L.row(r) = dense.row(rows[r]).head(n + 1);
            // Left eigenvector of eigenvalue 1 = right eigenvector of L^T, normalized to sum 1.
            const Eigendecomposition es = eigendecomposition(L.transpose(), true);
            int one = 0;
            for (int k = 0; k <= n; ++k)
                if (std::abs(es.values[k] - 1.0) < std::abs(es.values[one] - 1.0)) one = k;
            Eigen::VectorXd l = es.vectors.col(one).real();
            l /= l.sum();
            const double chi = loop_limit_ring_weight(w, n);
            EXPECT_NEAR(l[0], 1 - n * chi, 1e-13) << to_string(w) << " n=" << n;
            for (int k = 1; k <= n; ++k) EXPECT_NEAR(l[k], chi, 1e-13) << to_string(w) << " n=" << n;
            // And the limit position is that mask applied to the 1-ring.
            const LimitResult lim = loop_limit(m, {w, LoopBoundary::EdgeOnly});
            Vec3 expect = Vec3::Zero();
            for (int k = 0; k <= n; ++k) expect += l[k] * m.positions[k];
            EXPECT_NEAR((lim.position[0] - expect).norm(), 0.0, 1e-13);
        }
    }
}

TEST(LoopLimit, HandValuesRegularAndBoundary) {
    // Valence 6, Loop weights: beta = 1/16, chi = 1/(6 + 6) = 1/12, centre 1/2.
    EXPECT_DOUBLE_EQ(loop_limit_ring_weight(LoopWeights::Loop, 6), 1.0 / 12);
    // Warren, n = 3: beta = 3/16, chi = 1/(3 + 2) = 1/5.
    EXPECT_DOUBLE_EQ(loop_limit_ring_weight(LoopWeights::Warren, 3), 0.2);
    // A single triangle: every vertex on the boundary, 2/3 v + 1/6 of each neighbour; with
    // the corner rule each is a corner and stays.
    TriMesh t;
    t.positions = {Vec3(0, 0, 0), Vec3(6, 0, 0), Vec3(0, 6, 0)};
    t.triangles = {{0, 1, 2}};
    const LimitResult edge = loop_limit(t, {LoopWeights::Loop, LoopBoundary::EdgeOnly});
    EXPECT_NEAR((edge.position[0] - Vec3(1, 1, 0)).norm(), 0, 1e-15);
    EXPECT_TRUE(std::isnan(edge.normal[0].x()));  // boundary normals are not computed
    const LimitResult corner = loop_limit(t, {LoopWeights::Loop, LoopBoundary::EdgeAndCorner});
    EXPECT_EQ(corner.position[1], t.positions[1]);
}

TEST(LoopLimit, NormalsPointOutwardOnAClosedConvexMesh) {
    TriMesh m;
    m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const LimitResult lim = loop_limit(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly});
    for (int v = 0; v < 6; ++v) {
        // By symmetry the limit normal of a vertex of the octahedron is its own direction.
        EXPECT_NEAR((lim.normal[v] - m.positions[v]).norm(), 0.0, 1e-15) << v;
        // chi(4) = 1/(4 + 3/(8 beta(4))), beta(4) = (5/8 - (3/8)^2)/4 = 31/256.
        const double chi = 1.0 / (4 + 3.0 / (8 * 31.0 / 256));
        EXPECT_NEAR(lim.position[v].norm(), 1 - 4 * chi, 1e-15);
    }
}

TEST(CatmullClarkLimit, CubeCornerHandValueAndNormal) {
    // Corner (1,1,1), n = 3: (9 v + 4 (ring sum (1,1,1)) + (diagonals sum (-1,-1,-1)... ))/24.
    // Ring: (-1,1,1), (1,-1,1), (1,1,-1), sum (1,1,1); diagonals: (-1,-1,1), (-1,1,-1),
    // (1,-1,-1), sum (-1,-1,-1). (9 + 4 - 1) / 24 = 1/2 in each coordinate.
    const LimitResult lim = catmull_clark_limit(quad_cube(), {CatmullClarkBoundary::EdgeOnly});
    EXPECT_NEAR((lim.position[7] - Vec3::Constant(0.5)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((lim.normal[7] - Vec3::Constant(1 / std::sqrt(3.0))).norm(), 0.0, 1e-15);
    EXPECT_NEAR((lim.normal[0] + Vec3::Constant(1 / std::sqrt(3.0))).norm(), 0.0, 1e-15);
}

TEST(CatmullClarkLimit, RefusesNonQuadsAroundAVertexAndTheMidpointAverageRule) {
    PolyMesh tet;
    tet.positions = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
    for (auto f : {std::array{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}) tet.add_face(f);
    EXPECT_THROW(catmull_clark_limit(tet, {CatmullClarkBoundary::EdgeOnly}), InputError);
    // After one level every face is a quad and the mask applies.
    EXPECT_NO_THROW(catmull_clark_limit(catmull_clark_subdivide(tet, {CatmullClarkBoundary::EdgeOnly}, 1),
                                        {CatmullClarkBoundary::EdgeOnly}));
    EXPECT_THROW(catmull_clark_limit(quad_cube(), {CatmullClarkBoundary::MidpointAverage}), InputError);
}

TEST(CatmullClarkLimit, IsTheLimitOfRefinement) {
    // The limit of vertex 7 after refining: its position converges to the mask's value.
    PolyMesh m = quad_cube();
    m.positions[7] += Vec3(0.3, -0.1, 0.2);
    const Vec3 limit = catmull_clark_limit(m, {CatmullClarkBoundary::EdgeOnly}).position[7];
    const PolyMesh fine = catmull_clark_subdivide(m, {CatmullClarkBoundary::EdgeOnly}, 7);
    const Vec3 after_many = catmull_clark_limit(fine, {CatmullClarkBoundary::EdgeOnly}).position[7];
    EXPECT_NEAR((after_many - limit).norm(), 0.0, 1e-13);
    EXPECT_LT((fine.positions[7] - limit).norm(), 1e-3);
}

TEST(LimitMatrix, HandRowsAndTheSamePositionsAsTheMasks) {
    // Loop, octahedron: every vertex of valence 4, centre 1 - 4 chi(4), ring chi(4) (above).
    TriMesh oct;
    oct.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
    oct.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const LoopOptions loop{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    const Eigen::MatrixXd l(loop_limit_matrix(oct, loop));
    const double chi = 1.0 / (4 + 3.0 / (8 * 31.0 / 256));
    EXPECT_DOUBLE_EQ(l(4, 4), 1 - 4 * chi);
    for (int v : {0, 1, 2, 3}) EXPECT_DOUBLE_EQ(l(4, v), chi);
    EXPECT_EQ(l(4, 5), 0.0);
    // Catmull-Clark, cube corner 7 (n = 3): 9/24 on itself, 4/24 on each ring vertex, 1/24 on
    // each diagonal, 0 on the opposite corner 0.
    const Eigen::MatrixXd c(catmull_clark_limit_matrix(quad_cube(), {CatmullClarkBoundary::EdgeOnly}));
    EXPECT_DOUBLE_EQ(c(7, 7), 9.0 / 24);
    for (int v : {3, 5, 6}) EXPECT_DOUBLE_EQ(c(7, v), 4.0 / 24);
    for (int v : {1, 2, 4}) EXPECT_DOUBLE_EQ(c(7, v), 1.0 / 24);
    EXPECT_EQ(c(7, 0), 0.0);
    // Boundary and corner rows: a single triangle, 2/3 and 1/6 each, or the identity.
    TriMesh t;
    t.positions = {Vec3(0, 0, 0), Vec3(6, 0, 0), Vec3(0, 6, 0)};
    t.triangles = {{0, 1, 2}};
    const Eigen::MatrixXd b(loop_limit_matrix(t, loop));
    EXPECT_DOUBLE_EQ(b(0, 0), 2.0 / 3);
    EXPECT_DOUBLE_EQ(b(0, 1), 1.0 / 6);
    EXPECT_DOUBLE_EQ(b(0, 2), 1.0 / 6);
    EXPECT_EQ(Eigen::MatrixXd(loop_limit_matrix(t, {LoopWeights::Loop, LoopBoundary::EdgeAndCorner})),
              Eigen::MatrixXd::Identity(3, 3));

    // On irregular meshes with boundaries the matrix gives the masks' positions to rounding.
    for (int n : {3, 5, 7, 11}) {
        const TriMesh f = loop_subdivide(fan(n), loop, 1);
        const LimitResult lim = loop_limit(f, loop);
        const Eigen::SparseMatrix<double, Eigen::RowMajor> m = loop_limit_matrix(f, loop);
        for (int v = 0; v < f.num_vertices(); ++v) {
            Vec3 p = Vec3::Zero();
            for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(m, v); it; ++it)
                p += it.value() * f.positions[static_cast<size_t>(it.col())];
            EXPECT_NEAR((p - lim.position[v]).norm(), 0.0, 1e-14) << "n=" << n << " v=" << v;
        }
    }
    const PolyMesh cc = catmull_clark_subdivide(quad_cube(), {CatmullClarkBoundary::EdgeOnly}, 1);
    const LimitResult cl = catmull_clark_limit(cc, {CatmullClarkBoundary::EdgeOnly});
    const Eigen::MatrixXd cm(catmull_clark_limit_matrix(cc, {CatmullClarkBoundary::EdgeOnly}));
    for (int v = 0; v < cc.num_vertices(); ++v) {
        Vec3 p = Vec3::Zero();
        for (int u = 0; u < cc.num_vertices(); ++u) p += cm(v, u) * cc.positions[static_cast<size_t>(u)];
        EXPECT_NEAR((p - cl.position[v]).norm(), 0.0, 1e-15) << v;
    }
    EXPECT_THROW(loop_limit_matrix(oct, {LoopWeights::Regularity, LoopBoundary::EdgeOnly}), InputError);
}

}  // namespace
}  // namespace crossdiv
