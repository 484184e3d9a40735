// Catmull-Clark, polygon connectivity and the generic stencil driver on tiny meshes whose
// refined positions are computed by hand.
#include <gtest/gtest.h>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "test_meshes.h"
#include "test_points.h"

namespace crossdiv {
namespace {

using test::kEdgeAndCorner;
using test::kEdgeOnly;
using test::kMidpointAverage;

using test::cube;
using test::square;

using test::expect_near;

TEST(PolyConnectivity, CubeIsClosedWithTwelveEdges) {
    const PolyMesh m = cube();
    const PolyConnectivity c = build_poly_connectivity(m);
    EXPECT_EQ(c.num_edges(), 12);
    for (int e = 0; e < 12; ++e) EXPECT_FALSE(c.is_boundary_edge(e));
    for (int v = 0; v < 8; ++v) {
        EXPECT_FALSE(c.is_boundary_vertex(v));
        int faces = 0;
        for (int k = c.vertex_corner[v];;) {
            ++faces;
            EXPECT_EQ(c.corner_vertex[k], v);
            k = c.next_around_vertex(k);
            if (k == c.vertex_corner[v]) break;
        }
        EXPECT_EQ(faces, 3);
    }
}

TEST(PolyConnectivity, SquareBoundaryWalkStartsWhereTheBoundaryComesIn) {
    const PolyConnectivity c = build_poly_connectivity(square());
    EXPECT_EQ(c.num_edges(), 4);
    for (int v = 0; v < 4; ++v) {
        EXPECT_TRUE(c.is_boundary_vertex(v));
        EXPECT_EQ(c.next_around_vertex(c.vertex_corner[v]), -1);
    }
}

TEST(PolyConnectivity, APyramidOverAHundredGonIsClosed) {
    // Apex 0 of valence 100 over the base polygon 1..100: 2 * 100
    // edges, each corner's twin leaves the corner's head and is twinned back.
    const int n = 100;
    PolyMesh m;
    m.positions.push_back(Vec3(0, 0, 1));
    for (int k = 0; k < n; ++k) m.positions.push_back(Vec3(std::cos(2 * M_PI * k / n), std::sin(2 * M_PI * k / n), 0));
    for (int k = 0; k < n; ++k) m.add_face({0, 1 + k, 1 + (k + 1) % n});
    std::vector<int> base;
    for (int k = n; k >= 1; --k) base.push_back(k);
    m.add_face(base);
    const PolyConnectivity c = build_poly_connectivity(m);
    EXPECT_EQ(c.num_edges(), 2 * n);
    for (int k = 0; k < static_cast<int>(c.twin.size()); ++k) {
        ASSERT_GE(c.twin[k], 0) << k;
        EXPECT_EQ(c.twin[c.twin[k]], k);
        EXPECT_EQ(c.corner_vertex[c.twin[k]], c.head(k));
    }
    m.add_face({0, 2, 1});  // a third face on the edges (0, 1) and (0, 2)
    EXPECT_THROW(build_poly_connectivity(m), NonManifoldInput);
}

TEST(PolyConnectivity, RefusesBadPolygonsNamingTheElement) {
    PolyMesh two_corner;
    two_corner.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
    two_corner.add_face({0, 1});
    EXPECT_THROW(build_poly_connectivity(two_corner), InputError);

    PolyMesh flipped = cube();
    std::swap(flipped.face_vertices[1], flipped.face_vertices[3]);  // face 0 reversed
    try {
        build_poly_connectivity(flipped);
        FAIL() << "inconsistent orientation accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("orientation"), std::string::npos) << e.what();
    }

    PolyMesh nan = square();
    nan.positions[2].y() = NAN;
    try {
        build_poly_connectivity(nan);
        FAIL() << "NaN accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 2"), std::string::npos) << e.what();
    }
}

