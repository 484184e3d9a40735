// VTK's triangle subdivision filters through the adapter: what each filter makes of a
// four-triangle pyramid, by hand. Every expected value is exact in single precision, the
// precision VTK stores its points in.
#include <gtest/gtest.h>

#include "crossdiv/adapters/vtk.h"

namespace crossdiv::adapters::vtk {
namespace {

/// A four-triangle pyramid: apex 0 at (0,0,1) over the corners 1..4 at (1,0,0), (0,1,0),
/// (-1,0,0), (0,-1,0). The apex is interior (valence 4), the corners are on the boundary.
TriMesh pyramid() {
    TriMesh m;
    m.positions = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    for (int k = 0; k < 4; ++k) m.triangles.push_back({0, 1 + k, 1 + (k + 1) % 4});
    return m;
}

/// Whether `mesh` has a vertex at `p` exactly.
bool has_point(const PolyMesh& mesh, const Vec3& p) {
    for (const Vec3& q : mesh.positions)
        if (q == p) return true;
    return false;
}

/// One level of any filter: the input's points first, in order, then one per edge (8), and
/// four triangles per triangle.
void expect_one_level_counts(const LevelTrace& t) {
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].num_vertices(), 5);
    EXPECT_EQ(t[1].num_vertices(), 13);
    EXPECT_EQ(t[1].num_faces(), 16);
    for (int f = 0; f < t[1].num_faces(); ++f) EXPECT_EQ(t[1].face_size(f), 3);
}

// Loop's weights: the apex (valence 4, beta = (5/8 - (3/8 + cos(pi/2)/4)^2)/4 = 31/256) goes to
// (1 - 4 beta) (0,0,1) = (0,0,132/256); a corner (boundary) to 3/4 of itself plus 1/8 of each
// boundary neighbour: (3/4, 0, 0); the edge apex-corner 1 to 3/8 (its ends) + 1/8 (its two
// opposite corners, which cancel): (3/8, 0, 3/8); a boundary edge to its midpoint.
TEST(VtkSubdivision, LoopMovesTheVerticesByLoopsWeights) {
    const LevelTrace t = subdivide(pyramid(), Filter::Loop, 1);
    expect_one_level_counts(t);
    EXPECT_EQ(t[1].positions[0], Vec3(0, 0, 0.515625));
    EXPECT_EQ(t[1].positions[1], Vec3(0.75, 0, 0));
    EXPECT_EQ(t[1].positions[3], Vec3(-0.75, 0, 0));
    EXPECT_TRUE(has_point(t[1], Vec3(0.375, 0, 0.375)));
    EXPECT_TRUE(has_point(t[1], Vec3(0.5, 0.5, 0)));
}

// Interpolating: the old points stay. A boundary edge takes the four-point rule,
// -1/16 p0 + 9/16 p1 + 9/16 p2 - 1/16 p3 along the boundary: for the edge (1,0,0)-(0,1,0),
// -1/16 (0,-1,0) + 9/16 (1,0,0) + 9/16 (0,1,0) - 1/16 (-1,0,0) = (5/8, 5/8, 0).
TEST(VtkSubdivision, ButterflyKeepsTheOldPointsAndTakesTheFourPointRuleOnTheBoundary) {
    const LevelTrace t = subdivide(pyramid(), Filter::Butterfly, 1);
    expect_one_level_counts(t);
    for (int v = 0; v < 5; ++v) EXPECT_EQ(t[1].positions[v], pyramid().positions[v]);
    EXPECT_TRUE(has_point(t[1], Vec3(0.625, 0.625, 0)));
    EXPECT_TRUE(has_point(t[1], Vec3(-0.625, -0.625, 0)));
}

// Its boundary choices (core's other-face-wings): the spoke apex -> (1,0,0) joins two vertices
// of other than 6 faces, so it is half the apex's K-point stencil, (1/2, 0, 3/4), and half the
// eight-point stencil the corner stands for (its walk meets the boundary), with the wings
// beyond the boundary the other triangle's apex: (5/8, 0, 1/2). Together (9/16, 0, 5/8),
// where OpenMesh's choices give (1/2, 0, 3/4).
TEST(VtkSubdivision, ButterflyAveragesTheApexStencilWithTheEightPointOneOfABoundaryEnd) {
    const LevelTrace t = subdivide(pyramid(), Filter::Butterfly, 1);
    EXPECT_TRUE(has_point(t[1], Vec3(0.5625, 0, 0.625)));
    EXPECT_TRUE(has_point(t[1], Vec3(0, 0.5625, 0.625)));
    EXPECT_FALSE(has_point(t[1], Vec3(0.5, 0, 0.75)));
}

// Every new point the midpoint of its edge.
TEST(VtkSubdivision, LinearSplitsAtTheEdgeMidpoints) {
    const LevelTrace t = subdivide(pyramid(), Filter::Linear, 1);
    expect_one_level_counts(t);
    for (const Vec3& p : {Vec3(0.5, 0, 0.5), Vec3(0, 0.5, 0.5), Vec3(-0.5, 0, 0.5), Vec3(0, -0.5, 0.5), Vec3(0.5, 0.5, 0),
                          Vec3(-0.5, 0.5, 0), Vec3(-0.5, -0.5, 0), Vec3(0.5, -0.5, 0)})
        EXPECT_TRUE(has_point(t[1], p)) << p.transpose();
    EXPECT_EQ(subdivide_native(pyramid(), Filter::Linear, 2), 64u);
}

// VTK refuses a non-manifold edge in its own words, which the adapter passes on.
TEST(VtkSubdivision, ANonManifoldEdgeIsRefusedInVtksWords) {
    TriMesh three = pyramid();
    three.positions.push_back({0, 0, -1});
    three.triangles.push_back({0, 1, 5});  // the edge 0-1 now has three faces
    try {
        subdivide(three, Filter::Loop, 1);
        FAIL() << "VTK refined a non-manifold edge";
    } catch (const Rejected& e) {
        EXPECT_NE(std::string(e.what()).find("non-manifold"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace crossdiv::adapters::vtk
