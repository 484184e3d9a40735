// Loop subdivision on tiny meshes whose refined positions are computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_split_flip.h"
#include "loop_test_meshes.h"

namespace crossdiv {
namespace {

using test::kLoopCorner;
using test::kLoopEdge;
using test::kWarrenEdge;
using test::tri_octahedron;
using test::tri_tetrahedron;

Vec3 edge_point(const TriMesh& coarse, const TriMesh& fine, int a, int b, const std::vector<VertexOrigin>& o) {
    for (size_t i = 0; i < o.size(); ++i)
        if (o[i].is_edge_point() && std::set<int>{o[i].a, o[i].b} == std::set<int>{a, b}) return fine.positions[i];
    ADD_FAILURE() << "no edge point for (" << a << ", " << b << ")";
    (void)coarse;
    return Vec3::Constant(NAN);
}

TEST(Loop, SeedExampleOddVertex) {
    // The seed's figure: p11 = 3/8 p1 + 3/8 p4 + 1/8 p6 + 1/8 p5, edge (p1, p4) between the
    // triangles (p1, p4, p6) and (p4, p1, p5). Indices 0..3 stand for p1, p4, p6, p5.
    TriMesh m;
    m.positions = {Vec3(0.3, -1.2, 2.0), Vec3(1.7, 0.4, -0.5), Vec3(0.9, 2.2, 0.1), Vec3(-0.6, -0.8, 1.3)};
    m.triangles = {{0, 1, 2}, {1, 0, 3}};
    LoopRefiner r(m, kLoopEdge);
    r.refine();
    const Vec3 expected = 3.0 / 8 * m.positions[0] + 3.0 / 8 * m.positions[1] + 1.0 / 8 * m.positions[2] +
                          1.0 / 8 * m.positions[3];
    const Vec3 got = edge_point(m, r.mesh(1), 0, 1, r.origins(1));
    EXPECT_NEAR((got - expected).norm(), 0.0, 4e-16);
}

TEST(Loop, TetrahedronByHand) {
    // Valence 3, beta = 3/16 in both families: v' = 7/16 v + 3/16 (-v) = v/4.
    // Edge (a, b): 3/8 (a + b) + 1/8 (c + d) = 3/8 (a + b) - 1/8 (a + b) = (a + b)/4.
    const TriMesh m = tri_tetrahedron();
    for (LoopOptions opt : {kLoopEdge, kWarrenEdge}) {
        LoopRefiner r(m, opt);
        r.refine();
        const TriMesh& f = r.mesh(1);
        ASSERT_EQ(f.num_vertices(), 10);
        ASSERT_EQ(f.num_faces(), 16);
        for (int v = 0; v < 4; ++v) EXPECT_EQ(f.positions[v], m.positions[v] / 4.0);
        const auto o = r.origins(1);
        for (int i = 4; i < 10; ++i)
            EXPECT_EQ(f.positions[i], (m.positions[o[i].a] + m.positions[o[i].b]) / 4.0) << "edge vertex " << i;
    }
}

TEST(Loop, OctahedronByHandBothFamilies) {
    // Valence 4, the ring of every vertex sums to zero: v' = (1 - 4 beta) v.
    // Loop: beta = 31/256, v' = 33/64 v. Warren: beta = 3/32, v' = 5/8 v.
    // Edge (+x, +y): 3/8 (x + y) + 1/8 (z - z) = 3/8 (1, 1, 0).
    const TriMesh m = tri_octahedron();
    const struct { LoopOptions opt; double scale; } cases[] = {{kLoopEdge, 33.0 / 64.0}, {kWarrenEdge, 5.0 / 8.0}};
    for (const auto& c : cases) {
        LoopRefiner r(m, c.opt);
        r.refine();
        for (int v = 0; v < 6; ++v) EXPECT_EQ(r.mesh(1).positions[v], c.scale * m.positions[v]);
        EXPECT_EQ(edge_point(m, r.mesh(1), 0, 2, r.origins(1)), Vec3(0.375, 0.375, 0.0));
    }
}

TEST(Loop, SingleTriangleUnderBothBoundaryRules) {
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(8, 0, 0), Vec3(0, 8, 0)};
    m.triangles = {{0, 1, 2}};
    // Edge-only: each vertex 3/4 itself + 1/8 each other vertex; edges are midpoints.
    const TriMesh e = loop_subdivide(m, kLoopEdge, 1);
    EXPECT_EQ(e.positions[0], Vec3(1, 1, 0));
    EXPECT_EQ(e.positions[1], Vec3(6, 1, 0));
    EXPECT_EQ(e.positions[2], Vec3(1, 6, 0));
    // Edge-and-corner: all three have one face, so all stay.
    const TriMesh c = loop_subdivide(m, kLoopCorner, 1);
    for (int v = 0; v < 3; ++v) EXPECT_EQ(c.positions[v], m.positions[v]);
    for (const TriMesh* r : {&e, &c}) {
        // Edges 0->1, 1->2, 2->0 are numbered 0, 1, 2: new vertices 3, 4, 5.
        EXPECT_EQ(r->positions[3], Vec3(4, 0, 0));
        EXPECT_EQ(r->positions[4], Vec3(4, 4, 0));
        EXPECT_EQ(r->positions[5], Vec3(0, 4, 0));
        EXPECT_EQ(r->triangles,
                  (std::vector<Triangle>{{0, 3, 5}, {1, 4, 3}, {2, 5, 4}, {3, 4, 5}}));
    }
}

TEST(Loop, OpenFanUnderBothBoundaryRules) {
    // Centre 0 with triangles (0,1,2), (0,2,3), (0,3,4): 0 is a boundary vertex with 3 faces,
    // 1 and 4 have one face (corners), 2 and 3 have two.
    TriMesh m;
    m.positions = {Vec3(0, 0, 8), Vec3(8, 0, 0), Vec3(0, 8, 0), Vec3(-8, 0, 0), Vec3(0, -8, 0)};
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    const TriMesh e = loop_subdivide(m, kLoopEdge, 1);
    const TriMesh c = loop_subdivide(m, kLoopCorner, 1);
    const auto& p = m.positions;
    const Vec3 centre = 0.75 * p[0] + 0.125 * (p[1] + p[4]);  // its boundary neighbours are 1 and 4
    EXPECT_EQ(e.positions[0], centre);
    EXPECT_EQ(c.positions[0], centre);
    EXPECT_EQ(e.positions[1], 0.75 * p[1] + 0.125 * (p[0] + p[2]));
    EXPECT_EQ(c.positions[1], p[1]);
    EXPECT_EQ(e.positions[4], 0.75 * p[4] + 0.125 * (p[0] + p[3]));
    EXPECT_EQ(c.positions[4], p[4]);
    EXPECT_EQ(e.positions[2], 0.75 * p[2] + 0.125 * (p[1] + p[3]));
    EXPECT_EQ(c.positions[2], e.positions[2]);
}

TEST(Loop, SubdivisionMatrixRowsSumToOneAndReproduceRefinement) {
    for (const TriMesh& m : {tri_tetrahedron(), tri_octahedron()}) {
        for (LoopOptions opt : {kLoopEdge, kWarrenEdge, kLoopCorner}) {
            const Eigen::SparseMatrix<double> S = loop_subdivision_matrix(m, opt);
            const TriMesh fine = loop_subdivide(m, opt, 1);
            ASSERT_EQ(S.rows(), fine.num_vertices());
            ASSERT_EQ(S.cols(), m.num_vertices());
            const Eigen::VectorXd rows = S * Eigen::VectorXd::Ones(S.cols());
            for (int i = 0; i < S.rows(); ++i) EXPECT_NEAR(rows[i], 1.0, 4e-16);
            Eigen::MatrixXd V(m.num_vertices(), 3);
            for (int v = 0; v < m.num_vertices(); ++v) V.row(v) = m.positions[v].transpose();
            const Eigen::MatrixXd SV = S * V;
            for (int i = 0; i < S.rows(); ++i) EXPECT_NEAR((SV.row(i).transpose() - fine.positions[i]).norm(), 0, 1e-15);
        }
    }
}

TEST(Loop, DerivedConnectivityEqualsRebuiltConnectivity) {
    // The refined tables are derived, not rebuilt; rebuilding from the refined triangles must
    // give the same neighbours (they are unique) and the same edges (as vertex pairs).
    TriMesh open;
    open.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 1)};
    open.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
    for (const TriMesh& m : {tri_tetrahedron(), tri_octahedron(), open}) {
        LoopRefiner r(m, kLoopEdge);
        r.refine(3);
        for (int l = 1; l <= 3; ++l) {
            const TriConnectivity& derived = r.connectivity(l);
            const TriConnectivity rebuilt = build_tri_connectivity(r.mesh(l));
            EXPECT_EQ(derived.neighbor_tris, rebuilt.neighbor_tris) << "level " << l;
            EXPECT_EQ(derived.neighbor_edges, rebuilt.neighbor_edges) << "level " << l;
            auto edge_set = [](const TriConnectivity& c) {
                std::set<std::pair<int, int>> s;
                for (auto [a, b] : c.edge_vertices) s.insert({std::min(a, b), std::max(a, b)});
                return s;
            };
            EXPECT_EQ(edge_set(derived), edge_set(rebuilt));
            for (int v = 0; v < r.mesh(l).num_vertices(); ++v)
                EXPECT_EQ(derived.is_boundary_vertex(v), rebuilt.is_boundary_vertex(v)) << "vertex " << v;
            for (int e = 0; e < derived.num_edges(); ++e) {
                const int c = derived.edge_corner[e];
                EXPECT_EQ(r.mesh(l).triangles[c / 3][c % 3], derived.edge_vertices[e][0]);
                EXPECT_EQ(derived.tri_edges[c / 3][c % 3], e);
            }
        }
    }
}

