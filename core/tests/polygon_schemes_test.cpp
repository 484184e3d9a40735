// sqrt3, Doo-Sabin and the two Butterflies on tiny meshes whose refined positions and counts
// are computed by hand (the derivations are in the comments).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/butterfly.h"
#include "crossdiv/subdiv/doo_sabin.h"
#include "crossdiv/subdiv/sqrt3.h"
#include "test_meshes.h"
#include "test_points.h"

namespace crossdiv {
namespace {

// Hand values are exact rationals of small denominators; 1e-15 allows the last bit of a
// few-term sum of numbers of size ~1.
constexpr double kHand = 1e-15;

using test::expect_near;  // within 1e-15, as kHand

// The regular tetrahedron on alternate cube corners, outward faces; valence 3 everywhere.
PolyMesh regular_tetrahedron() {
    PolyMesh m;
    m.positions = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
    m.add_face({0, 1, 2});
    m.add_face({0, 3, 1});
    m.add_face({0, 2, 3});
    m.add_face({1, 3, 2});
    return m;
}

// One triangle, every edge on the boundary.
PolyMesh triangle() {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(0, 3, 0)};
    m.add_face({0, 1, 2});
    return m;
}

using test::cube;

// A regular (valence 6) triangulated torus of n x n quads split by one diagonal.
PolyMesh regular_torus(int n) {
    PolyMesh m;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / n;
            m.positions.emplace_back((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v));
        }
    const auto id = [n](int i, int j) { return ((i + n) % n) * n + (j + n) % n; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

// ---- sqrt3 ------------------------------------------------------------------------------

TEST(Sqrt3Mask, KobbeltAlphaAtValence3And6) {
    // alpha_3 = (4 - 2 cos 120deg) / 9 = 5/9; alpha_6 = (4 - 1) / 9 = 1/3.
    EXPECT_NEAR(sqrt3_interior_vertex_mask(3).self, 4.0 / 9, kHand);
    EXPECT_NEAR(sqrt3_interior_vertex_mask(3).ring, 5.0 / 27, kHand);
    EXPECT_NEAR(sqrt3_interior_vertex_mask(6).self, 2.0 / 3, kHand);
    EXPECT_NEAR(sqrt3_interior_vertex_mask(6).ring, 1.0 / 18, kHand);
}

TEST(Sqrt3, TetrahedronOneStepByHand) {
    const PolyMesh r = sqrt3_subdivide(regular_tetrahedron(), {Sqrt3Parity::CountFromInput}, 1);
    // 4 old + 4 centroids; two faces per edge (6 edges).
    ASSERT_EQ(r.num_vertices(), 8);
    ASSERT_EQ(r.num_faces(), 12);
    // v0 = 4/9 (1,1,1) + 5/27 * (sum of the others = (-1,-1,-1)) = 7/27 (1,1,1).
    expect_near(r.positions[0], Vec3(7, 7, 7) / 27.0);
    // Centroid of face 3 (v1, v3, v2) = (-1/3, -1/3, -1/3).
    expect_near(r.positions[4 + 3], Vec3(-1, -1, -1) / 3.0);
    // Every old vertex now has valence 3 among the new points only: the old edges are gone.
    const PolyConnectivity c = build_poly_connectivity(r);
    for (int e = 0; e < c.num_edges(); ++e) EXPECT_TRUE(c.edge_vertices[e][0] >= 4 || c.edge_vertices[e][1] >= 4);
}

TEST(Sqrt3, BoundaryWaitsOneStepThenIsTrisected) {
    // Step 0 keeps the boundary: 3 faces (a, b, m), m = (1, 1, 0).
    const PolyMesh one = sqrt3_subdivide(triangle(), {Sqrt3Parity::CountFromInput}, 1);
    ASSERT_EQ(one.num_vertices(), 4);
    ASSERT_EQ(one.num_faces(), 3);
    expect_near(one.positions[0], Vec3(0, 0, 0));
    expect_near(one.positions[3], Vec3(1, 1, 0));
    // Step 1 trisects each boundary edge (2 points per face) and smooths the boundary:
    // a' = (4 c + 19 a + 4 b) / 27 = (12, 12, 0) / 27; m (valence 3) = 4/9 m + 5/27 (a + b + c)
    // = (1, 1, 0); faces = 2 per interior edge (3) + 1 per boundary face (3).
    const PolyMesh two = sqrt3_subdivide(triangle(), {Sqrt3Parity::CountFromInput}, 2);
    ASSERT_EQ(two.num_vertices(), 10);
    ASSERT_EQ(two.num_faces(), 9);
    expect_near(two.positions[0], Vec3(12, 12, 0) / 27.0);
    expect_near(two.positions[3], Vec3(1, 1, 0));
    // Face 0 of level 1 is (a, b, m): its points trisect a -> b, nearer a first:
    // (c + 16 a + 10 b) / 27 = (30, 3, 0) / 27 and (10 a + 16 b + c) / 27 = (48, 3, 0) / 27.
    expect_near(two.positions[4], Vec3(30, 3, 0) / 27.0);
    expect_near(two.positions[5], Vec3(48, 3, 0) / 27.0);
    // Restarting the generation each level never touches the boundary.
    const PolyMesh restart = sqrt3_subdivide(triangle(), {Sqrt3Parity::RestartEachLevel}, 2);
    EXPECT_EQ(restart.num_vertices(), 7);
    expect_near(restart.positions[0], Vec3(0, 0, 0));
}

TEST(Sqrt3, RefusesAQuadNamingTheFace) {
    try {
        sqrt3_subdivide(test::square(), {Sqrt3Parity::CountFromInput}, 0);
        FAIL() << "a quad was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("face 0: has 4 corners; sqrt3 refines triangles only"), std::string::npos)
            << e.what();
    }
}

TEST(Sqrt3, BoundaryStepRefusesAFaceWithTwoBoundaryEdges) {
    const PolyMesh t = triangle();
    EXPECT_THROW(sqrt3_step(t, build_poly_connectivity(t), true), InputError);
}

// ---- Doo-Sabin ----------------------------------------------------------------------------

TEST(DooSabinMask, QuadIsTheBiquadraticBSplineTriangleIsTwoThirds) {
    EXPECT_NEAR(doo_sabin_weight(4, 0), 9.0 / 16, kHand);
    EXPECT_NEAR(doo_sabin_weight(4, 1), 3.0 / 16, kHand);
    EXPECT_NEAR(doo_sabin_weight(4, 2), 1.0 / 16, kHand);
    EXPECT_NEAR(doo_sabin_weight(4, 3), 3.0 / 16, kHand);
    EXPECT_NEAR(doo_sabin_weight(3, 0), 2.0 / 3, kHand);
    EXPECT_NEAR(doo_sabin_weight(3, 1), 1.0 / 6, kHand);
    for (int n = 3; n <= 12; ++n) {  // affine: the weights sum to one
        double sum = 0;
        for (int k = 0; k < n; ++k) sum += doo_sabin_weight(n, k);
        EXPECT_NEAR(sum, 1.0, 1e-15) << n;
    }
}

TEST(DooSabinMask, CatmullClarksWeightsAreTheAverageOfVertexMidpointsAndCentroid) {
    // Quads: the same as Doo and Sabin's.
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(doo_sabin_weight(4, k, DooSabinWeights::CatmullClark), doo_sabin_weight(4, k), kHand);
    // Corner 0 of triangle() (0,0,0), (3,0,0), (0,3,0): the average of (0,0,0), the midpoints
    // (3/2,0,0) and (0,3/2,0) and the centroid (1,1,0) is (5/8, 5/8, 0); Doo and Sabin's
    // 2/3, 1/6, 1/6 give (1/2, 1/2, 0).
    const PolyMesh cc = doo_sabin_subdivide(triangle(), {DooSabinBoundary::ChaikinBoundary, DooSabinWeights::CatmullClark}, 1);
    expect_near(cc.positions[0], Vec3(5.0 / 8, 5.0 / 8, 0));
    expect_near(doo_sabin_subdivide(triangle(), {DooSabinBoundary::ChaikinBoundary}, 1).positions[0], Vec3(0.5, 0.5, 0));
    for (int n = 3; n <= 12; ++n) {
        double sum = 0;
        for (int k = 0; k < n; ++k) sum += doo_sabin_weight(n, k, DooSabinWeights::CatmullClark);
        EXPECT_NEAR(sum, 1.0, 1e-15) << n;
    }
}

TEST(DooSabin, CubeOneLevelByHand) {
    const PolyMesh r = doo_sabin_subdivide(cube(), {DooSabinBoundary::ChaikinBoundary}, 1);
    // One point per corner (24); faces F + E + V = 6 + 12 + 8.
    ASSERT_EQ(r.num_vertices(), 24);
    ASSERT_EQ(r.num_faces(), 26);
    // Corner 0 of face 0 (vertex 0 = (-1,-1,-1) of the z = -1 face): 9/16 v0 + 3/16 (v2 + v1)
    // + 1/16 v3 = (-1/2, -1/2, -1).
    expect_near(r.positions[0], Vec3(-0.5, -0.5, -1));
    // The V-face of a valence-3 vertex is a triangle, the E-faces are quads.
    int triangles = 0, quads = 0;
    for (int f = 0; f < r.num_faces(); ++f) (r.face_size(f) == 3 ? triangles : quads) += 1;
    EXPECT_EQ(triangles, 8);
    EXPECT_EQ(quads, 18);
    // Closed and consistently oriented: the next level's connectivity accepts it.
    EXPECT_NO_THROW(build_poly_connectivity(r));
}

TEST(DooSabin, SquareBoundaryIsChaikinsCornerCutting) {
    const PolyMesh r = doo_sabin_subdivide(test::square(), {DooSabinBoundary::ChaikinBoundary}, 1);
    // 4 corner points + 2 Chaikin points on each of the 4 edges; faces 1 F + 4 E + 4 V.
    ASSERT_EQ(r.num_vertices(), 12);
    ASSERT_EQ(r.num_faces(), 9);
    expect_near(r.positions[0], Vec3(0.25, 0.25, 0));
    expect_near(r.positions[4], Vec3(0.25, 0, 0));  // edge 0 -> 1: 3/4 a + 1/4 b
    expect_near(r.positions[5], Vec3(0.75, 0, 0));
    const PolyConnectivity c = build_poly_connectivity(r);
    int boundary_edges = 0;
    for (int e = 0; e < c.num_edges(); ++e) boundary_edges += c.is_boundary_edge(e);
    EXPECT_EQ(boundary_edges, 8);  // the octagon of Chaikin's points
    for (int v = 0; v < 4; ++v) EXPECT_FALSE(c.is_boundary_vertex(v));
    // CGAL's rule keeps the F-face only.
    const PolyMesh dropped = doo_sabin_subdivide(test::square(), {DooSabinBoundary::DropBorderFaces}, 1);
    EXPECT_EQ(dropped.num_vertices(), 4);
    EXPECT_EQ(dropped.num_faces(), 1);
}

TEST(DooSabin, APolygonOfManySidesTakesItsCornerPointsThroughFourierSums) {
    // Above 32 sides the corner points are stated through sums over the face (Catmull and
    // Clark's weights through the centroid alone): against
    // the published weights summed term by term, within 1e-14 of the polygon's size: either
    // side sums n terms, whose rounding grows about as sqrt(n) eps (7e-15 at n = 1000). One
    // polygon of n sides, its corner points the first n rows.
    for (const int n : {33, 100, 1000}) {
        PolyMesh m;
        std::vector<int> face;
        for (int k = 0; k < n; ++k) {
            const double a = 2 * M_PI * k / n;
            m.positions.push_back(Vec3((1 + 0.3 * std::cos(2 * a)) * std::cos(a), std::sin(a), 0.2 * std::sin(3 * a)));
            face.push_back(k);
        }
        m.add_face(face);
        for (DooSabinWeights w : {DooSabinWeights::DooSabin, DooSabinWeights::CatmullClark}) {
            const PolyMesh r = doo_sabin_subdivide(m, {DooSabinBoundary::ChaikinBoundary, w}, 1);
            double worst = 0;
            for (int i = 0; i < n; ++i) {
                Vec3 expected = Vec3::Zero();
                for (int k = 0; k < n; ++k) expected += doo_sabin_weight(n, k, w) * m.positions[static_cast<size_t>((i + k) % n)];
                worst = std::max(worst, (r.positions[static_cast<size_t>(i)] - expected).norm());
            }
            EXPECT_LE(worst, 1e-14) << "n = " << n << ", " << to_string(w);
        }
    }
}

// ---- Butterflies --------------------------------------------------------------------------

TEST(ButterflyMask, ZorinStencilsSumToOne) {
    const std::vector<double> s3 = modified_butterfly_stencil(3), s4 = modified_butterfly_stencil(4);
    EXPECT_EQ(s3, (std::vector<double>{5.0 / 12, -1.0 / 12, -1.0 / 12, 0.75}));
    EXPECT_EQ(s4, (std::vector<double>{3.0 / 8, 0.0, -1.0 / 8, 0.0, 0.75}));
    for (int k = 5; k <= 30; ++k) {
        const std::vector<double> s = modified_butterfly_stencil(k);
        // s_0 = (1/4 + 1 + 1/2) / K; the centre weight is 3/4 (the ring sums to 1/4).
        EXPECT_NEAR(s[0], 1.75 / k, kHand);
        EXPECT_NEAR(s[k], 0.75, 1e-14) << k;
    }
}

TEST(Butterfly, TetrahedronClassicIsTheMidpointModifiedIsNot) {
    // Classic: 1/2 (a0 + a1) + 1/8 (b0 + b1) - 1/16 (4 wing points). On a tetrahedron every
    // wing point is b0 or b1, twice each, so the b terms cancel: the midpoint (1, 0, 0) of
    // v0 = (1,1,1), v1 = (1,-1,-1).
    const PolyMesh t = regular_tetrahedron();
    const PolyConnectivity c = build_poly_connectivity(t);
    int e01 = -1;
    for (int e = 0; e < c.num_edges(); ++e)
        if (std::min(c.edge_vertices[e][0], c.edge_vertices[e][1]) == 0 && std::max(c.edge_vertices[e][0], c.edge_vertices[e][1]) == 1)
            e01 = e;
    ASSERT_GE(e01, 0);
    const PolyMesh classic = butterfly_subdivide(t, ButterflyVariant::Classic, 1);
    expect_near(classic.positions[4 + e01], Vec3(1, 0, 0));
    // Modified: both endpoints have valence 3, so the average of the two K = 3 stencils:
    // 7/12 (a0 + a1) - 1/12 (b0 + b1) = 7/12 (2,0,0) - 1/12 (-2,0,0) = (4/3, 0, 0).
    const PolyMesh modified = butterfly_subdivide(t, ButterflyVariant::Modified, 1);
    expect_near(modified.positions[4 + e01], Vec3(4.0 / 3, 0, 0));
    for (int v = 0; v < 4; ++v) EXPECT_EQ(modified.positions[v], t.positions[v]);  // interpolating
    EXPECT_EQ(modified.num_faces(), 16);
}

TEST(Butterfly, RegularPatchHasThePublishedEightPointStencil) {
    const PolyMesh torus = regular_torus(6);
    const RefinementStep step = butterfly_step(torus, build_poly_connectivity(torus), ButterflyVariant::Modified);
    const Eigen::SparseMatrix<double, Eigen::RowMajor> S = step.stencils.matrix();
    const std::vector<double> published{-1.0 / 16, -1.0 / 16, -1.0 / 16, -1.0 / 16, 1.0 / 8, 1.0 / 8, 0.5, 0.5};
    for (int r = torus.num_vertices(); r < S.rows(); ++r) {
        std::vector<double> w;
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(S, r); it; ++it) w.push_back(it.value());
        std::sort(w.begin(), w.end());
        EXPECT_EQ(w, published) << "edge row " << r;
    }
    // Both variants are the same scheme there, bit for bit.
    EXPECT_EQ(butterfly_subdivide(torus, ButterflyVariant::Classic, 2).positions,
              butterfly_subdivide(torus, ButterflyVariant::Modified, 2).positions);
}

TEST(Butterfly, WingsBeyondTheBoundaryAreReflectedOrTheOppositeVertex) {
    // Square (0,0,0), (1,0,1), (1,1,0), (0,1,1) split along the diagonal 0-2 into (0,1,2) and
    // (0,2,3). The diagonal's four wing edges are all boundary edges: (1,2) and (0,1) in the
    // first triangle, (2,3) and (3,0) in the second.
    // Reflected: wings v1+v2-v0, v0+v1-v2, v2+v3-v0, v3+v0-v2 sum to 2(v1 + v3), so the point
    // is 1/2 (v0 + v2) + 1/8 (v1 + v3) - 1/16 * 2 (v1 + v3) = (v0 + v2) / 2 = (1/2, 1/2, 0).
    // Opposite vertex: wings v0, v2, v0, v2, so 3/8 (v0 + v2) + 1/8 (v1 + v3)
    // = (3/8 + 1/8, 3/8 + 1/8, 1/4) = (1/2, 1/2, 1/4): Loop's edge mask.
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 1), Vec3(1, 1, 0), Vec3(0, 1, 1)};
    m.add_face({0, 1, 2});
    m.add_face({0, 2, 3});
    const PolyConnectivity c = build_poly_connectivity(m);
    const int diagonal = 4 + c.corner_edge[2];  // corner 2 of face 0 runs 2 -> 0
    for (ButterflyVariant v : {ButterflyVariant::Classic, ButterflyVariant::Modified}) {
        expect_near(butterfly_subdivide(m, v, 1).positions[diagonal], Vec3(0.5, 0.5, 0));
        expect_near(butterfly_subdivide(m, v, 1, ButterflyWings::OppositeVertex).positions[diagonal], Vec3(0.5, 0.5, 0.25));
    }
    // Boundary edges take the four-point rule under both wing rules.
    const PolyMesh reflected = butterfly_subdivide(m, ButterflyVariant::Classic, 1);
    const PolyMesh opposite = butterfly_subdivide(m, ButterflyVariant::Classic, 1, ButterflyWings::OppositeVertex);
    for (int e = 0; e < c.num_edges(); ++e) {
        if (4 + e != diagonal) {
            EXPECT_EQ(reflected.positions[4 + e], opposite.positions[4 + e]) << e;
        }
    }
}