TEST(CatmullClark, CubeHandValues) {
    const PolyMesh fine = catmull_clark_subdivide(cube(), kEdgeOnly, 1);
    ASSERT_EQ(fine.num_vertices(), 8 + 6 + 12);
    ASSERT_EQ(fine.num_faces(), 24);
    // Corner (1,1,1), n = 3: v/3 + (ring sum (1,1,1))/9 + (face points (1,0,0)+(0,1,0)+(0,0,1))/9.
    expect_near(fine.positions[7], Vec3::Constant(5.0 / 9.0));
    expect_near(fine.positions[0], Vec3::Constant(-5.0 / 9.0));
    // Face point of x = +1 (face 5).
    expect_near(fine.positions[8 + 5], Vec3(1, 0, 0));
    // Every edge point of the cube lies at 3/4 along two axes, e.g. (3/4, 3/4, 0) on the edge
    // from (1,1,-1) to (1,1,1): its ends and the face points (1,0,0) and (0,1,0), a quarter each.
    for (int e = 0; e < 12; ++e) {
        const Vec3 p = fine.positions[14 + e].cwiseAbs();
        EXPECT_NEAR(p.sum(), 1.5, 1e-15);
        EXPECT_NEAR(p.maxCoeff(), 0.75, 1e-15);
    }
    // Each coarse corner c becomes the quad (v, E, F, E') with v the old vertex, F the face point.
    for (int q = 0; q < 24; ++q) {
        EXPECT_LT(fine.face(q)[0], 8);
        EXPECT_EQ(fine.face(q)[2], 8 + q / 4);
    }
}

TEST(CatmullClark, TheLiteraturesOtherVertexRulesAtTheCubesCorner) {
    // Corner (1,1,1), n = 3: ring sum and face-point sum are both (1,1,1).
    // Regular weights, F/4 + R/2 + V/4 = V/2 + ring/(4n) + faces/(4n): 1/2 + 1/12 + 1/12 = 2/3.
    CatmullClarkOptions regular = kEdgeOnly;
    regular.vertex = CatmullClarkVertexRule::RegularWeights;
    expect_near(catmull_clark_subdivide(cube(), regular, 1).positions[7], Vec3::Constant(2.0 / 3.0));
    // Edge-point average: the three edge points at the corner are (0, 3/4, 3/4) and its
    // permutations, E = (1/2, 1/2, 1/2); (F + 2E + 0 V) / 3 = (1/3 + 1) / 3 = 4/9.
    CatmullClarkOptions edge_points = kEdgeOnly;
    edge_points.vertex = CatmullClarkVertexRule::EdgePointAverage;
    const PolyMesh fine = catmull_clark_subdivide(cube(), edge_points, 1);
    expect_near(fine.positions[7], Vec3::Constant(4.0 / 9.0));
    // Only vertex points change: the edge points are the standard rule's.
    expect_near(fine.positions[14], catmull_clark_subdivide(cube(), kEdgeOnly, 1).positions[14]);
    // The masks are affine at every valence.
    for (int n = 3; n <= 12; ++n)
        for (CatmullClarkVertexRule r : {CatmullClarkVertexRule::Standard, CatmullClarkVertexRule::RegularWeights,
                                         CatmullClarkVertexRule::EdgePointAverage}) {
            const CatmullClarkVertexMask m = catmull_clark_interior_vertex_mask(n, r);
            EXPECT_NEAR(m.self + n * (m.ring + m.face), 1.0, 1e-15) << n;
        }
}

TEST(CatmullClark, SquareBoundaryRules) {
    // Edge points are midpoints under every rule; the face point is the centre.
    for (const CatmullClarkOptions& o : {kEdgeOnly, kEdgeAndCorner, kMidpointAverage}) {
        const PolyMesh fine = catmull_clark_subdivide(square(), o, 1);
        ASSERT_EQ(fine.num_vertices(), 4 + 1 + 4);
        expect_near(fine.positions[4], Vec3(0.5, 0.5, 0));
        expect_near(fine.positions[5], Vec3(0.5, 0, 0));  // edge 0 = (0, 1)
    }
    // Vertex 0 at the origin, boundary neighbours (1,0,0) and (0,1,0).
    expect_near(catmull_clark_subdivide(square(), kEdgeOnly, 1).positions[0], Vec3(0.125, 0.125, 0));
    expect_near(catmull_clark_subdivide(square(), kEdgeAndCorner, 1).positions[0], Vec3(0, 0, 0));
    expect_near(catmull_clark_subdivide(square(), kMidpointAverage, 1).positions[0], Vec3(1.0 / 6, 1.0 / 6, 0));
}