TEST(Loop, FastPathEqualsRefinerBitwise) {
    LoopRefiner r(tri_octahedron(), kWarrenEdge);
    r.refine(3);
    const TriMesh fast = loop_subdivide(tri_octahedron(), kWarrenEdge, 3);
    EXPECT_EQ(fast.positions, r.mesh(3).positions);
    EXPECT_EQ(fast.triangles, r.mesh(3).triangles);
}

TEST(Loop, ColorsFollowTheSameStencils) {
    TriMesh m = tri_tetrahedron();
    m.colors = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
    const TriMesh f = loop_subdivide(m, kLoopEdge, 1);
    ASSERT_EQ(f.colors.size(), f.positions.size());
    // Vertex 0: 7/16 (1,0,0) + 3/16 ((0,1,0) + (0,0,1) + (1,1,1)) = (10/16, 6/16, 6/16).
    EXPECT_EQ(f.colors[0], Vec3(10.0 / 16, 6.0 / 16, 6.0 / 16));
}

// Hexagonal bipyramid: poles 0 (z = 1) and 1 (z = -1) of valence 6, equator 2..7 of valence 4.
TriMesh hexagonal_bipyramid() {
    TriMesh m;
    m.positions = {Vec3(0, 0, 1), Vec3(0, 0, -1)};
    for (int i = 0; i < 6; ++i) m.positions.push_back(Vec3(std::cos(M_PI * i / 3), std::sin(M_PI * i / 3), 0));
    for (int i = 0; i < 6; ++i) {
        const int a = 2 + i, b = 2 + (i + 1) % 6;
        m.triangles.push_back({0, a, b});
        m.triangles.push_back({1, b, a});
    }
    return m;
}

