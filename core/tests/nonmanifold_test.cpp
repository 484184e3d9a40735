// OpenSubdiv's non-manifold rules in core (nonmanifold.h), computed by hand on the smallest
// meshes that show each: an edge of three faces, a bowtie vertex, an interior non-manifold
// crease; and what is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "loop_test_meshes.h"

namespace crossdiv {
namespace {

using test::kLoopEdge;

/// Three triangles on the edge (0, 1): vertices 2, 3, 4 are their tips.
PolyMesh book3() {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0.5), Vec3(-0.5, 0.8, 0.5), Vec3(-0.5, -0.8, 0.3)};
    m.add_face({1, 0, 2});
    m.add_face({0, 1, 3});
    m.add_face({1, 0, 4});
    return m;
}

TEST(NonManifold, AnEdgeOfThreeFacesIsSharpAndItsEndsAreCorners) {
    const PolyMesh m = book3();
    EXPECT_EQ(nonmanifold_vertices(m), (std::vector<int>{0, 1}));
    EXPECT_THROW(loop_subdivide(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly, CreaseMethod::Uniform,
                                    NonManifoldRule::Refuse}, 1),
                 NonManifoldInput);
    const PolyMesh r = loop_subdivide(m, kLoopEdge, 1);
    ASSERT_EQ(r.num_vertices(), 5 + 7);  // 7 edges: the shared one and two per page
    ASSERT_EQ(r.num_faces(), 12);
    // Ends of the non-manifold edge: corners, they stay.
    EXPECT_EQ(r.positions[0], m.positions[0]);
    EXPECT_EQ(r.positions[1], m.positions[1]);
    // A tip has two boundary edges: the crease rule 3/4, 1/8, 1/8.
    EXPECT_TRUE(r.positions[2].isApprox(0.75 * m.positions[2] + 0.125 * (m.positions[0] + m.positions[1])));
    // The shared edge (numbered first, at corner 0) is sharp: its midpoint.
    const std::vector<std::array<int, 2>> edges = nonmanifold_edges(m);
    ASSERT_EQ(edges.size(), 7u);
    EXPECT_EQ(edges[0], (std::array<int, 2>{1, 0}));
    EXPECT_TRUE(r.positions[5].isApprox(0.5 * (m.positions[0] + m.positions[1])));

    // Catmull-Clark on the same pages: the same corners and crease tips, face points the centroids.
    const PolyMesh cc = catmull_clark_subdivide(m, {CatmullClarkBoundary::EdgeOnly}, 1);
    EXPECT_EQ(cc.positions[0], m.positions[0]);
    EXPECT_TRUE(cc.positions[5].isApprox((m.positions[1] + m.positions[0] + m.positions[2]) / 3.0));
}

TEST(NonManifold, ABowtieVertexIsACornerAndTheFansAreRefinedApart) {
    // Two triangles meeting only at vertex 0.
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0.5, 0.2), Vec3(1, -0.5, 0), Vec3(-1, 0.5, 0), Vec3(-1, -0.5, 0.3)};
    m.add_face({0, 2, 1});
    m.add_face({0, 3, 4});
    EXPECT_EQ(nonmanifold_vertices(m), std::vector<int>{0});
    const PolyMesh r = loop_subdivide(m, kLoopEdge, 1);
    EXPECT_EQ(r.positions[0], m.positions[0]);
    // Vertex 1 is an ordinary boundary corner of its triangle: crease rule on its two edges.
    EXPECT_TRUE(r.positions[1].isApprox(0.75 * m.positions[1] + 0.125 * (m.positions[0] + m.positions[2])));
}

