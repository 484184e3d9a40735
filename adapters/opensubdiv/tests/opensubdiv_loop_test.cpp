// The OpenSubdiv adapter on meshes whose Loop refinement is known by hand.
#include <gtest/gtest.h>

#include "crossdiv/adapters/opensubdiv.h"
#include "crossdiv/datasets/bundled.h"

namespace crossdiv::adapters {
namespace {

TEST(OpenSubdivLoop, TetrahedronByHand) {
    // Valence 3, beta = 3/16: v' = v/4; edge point (a + b)/4 (the other two sum to -(a + b)).
    const TriMesh m = to_tri_mesh(datasets::bundled_mesh("tetrahedron"));
    const LevelTrace t = opensubdiv::loop(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].positions, m.positions);
    ASSERT_EQ(t[1].num_vertices(), 10);
    ASSERT_EQ(t[1].num_faces(), 16);
    for (int v = 0; v < 4; ++v) EXPECT_NEAR((t[1].positions[v] - m.positions[v] / 4.0).norm(), 0.0, 1e-15);
    // Edge vertices follow at nv + edge index; each is (a + b)/4 for some pair of corners.
    for (int i = 4; i < 10; ++i) {
        bool found = false;
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b)
                found |= (t[1].positions[i] - (m.positions[a] + m.positions[b]) / 4.0).norm() < 1e-15;
        EXPECT_TRUE(found) << "edge vertex " << i;
    }
}

TEST(OpenSubdivLoop, CornerRuleKeepsOneFaceCorners) {
    TriMesh tri;
    tri.positions = {Vec3(0, 0, 0), Vec3(8, 0, 0), Vec3(0, 8, 0)};
    tri.triangles = {{0, 1, 2}};
    const LevelTrace corner = opensubdiv::loop(tri, {LoopWeights::Loop, LoopBoundary::EdgeAndCorner}, 1);
    const LevelTrace edge = opensubdiv::loop(tri, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    for (int v = 0; v < 3; ++v) EXPECT_EQ(corner[1].positions[v], tri.positions[v]);
    EXPECT_EQ(edge[1].positions[0], Vec3(1, 1, 0));  // 3/4 (0,0,0) + 1/8 (8,0,0) + 1/8 (0,8,0)
}

TEST(OpenSubdivLoop, RejectsWarrenWeights) {
    const TriMesh m = to_tri_mesh(datasets::bundled_mesh("tetrahedron"));
    EXPECT_FALSE(opensubdiv::supports({LoopWeights::Warren, LoopBoundary::EdgeOnly}));
    EXPECT_THROW(opensubdiv::loop(m, {LoopWeights::Warren, LoopBoundary::EdgeOnly}, 1), Rejected);
}

TEST(OpenSubdivLoop, ReportsItsVersion) { EXPECT_EQ(opensubdiv::version(), "OpenSubdiv 3.5.0"); }

}  // namespace
}  // namespace crossdiv::adapters