TEST(Butterfly, APoleOfLargeValenceTakesTheKPointStencilThroughItsFourierSums) {
    // Bicones whose poles have valence K above the direct stencil's limit (32), a rim
    // that wobbles so that every Fourier sum matters. Each edge point against Zorin's K-point
    // stencils summed term by term around both endpoints (the rim vertices have valence 4),
    // half each: within 1e-14 of the mesh's size, as either side sums K terms, whose rounding
    // grows about as sqrt(K) eps (7e-15 at K = 1000).
    for (const int K : {33, 64, 360, 1000}) {
        PolyMesh m;
        m.positions.push_back(Vec3(0.1, -0.05, 0.7));
        for (int k = 0; k < K; ++k) {
            const double a = 2 * M_PI * k / K;
            m.positions.push_back(Vec3((1 + 0.2 * std::cos(3 * a)) * std::cos(a), std::sin(a), 0.1 * std::sin(5 * a)));
        }
        m.positions.push_back(Vec3(-0.1, 0.02, -0.6));
        for (int k = 0; k < K; ++k) m.add_face({0, 1 + k, 1 + (k + 1) % K});
        for (int k = 0; k < K; ++k) m.add_face({K + 1, 1 + (k + 1) % K, 1 + k});
        const PolyConnectivity c = build_poly_connectivity(m);
        const PolyMesh fine = butterfly_subdivide(m, ButterflyVariant::Modified, 1);
        const auto k_point = [&](int corner) {
            const int v = c.corner_vertex[corner];
            int valence = 0;
            for (int x = corner;;) {
                ++valence;
                x = c.next_around_vertex(x);
                if (x == corner) break;
            }
            const std::vector<double> s = modified_butterfly_stencil(valence);
            Vec3 sum = s[static_cast<size_t>(valence)] * m.positions[v];
            int j = 0;
            for (int x = corner;;) {
                sum += s[static_cast<size_t>(j++)] * m.positions[c.head(x)];
                x = c.next_around_vertex(x);
                if (x == corner) break;
            }
            return sum;
        };
        double worst = 0;
        for (int e = 0; e < c.num_edges(); ++e) {
            const int corner = c.edge_corner[e];
            const Vec3 expected = 0.5 * k_point(corner) + 0.5 * k_point(c.twin[corner]);
            worst = std::max(worst, (fine.positions[static_cast<size_t>(m.num_vertices() + e)] - expected).norm());
        }
        EXPECT_LE(worst, 1e-14) << "K = " << K;
    }
}