TEST(NonManifold, CatmullClarksMidpointAverageBoundaryBesideABowtie) {
    // The same two triangles under Catmull-Clark's midpoint-average rule (OpenMesh's): the
    // bowtie vertex keeps OpenSubdiv's corner rule, a manifold boundary vertex takes the rule's
    // mask (2/3 itself, 1/6 each boundary neighbour) where edge-only takes 3/4 and 1/8.
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0.5, 0.2), Vec3(1, -0.5, 0), Vec3(-1, 0.5, 0), Vec3(-1, -0.5, 0.3)};
    m.add_face({0, 2, 1});
    m.add_face({0, 3, 4});
    const PolyMesh r = catmull_clark_subdivide(m, {CatmullClarkBoundary::MidpointAverage}, 1);
    EXPECT_EQ(r.positions[0], m.positions[0]);
    EXPECT_TRUE(r.positions[1].isApprox(2.0 / 3.0 * m.positions[1] + (m.positions[0] + m.positions[2]) / 6.0))
        << r.positions[1].transpose();
    const PolyMesh e = catmull_clark_subdivide(m, {CatmullClarkBoundary::EdgeOnly}, 1);
    EXPECT_TRUE(e.positions[1].isApprox(0.75 * m.positions[1] + 0.125 * (m.positions[0] + m.positions[2])));
    // The refusal under NonManifoldRule::Refuse stands.
    CatmullClarkOptions refuse{CatmullClarkBoundary::MidpointAverage};
    refuse.nonmanifold = NonManifoldRule::Refuse;
    EXPECT_THROW(catmull_clark_subdivide(m, refuse, 1), NonManifoldInput);
}

/// An open fan of four triangles around vertex 0 (spokes 1..5 on a half circle, lifted), and
/// the same fan turned and shifted: vertices 6..10, joined at vertex 0 in a bowtie.
PolyMesh fan4(bool bowtie) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0)};
    for (int k = 0; k <= 4; ++k)
        m.positions.push_back(Vec3(std::cos(k * M_PI / 4), std::sin(k * M_PI / 4), 0.1 * k * k));
    for (int k = 1; k <= 4; ++k) m.add_face({0, k, k + 1});
    if (!bowtie) return m;
    for (int k = 0; k <= 4; ++k)
        m.positions.push_back(Vec3(-std::cos(k * M_PI / 4), -std::sin(k * M_PI / 4), -0.2 * k));
    for (int k = 6; k <= 9; ++k) m.add_face({0, k, k + 1});
    return m;
}

TEST(NonManifold, TheTunedEdgeMaskReadsTheFanThatHoldsTheEdge) {
    // Vertex 0's open fan of 4 faces reads 2 (4 - 1) = 6, as a manifold boundary vertex of 4
    // faces; spoke 2 has 2 faces, boundary: it reads max(2, 3) = 3. So the edge (0, 2) takes
    // the regularity table's row of valence 3: .15658 on spoke 2, .14427 on each opposite
    // vertex (spokes 1 and 3), 1 - .15658 - 2 (.14427) = .55488 on vertex 0. In the bowtie
    // vertex 0 has 8 faces and 10 edges in two fans; each fan reads 6 as if alone.
    const LoopOptions regularity{LoopWeights::Regularity, LoopBoundary::EdgeOnly};
    for (bool bowtie : {false, true}) {
        SCOPED_TRACE(bowtie ? "bowtie" : "one fan");
        const PolyMesh m = fan4(bowtie);
        const PolyMesh r = loop_subdivide(m, regularity, 1);
        const std::vector<std::array<int, 2>> edges = nonmanifold_edges(m);
        const auto it = std::find_if(edges.begin(), edges.end(), [](const std::array<int, 2>& e) {
            return std::min(e[0], e[1]) == 0 && std::max(e[0], e[1]) == 2;
        });
        ASSERT_NE(it, edges.end());
        // Face order numbers the edges the same in both refinements (manifold and not).
        const Vec3& p = r.positions[static_cast<size_t>(m.num_vertices() + (it - edges.begin()))];
        const Vec3 expected = (1 - .15658 - 2 * .14427) * m.positions[0] + .15658 * m.positions[2] +
                              .14427 * (m.positions[1] + m.positions[3]);
        EXPECT_LE((p - expected).norm(), 1e-15) << p.transpose() << " against " << expected.transpose();
    }
    // The bowtie's vertex 0 is a corner; in the fan alone, a boundary vertex (3/4, 1/8, 1/8).
    EXPECT_EQ(loop_subdivide(fan4(true), regularity, 1).positions[0], Vec3(0, 0, 0));
}

