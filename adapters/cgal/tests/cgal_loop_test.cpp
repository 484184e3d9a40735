// The CGAL adapter on meshes whose Loop refinement is known by hand.
#include <gtest/gtest.h>

#include "crossdiv/adapters/cgal.h"
#include "crossdiv/datasets/bundled.h"

namespace crossdiv::adapters {
namespace {

TEST(CgalLoop, TetrahedronByHand) {
    const TriMesh m = to_tri_mesh(datasets::bundled_mesh("tetrahedron"));
    const LevelTrace t = cgal::loop(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].positions, m.positions);
    ASSERT_EQ(t[1].num_faces(), 16);
    for (int v = 0; v < 4; ++v) EXPECT_NEAR((t[1].positions[v] - m.positions[v] / 4.0).norm(), 0.0, 1e-15);
}

TEST(CgalLoop, BorderVertexIsOneSixOne) {
    TriMesh tri;
    tri.positions = {Vec3(0, 0, 0), Vec3(8, 0, 0), Vec3(0, 8, 0)};
    tri.triangles = {{0, 1, 2}};
    const LevelTrace t = cgal::loop(tri, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    EXPECT_EQ(t[1].positions[0], Vec3(1, 1, 0));
}

TEST(CgalLoop, RejectsWhatItLacksAndBadFaces) {
    const TriMesh m = to_tri_mesh(datasets::bundled_mesh("tetrahedron"));
    EXPECT_THROW(cgal::loop(m, {LoopWeights::Warren, LoopBoundary::EdgeOnly}, 1), Rejected);
    TriMesh bad;
    bad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    bad.triangles = {{0, 1, 2}, {0, 1, 3}};  // inconsistent orientation across edge (0, 1)
    EXPECT_THROW(cgal::loop(bad, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1), Rejected);
}

}  // namespace
}  // namespace crossdiv::adapters