TEST(Butterfly, OtherFaceWingsTakeVtksBoundaryChoices) {
    // The four-triangle pyramid: apex 0 = (0,0,1), interior, 4 faces; corners 1..4 = (1,0,0),
    // (0,1,0), (-1,0,0), (0,-1,0) on the boundary, 2 faces each. The spoke 0 -> 1:
    // OpenMesh's choice (reflected wings) reads the apex's K-point stencil alone (the corner
    // is on the boundary): 3/4 apex + 3/8 c1 - 1/8 c3 = (1/2, 0, 3/4).
    // VTK's (other-face wings): neither end has 6 faces, so half of each end's stencil; the
    // corner's walk meets the boundary, so its half is the eight-point stencil, whose wings
    // beyond the boundary edges (1,2) and (4,1) are the other triangle's apex (c4, c2):
    // 1/2 (apex + c1) + 1/8 (c2 + c4) - 1/16 (c3 + c4 + c3 + c2) = (5/8, 0, 1/2).
    // Half each: (9/16, 0, 5/8).
    PolyMesh m;
    m.positions = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)};
    for (int k = 0; k < 4; ++k) m.add_face({0, 1 + k, 1 + (k + 1) % 4});
    const PolyConnectivity c = build_poly_connectivity(m);
    const int spoke = 5 + c.corner_edge[0];  // corner 0 of face 0 runs 0 -> 1
    expect_near(butterfly_subdivide(m, ButterflyVariant::Modified, 1).positions[spoke], Vec3(0.5, 0, 0.75));
    expect_near(butterfly_subdivide(m, ButterflyVariant::Modified, 1, ButterflyWings::OtherFaceVertex).positions[spoke],
                Vec3(9.0 / 16, 0, 5.0 / 8));
    // The classic scheme takes the eight-point stencil everywhere: with these wings, (5/8, 0, 1/2).
    expect_near(butterfly_subdivide(m, ButterflyVariant::Classic, 1, ButterflyWings::OtherFaceVertex).positions[spoke],
                Vec3(5.0 / 8, 0, 0.5));
}

TEST(Butterfly, BoundaryEdgeIsTheFourPointRule) {
    // Square split into two triangles: the boundary loop is 0, 1, 2, 3. Edge 0 -> 1 gets
    // 9/16 (v0 + v1) - 1/16 (v3 + v2) = (1/2, -1/8, 0).
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    m.add_face({0, 1, 2});
    m.add_face({0, 2, 3});
    const PolyMesh r = butterfly_subdivide(m, ButterflyVariant::Modified, 1);
    const PolyConnectivity c = build_poly_connectivity(m);
    expect_near(r.positions[4 + c.corner_edge[0]], Vec3(0.5, -0.125, 0));
}

}  // namespace
}  // namespace crossdiv