TEST(NonManifold, AnInteriorNonManifoldCreaseKeepsTheCreaseRule) {
    // Three strips of two triangles on each side of p1 along the seam p0-p1-p2: p1 has two
    // non-manifold edges, no boundary edge and 9 faces on 8 edges, so Far does not sharpen it.
    PolyMesh m;
    m.positions = {Vec3(0, 0, -1), Vec3(0.2, 0.1, 0), Vec3(0, 0, 1.3)};
    for (int k = 0; k < 3; ++k) {
        const Vec3 d(std::cos(2 * M_PI * k / 3), std::sin(2 * M_PI * k / 3), 0);
        const int q = m.num_vertices();
        for (int i = 0; i < 3; ++i) m.positions.push_back(m.positions[static_cast<size_t>(i)] + d);
        m.add_face({0, 1, q + 1});
        m.add_face({0, q + 1, q});
        m.add_face({1, 2, q + 2});
        m.add_face({1, q + 2, q + 1});
    }
    const PolyMesh r = loop_subdivide(m, kLoopEdge, 1);
    EXPECT_TRUE(r.positions[1].isApprox(0.75 * m.positions[1] + 0.125 * (m.positions[0] + m.positions[2])));
    EXPECT_FALSE(r.positions[1].isApprox(m.positions[1]));  // not a corner
    EXPECT_EQ(r.positions[0], m.positions[0]);              // p0 ends the seam: sharpened
}

/// Pairs of vertices of `m` at exactly the same place.
int coincident_pairs(const PolyMesh& m) {
    std::vector<std::array<double, 3>> p;
    for (const Vec3& x : m.positions) p.push_back({x.x(), x.y(), x.z()});
    std::sort(p.begin(), p.end());
    int pairs = 0;
    for (size_t i = 1; i < p.size(); ++i) pairs += p[i] == p[i - 1];
    return pairs;
}

TEST(NonManifold, ADuplicateFaceSharesItsEdgesAndKeepsTheEdgesInsideItsCopiesApart) {
    PolyMesh dup = book3();
    dup.add_face({0, 2, 1});  // face 0 again, from another corner
    // Level 1: the copy joins face 0's three edges (same direction: non-manifold, sharp), so
    // there are still 7 edges; vertex 2 ends two non-manifold edges and is a corner.
    const PolyMesh l1 = loop_subdivide(dup, kLoopEdge, 1);
    ASSERT_EQ(l1.num_vertices(), 5 + 7);
    ASSERT_EQ(l1.num_faces(), 16);
    EXPECT_EQ(l1.positions[2], dup.positions[2]);
    EXPECT_EQ(coincident_pairs(l1), 0);
    // Level 2: 2 x 7 halves and 3 edges inside each of the 4 faces: 26 edges, 38 vertices.
    // The 3 edges inside the copy have the same ends as those inside face 0 but are other
    // edges (OpenSubdiv derives child edges per face): 3 pairs of coincident points, where
    // completing the level from its face-vertices would have made 35 vertices.
    const PolyMesh l2 = loop_subdivide(dup, kLoopEdge, 2);
    EXPECT_EQ(l2.num_vertices(), 12 + 26);
    EXPECT_EQ(coincident_pairs(l2), 3);
    // Catmull-Clark: the two copies' face points coincide at level 1 (16 = 5 + 4 + 7
    // vertices); level 2 has 16 + 12 face points + (2 x 7 + 12) edge points.
    const CatmullClarkOptions cc{CatmullClarkBoundary::EdgeOnly};
    EXPECT_EQ(coincident_pairs(catmull_clark_subdivide(dup, cc, 1)), 1);
    EXPECT_EQ(catmull_clark_subdivide(dup, cc, 2).num_vertices(), 16 + 12 + 26);
}

TEST(NonManifold, AFaceNamingAVertexTwiceHasADegenerateEdgeAndTwoInstancesOfAPair) {
    PolyMesh m = book3();
    m.add_face({0, 0, 2});
    // Edges as completeTopologyFromFaceVertices makes them: (0, 0) is a new, degenerate edge;
    // 0 -> 2 joins face 0's edge (the same direction: non-manifold); 2 -> 0 is a pair the
    // edge's last face already uses, so a second instance. 7 + 2 edges, all three sharp.
    const std::vector<std::array<int, 2>> edges = nonmanifold_edges(m);
    ASSERT_EQ(edges.size(), 9u);
    EXPECT_EQ(std::count(edges.begin(), edges.end(), std::array<int, 2>{0, 0}), 1);
    EXPECT_EQ(std::count(edges.begin(), edges.end(), std::array<int, 2>{2, 0}), 1);
    EXPECT_EQ(std::count(edges.begin(), edges.end(), std::array<int, 2>{0, 2}), 1);
    const PolyMesh r = loop_subdivide(m, kLoopEdge, 1);
    ASSERT_EQ(r.num_vertices(), 5 + 9);
    // Vertex 0 (a corner) stays, the degenerate edge's point is at it, and both instances
    // of {0, 2} have their point at the midpoint.
    const Vec3 mid = 0.5 * (m.positions[0] + m.positions[2]);
    EXPECT_EQ(std::count(r.positions.begin(), r.positions.end(), m.positions[0]), 2);
    EXPECT_EQ(std::count_if(r.positions.begin(), r.positions.end(), [&](const Vec3& p) { return p.isApprox(mid); }), 2);
    EXPECT_THROW(loop_subdivide(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly, CreaseMethod::Uniform,
                                    NonManifoldRule::Refuse}, 1),
                 NonManifoldInput);
}