TEST(Loop, TunedFamilyRowsOnTheHexagonalBipyramid) {
    // Regularity: the pole-equator edge (valences 6 and 4) takes the tuned row of valence 4
    // (.49923 on the pole, .25029 on the equator vertex, .12524 on its two equator neighbours);
    // the equator edge (4 and 4) keeps 3/8, 1/8; an equator vertex keeps .49954 on itself.
    const TriMesh m = hexagonal_bipyramid();
    const Eigen::SparseMatrix<double> S = loop_subdivision_matrix(m, {LoopWeights::Regularity, LoopBoundary::EdgeOnly});
    LoopRefiner r(m, {LoopWeights::Regularity, LoopBoundary::EdgeOnly});
    r.refine(1);
    const std::vector<VertexOrigin> o = r.origins(1);
    for (size_t row = 0; row < o.size(); ++row) {
        if (!o[row].is_edge_point()) continue;
        const std::set<int> ends{o[row].a, o[row].b};
        if (ends == std::set<int>{0, 2}) {
            EXPECT_NEAR(S.coeff(row, 0), 0.49923, 1e-15);
            EXPECT_NEAR(S.coeff(row, 2), 0.25029, 1e-15);
            EXPECT_NEAR(S.coeff(row, 3), 0.12524, 1e-15);
            EXPECT_NEAR(S.coeff(row, 7), 0.12524, 1e-15);
            EXPECT_EQ(S.coeff(row, 1), 0.0);
        }
        if (ends == std::set<int>{2, 3}) {
            EXPECT_EQ(S.coeff(row, 2), 0.375);
            EXPECT_EQ(S.coeff(row, 0), 0.125);
            EXPECT_EQ(S.coeff(row, 1), 0.125);
        }
    }
    EXPECT_NEAR(S.coeff(2, 2), 0.49954, 1e-15);
    EXPECT_NEAR(S.coeff(0, 0), 0.625, 1e-15);
    // The refinement is the matrix applied to the positions.
    const TriMesh fine = loop_subdivide(m, {LoopWeights::Regularity, LoopBoundary::EdgeOnly}, 1);
    for (int i = 0; i < S.rows(); ++i) {
        Vec3 p = Vec3::Zero();
        for (int v = 0; v < m.num_vertices(); ++v) p += S.coeff(i, v) * m.positions[v];
        EXPECT_NEAR((p - fine.positions[i]).norm(), 0.0, 1e-15);
    }
}

