// Midpoint subdivision of triangles on tiny meshes whose refined points and faces are written
// out by hand: every old vertex stays, every new one is the midpoint of its edge.
#include <gtest/gtest.h>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/midpoint.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "test_points.h"

namespace crossdiv {
namespace {

using test::expect_near;
using test::face_corners;  // within 1e-15: halves of small integers are exact anyway

TEST(Midpoint, ATriangleBecomesFourAtItsEdgeMidpoints) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 2, 6)};
    m.add_face({0, 1, 2});
    const PolyMesh r = midpoint_subdivide(m, 1);
    ASSERT_EQ(r.num_vertices(), 6);  // 3 old, 3 edge points
    ASSERT_EQ(r.num_faces(), 4);
    for (int v = 0; v < 3; ++v) EXPECT_EQ(r.positions[v], m.positions[v]);
    EXPECT_EQ(r.positions[3], Vec3(2, 0, 0));  // edge 0-1
    EXPECT_EQ(r.positions[4], Vec3(2, 1, 3));  // edge 1-2
    EXPECT_EQ(r.positions[5], Vec3(0, 1, 3));  // edge 2-0
    // (v_k, E(v_k v_k+1), E(v_k-1 v_k)) for k = 0, 1, 2, then the middle triangle.
    EXPECT_EQ(face_corners(r, 0), (std::vector<int>{0, 3, 5}));
    EXPECT_EQ(face_corners(r, 1), (std::vector<int>{1, 4, 3}));
    EXPECT_EQ(face_corners(r, 2), (std::vector<int>{2, 5, 4}));
    EXPECT_EQ(face_corners(r, 3), (std::vector<int>{3, 4, 5}));
}

TEST(Midpoint, TwoLevelsOfATetrahedronStayOnItsFacesAndCountAsLoopDoes) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(8, 0, 0), Vec3(0, 8, 0), Vec3(0, 0, 8)};
    for (const auto& t : std::vector<std::array<int, 3>>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}) m.add_face({t[0], t[1], t[2]});
    const PolyMesh r = midpoint_subdivide(m, 2);
    // V - E + F = 2 at every level: 4 + 6 = 10 vertices and 16 faces, then 10 + 24 = 34 and 64.
    EXPECT_EQ(r.num_vertices(), 34);
    EXPECT_EQ(r.num_faces(), 64);
    for (int f = 0; f < r.num_faces(); ++f) {
        // Every child lies in its ancestor's plane: x = 0, y = 0, z = 0 or x + y + z = 8.
        const Vec3 a = r.positions[r.face(f)[0]], b = r.positions[r.face(f)[1]], c = r.positions[r.face(f)[2]];
        const bool on_a_face = (a.x() == 0 && b.x() == 0 && c.x() == 0) || (a.y() == 0 && b.y() == 0 && c.y() == 0) ||
                               (a.z() == 0 && b.z() == 0 && c.z() == 0) || (a.sum() == 8 && b.sum() == 8 && c.sum() == 8);
        EXPECT_TRUE(on_a_face) << "face " << f;
    }
    // The same faces as Loop's under OpenSubdiv's numbering, vertex for vertex: the scheme
    // differs from Loop in its masks only.
    EXPECT_EQ(r.face_vertices, loop_subdivide_nonmanifold(m, LoopOptions{}, 2).face_vertices);
}

TEST(Midpoint, AnEdgeSharedByThreeFacesIsOneEdgePoint) {
    // Three triangles on the side (0, 1): not a manifold, and no rule is needed for it.
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, -1, 0), Vec3(1, 0, 2)};
    m.add_face({0, 1, 2});
    m.add_face({1, 0, 3});
    m.add_face({0, 1, 4});
    const PolyMesh r = midpoint_subdivide(m, 1);
    EXPECT_EQ(r.num_vertices(), 5 + 7);  // sides: (0,1) once, and six others
    EXPECT_EQ(r.num_faces(), 12);
    EXPECT_EQ(r.positions[5], Vec3(1, 0, 0));  // the first edge: (0, 1), the midpoint
    EXPECT_EQ(r.face(0)[1], 5);
    EXPECT_EQ(r.face(4)[1], 5) << "face 1's first child (1, E(1,0), E(3,1)) reads the shared point";
    EXPECT_EQ(r.face(8)[1], 5);
    EXPECT_EQ(midpoint_subdivide(m, 2).num_faces(), 48) << "the refined level's edges stated per corner refine again";
}

TEST(Midpoint, RefusesWhatItCannotRefine) {
    PolyMesh quad;
    quad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    quad.add_face({0, 1, 2, 3});
    EXPECT_THROW(midpoint_subdivide(quad, 1), InputError);
    EXPECT_THROW(midpoint_subdivide(quad, 0), InputError) << "level 0 checks as a refinement does";
    PolyMesh tri;
    tri.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    tri.add_face({0, 1, 2});
    EXPECT_THROW(midpoint_subdivide(tri, -1), InputError);
    PolyMesh tagged = tri;
    tagged.creases.vertices.push_back({0, 2.0});
    EXPECT_THROW(midpoint_subdivide(tagged, 1), InputError);
}

}  // namespace
}  // namespace crossdiv