TEST(NonManifold, TheChildOfASharpenedVertexStaysSharpWhereItsFacesLookManifold) {
    // A triangle naming vertex 1 twice: vertex 2 ends the two instances of the pair {1, 2}
    // (non-manifold edges) and is sharpened, a corner. Its child at level 1 lies in one quad
    // with two boundary edges, a plain corner, which the edge-only rule would move by the
    // boundary mask (3/4 of it, 1/8 of each neighbour); it inherits the infinite sharpness
    // instead (Far's vertex sharpness), so it stays at every level. Shrunk from a Sweet Home
    // 3D model, where the vertex ends beside an unused one.
    PolyMesh m;
    m.positions = {Vec3(9, 9, 9), Vec3(0, 0, 0), Vec3(4, 0, 1)};
    m.add_face({1, 2, 1});
    const CatmullClarkOptions cc{CatmullClarkBoundary::EdgeOnly};
    for (int levels = 1; levels <= 3; ++levels) {
        const PolyMesh r = catmull_clark_subdivide(m, cc, levels);
        EXPECT_EQ(r.positions[2], m.positions[2]) << levels;
        EXPECT_EQ(r.positions[0], m.positions[0]) << levels;  // the unused vertex stays too
    }
    // Level 1 alone shows nothing: there the vertex is still the parent's corner.
    const PolyMesh l1 = catmull_clark_subdivide(m, cc, 1);
    // Read again as a base level (its faces only), the child is a plain corner and moves:
    // what a refinement that recomputes the tags per level did.
    PolyMesh faces_only = l1;
    faces_only.derived = {};
    const PolyMesh from_l1 = catmull_clark_subdivide(faces_only, cc, 1);
    EXPECT_EQ(from_l1.positions[2], 0.75 * l1.positions[2] + 0.125 * (l1.positions[4] + l1.positions[5]));
}

TEST(NonManifold, TheHalvesOfANonManifoldEdgeStaySharpWhereTwoFacesShareThemTheManifoldWay) {
    // Triangle 0 names the pair {0, 1} twice; triangle 1 joins the first instance the other
    // way. That instance is non-manifold (forced: its face names it twice) though two faces
    // traverse it oppositely, and so are its halves at level 1, where they look manifold:
    // they stay sharp: their level-2 points are their midpoints (the pair's ends are corners,
    // its point the crease's midpoint), as in Far.
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(4, 0, 0.8), Vec3(2, 4, 0), Vec3(1.2, -4, 1.6)};
    m.add_face({0, 1, 0});
    m.add_face({1, 0, 3});
    const PolyMesh r = loop_subdivide(m, kLoopEdge, 2);
    // At 3/4 of the pair from vertex 0: the point of the half at vertex 1 of each instance
    // (the second instance's halves are boundary edges); nothing else lands there. A smooth
    // half would take 1/8 of each opposite vertex, one of them off the pair's line.
    const Vec3 three_quarters = 0.25 * m.positions[0] + 0.75 * m.positions[1];
    EXPECT_EQ(std::count_if(r.positions.begin(), r.positions.end(),
                            [&](const Vec3& p) { return (p - three_quarters).norm() < 1e-15; }),
              2);
}

TEST(NonManifold, SharpnessTagsOnANonManifoldMeshAreRefused) {
    PolyMesh tagged = book3();
    tagged.creases.edges.push_back({0, 2, 2.0f});
    EXPECT_THROW(loop_subdivide(tagged, kLoopEdge, 1), InputError);
}

}  // namespace
}  // namespace crossdiv