TEST(Loop, TunedFamiliesRefuseCreasesAndLimits) {
    PolyMesh tagged = to_poly_mesh(hexagonal_bipyramid());
    tagged.creases.edges.push_back({0, 2, 1.0f});
    EXPECT_THROW(loop_subdivide(tagged, {LoopWeights::Continuity, LoopBoundary::EdgeOnly}, 1), InputError);
    EXPECT_THROW(loop_limit(hexagonal_bipyramid(), {LoopWeights::Regularity, LoopBoundary::EdgeOnly}), InputError);
}

TEST(Loop, RejectsNonFiniteCoordinates) {
    TriMesh m = tri_tetrahedron();
    m.positions[2].y() = NAN;
    try {
        loop_subdivide(m, kLoopEdge, 1);
        FAIL() << "NaN accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 2"), std::string::npos) << e.what();
    }
}

TEST(Loop, AFiniteInputWhoseMasksOverflowIsRefusedNamingTheVertex) {
    // The octahedron's vertices (1,0,0), (0,1,0), ... scaled to DBL_MAX, then the top
    // pole moved to (M, M, M): the even point of (M, 0, 0) sums neighbours whose x reach 2M.
    const double M = std::numeric_limits<double>::max();
    TriMesh m = tri_octahedron();
    for (Vec3& p : m.positions) p *= M;
    m.positions[4] = Vec3(M, M, M);
    for (auto driver : {+[](const TriMesh& t) { return loop_subdivide(t, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1); },
                        +[](const TriMesh& t) { return loop_by_split_and_flip(t, {LoopWeights::Loop, LoopBoundary::EdgeOnly}); }}) {
        try {
            driver(m);
            ADD_FAILURE() << "no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("level 1, vertex "), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("is not finite"), std::string::npos) << e.what();
        }
    }
    // A quarter of that size, the same mesh refines to finite positions.
    for (Vec3& p : m.positions) p *= 0.25;
    for (const Vec3& p : loop_subdivide(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2).positions) EXPECT_TRUE(p.allFinite());
}

}  // namespace
}  // namespace crossdiv