TEST(CatmullClark, PentagonBecomesFiveQuadsAroundItsCentroid) {
    PolyMesh m;
    for (int k = 0; k < 5; ++k) m.positions.emplace_back(std::cos(2 * M_PI * k / 5), std::sin(2 * M_PI * k / 5), 0);
    m.add_face({0, 1, 2, 3, 4});
    const PolyMesh fine = catmull_clark_subdivide(m, kEdgeOnly, 1);
    ASSERT_EQ(fine.num_faces(), 5);
    for (int q = 0; q < 5; ++q) EXPECT_EQ(fine.face_size(q), 4);
    EXPECT_NEAR(fine.positions[5].norm(), 0.0, 1e-15);
}

TEST(CatmullClark, MatrixReproducesThePositionsAndRowsSumToOne) {
    PolyMesh m = cube();
    m.positions[3] += Vec3(0.1, -0.2, 0.3);  // break the symmetry
    for (const CatmullClarkOptions& o : {kEdgeOnly, kEdgeAndCorner, kMidpointAverage}) {
        const Eigen::SparseMatrix<double> S = catmull_clark_subdivision_matrix(m, o);
        const PolyMesh fine = catmull_clark_subdivide(m, o, 1);
        ASSERT_EQ(S.rows(), fine.num_vertices());
        Eigen::MatrixXd V(m.num_vertices(), 3);
        for (int v = 0; v < m.num_vertices(); ++v) V.row(v) = m.positions[v].transpose();
        const Eigen::MatrixXd SV = S * V;
        const Eigen::VectorXd sums = S * Eigen::VectorXd::Ones(m.num_vertices());
        for (int r = 0; r < S.rows(); ++r) {
            EXPECT_NEAR(sums[r], 1.0, 1e-15);
            expect_near(SV.row(r).transpose(), fine.positions[r]);
        }
    }
}

TEST(CatmullClark, ColorsAreRefinedWithTheSameStencils) {
    PolyMesh m = square();
    m.colors = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
    const PolyMesh fine = catmull_clark_subdivide(m, kEdgeOnly, 1);
    ASSERT_EQ(fine.colors.size(), fine.positions.size());
    expect_near(fine.colors[4], Vec3(0.5, 0.5, 0.5));
}

TEST(CatmullClark, RefusesANegativeLevelCountAndANonManifoldEdgeWhenToldTo) {
    EXPECT_THROW(catmull_clark_subdivide(cube(), kEdgeOnly, -1), InputError);
    PolyMesh fin = square();
    fin.positions.emplace_back(0.5, 0.5, 1);
    fin.positions.emplace_back(0.5, 0.5, -1);
    fin.add_face({1, 0, 4});
    fin.add_face({0, 1, 5});  // three faces on edge (0, 1)
    CatmullClarkOptions refuse = kEdgeOnly;
    refuse.nonmanifold = NonManifoldRule::Refuse;
    EXPECT_THROW(catmull_clark_subdivide(fin, refuse, 1), NonManifoldInput);
    // By default OpenSubdiv's rules refine it (nonmanifold_test.cpp): the edge's ends stay.
    const PolyMesh r = catmull_clark_subdivide(fin, kEdgeOnly, 1);
    EXPECT_EQ(r.positions[0], fin.positions[0]);
    EXPECT_EQ(r.positions[1], fin.positions[1]);
}

}  // namespace
}  // namespace crossdiv
