// Bilinear subdivision on tiny meshes whose refined points and faces are written out by hand:
// every point is the average of the corners it lies between.
#include <gtest/gtest.h>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/bilinear.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "test_points.h"

namespace crossdiv {
namespace {

using test::expect_near;  // within 1e-15: sums of two to four halves or quarters of small integers
using test::face_corners;

TEST(Bilinear, AQuadBecomesFourQuadsAroundItsCentre) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 2)};
    m.add_face({0, 1, 2, 3});
    const PolyMesh r = bilinear_subdivide(m, 1);
    ASSERT_EQ(r.num_vertices(), 9);  // 4 old, 1 face point, 4 edge points
    ASSERT_EQ(r.num_faces(), 4);
    for (int v = 0; v < 4; ++v) expect_near(r.positions[v], m.positions[v]);
    expect_near(r.positions[4], Vec3(1, 1, 0.5));  // (0+2+2+0, 0+0+2+2, 0+0+0+2) / 4
    expect_near(r.positions[5], Vec3(1, 0, 0));    // edge 0-1
    expect_near(r.positions[6], Vec3(2, 1, 0));    // edge 1-2
    expect_near(r.positions[7], Vec3(1, 2, 1));    // edge 2-3
    expect_near(r.positions[8], Vec3(0, 1, 1));    // edge 3-0
    // Quad k = (v_k, E(v_k v_k+1), F, E(v_k-1 v_k)).
    EXPECT_EQ(face_corners(r, 0), (std::vector<int>{0, 5, 4, 8}));
    EXPECT_EQ(face_corners(r, 1), (std::vector<int>{1, 6, 4, 5}));
    EXPECT_EQ(face_corners(r, 2), (std::vector<int>{2, 7, 4, 6}));
    EXPECT_EQ(face_corners(r, 3), (std::vector<int>{3, 8, 4, 7}));
}

TEST(Bilinear, ATriangleBecomesThreeQuadsAndTwoLevelsStayOnItsPlane) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(0, 3, 0)};
    m.add_face({0, 1, 2});
    const PolyMesh r = bilinear_subdivide(m, 1);
    ASSERT_EQ(r.num_vertices(), 7);
    ASSERT_EQ(r.num_faces(), 3);
    expect_near(r.positions[3], Vec3(1, 1, 0));
    expect_near(r.positions[4], Vec3(1.5, 0, 0));
    expect_near(r.positions[5], Vec3(1.5, 1.5, 0));
    expect_near(r.positions[6], Vec3(0, 1.5, 0));
    const PolyMesh r2 = bilinear_subdivide(m, 2);
    EXPECT_EQ(r2.num_faces(), 12);
    EXPECT_EQ(r2.num_vertices(), 7 + 3 + 9);  // 3 face points, 9 edges (6 halves of old sides, 3 inner)
    for (const Vec3& p : r2.positions) EXPECT_EQ(p.z(), 0.0);
}

TEST(Bilinear, AnEdgeSharedByThreeFacesIsOneEdgePoint) {
    // Three triangles on the side (0, 1): not a manifold, and no rule is needed for it.
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, -1, 0), Vec3(1, 0, 2)};
    m.add_face({0, 1, 2});
    m.add_face({1, 0, 3});
    m.add_face({0, 1, 4});
    const PolyMesh r = bilinear_subdivide(m, 1);
    EXPECT_EQ(r.num_vertices(), 5 + 3 + 7);  // sides: (0,1) once, and six others
    EXPECT_EQ(r.num_faces(), 9);
    expect_near(r.positions[8], Vec3(1, 0, 0));  // the first edge: (0, 1), the midpoint
    for (int f = 0; f < 3; ++f) EXPECT_EQ(r.face(3 * f)[1], 8) << "the quad at corner 0 of face " << f << " holds the shared edge point";
}

TEST(Bilinear, HasCatmullClarksTopologyAndRefusesWhatItCannotRefine) {
    PolyMesh cube;
    cube.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                      Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
    for (const auto& q : std::vector<std::vector<int>>{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}})
        cube.add_face({q[0], q[1], q[2], q[3]});
    const PolyMesh b = bilinear_subdivide(cube, 2), c = catmull_clark_subdivide(cube, {CatmullClarkBoundary::EdgeOnly}, 2);
    EXPECT_EQ(b.face_vertices, c.face_vertices);  // the same numbering of vertices, edges and faces
    for (const Vec3& p : b.positions) EXPECT_TRUE(p.minCoeff() == 0.0 || p.maxCoeff() == 1.0) << "on the cube's surface";
    PolyMesh tagged = cube;
    tagged.creases.vertices.push_back({0, 2.0});
    EXPECT_THROW(bilinear_subdivide(tagged, 1), InputError);
    EXPECT_THROW(bilinear_subdivide(cube, -1), InputError);
}

}  // namespace
}  // namespace crossdiv
