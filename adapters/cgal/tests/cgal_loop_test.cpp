// The CGAL adapter on meshes whose Loop refinement is known by hand.
#include <gtest/gtest.h>

#include <cmath>

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

// Jet fitting on the paraboloid z = (0.5 x^2 + 0.2 y^2) / 2 sampled on a symmetric 5 x 5 grid:
// the degree-2 jet is the surface itself and, by the grid's symmetry, the fitting frame is the
// axes, so CGAL's Monge form at the centre is k = 0.5 along x and 0.2 along y, bending towards
// +z. Against the orientation +z our convention negates them: k1 = -0.2 along y, k2 = -0.5.
TEST(CgalMonge, ParaboloidByHand) {
    TriMesh m;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            const double x = 0.1 * (i - 2), y = 0.1 * (j - 2);
            m.positions.emplace_back(x, y, (0.5 * x * x + 0.2 * y * y) / 2);
        }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const int a = 5 * i + j, b = a + 5;
            m.triangles.push_back({a, b, b + 1});
            m.triangles.push_back({a, b + 1, a + 1});
        }
    const std::vector<Vec3> up(m.positions.size(), Vec3::UnitZ());
    const cgal::MongeCurvatures c = cgal::monge_curvatures(m, up, 2, 2);
    ASSERT_TRUE(c.fitted[12]);
    EXPECT_NEAR(c.k1[12], -0.2, 1e-12);
    EXPECT_NEAR(c.k2[12], -0.5, 1e-12);
    EXPECT_NEAR(std::abs(c.direction1[12].y()), 1.0, 1e-12);
    EXPECT_NEAR(c.normal[12].z(), 1.0, 1e-12);
    EXPECT_THROW(cgal::monge_curvatures(m, up, 2, 5), Rejected);
}

}  // namespace
}  // namespace crossdiv::adapters
