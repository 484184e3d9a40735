// Holes and the other shape-file rules of OpenSubdiv in core: hole faces refined around and
// not emitted, the faces VTX_BOUNDARY_NONE makes holes, and Catmull-Clark's smooth-triangle
// edge weights -- each on a mesh small enough to count and compute by hand.
#include <gtest/gtest.h>

#include <vector>

#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "crossdiv/subdiv/loop.h"

namespace crossdiv {
namespace {

/// An n x n grid of unit quads in z = 0; face j*n + i has lower-left corner (i, j).
PolyMesh quad_grid(int n) {
    PolyMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.positions.emplace_back(i, j, 0.1 * ((3 * i + 5 * j) % 4));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            m.add_face({a, a + 1, a + n + 2, a + n + 1});
        }
    return m;
}

/// The grid with each quad split along its diagonal from the lower-left corner.
PolyMesh triangle_grid(int n) {
    const PolyMesh q = quad_grid(n);
    PolyMesh m;
    m.positions = q.positions;
    for (int f = 0; f < q.num_faces(); ++f) {
        const int* v = q.face(f);
        m.add_face({v[0], v[1], v[2]});
        m.add_face({v[0], v[2], v[3]});
    }
    return m;
}

TEST(Holes, AHoleIsRefinedAroundAndItsChildrenAreHoles) {
    PolyMesh grid = quad_grid(3);
    grid.creases.holes = {4};  // the centre quad
    const CatmullClarkOptions o{CatmullClarkBoundary::EdgeOnly};
    const PolyMesh one = catmull_clark_subdivide(grid, o, 1);
    // One quad per corner in corner order: face 4's children are corners 16..19.
    EXPECT_EQ(one.creases.holes, (std::vector<int>{16, 17, 18, 19}));
    const PolyMesh two = catmull_clark_subdivide(grid, o, 2);
    ASSERT_EQ(two.creases.holes.size(), 16u);
    EXPECT_EQ(two.creases.holes.front(), 64);
    EXPECT_EQ(two.creases.holes.back(), 79);
    // Positions are those of the mesh without the tag, bit for bit: a hole changes what is
    // emitted, not what is computed.
    PolyMesh untagged = grid;
    untagged.creases.holes.clear();
    EXPECT_EQ(two.positions, catmull_clark_subdivide(untagged, o, 2).positions);
    // Emitted: every face but the 16, every vertex kept (the hole's inner vertices unused).
    const PolyMesh emitted = without_hole_faces(two);
    EXPECT_EQ(emitted.num_faces(), 9 * 16 - 16);
    EXPECT_EQ(emitted.num_vertices(), two.num_vertices());
    EXPECT_TRUE(emitted.creases.holes.empty());

    PolyMesh tris = triangle_grid(2);
    tris.creases.holes = {1, 6};
    const PolyMesh loop = loop_subdivide(tris, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2);
    std::vector<int> expected;  // 4 per triangle per level: faces 16..31 and 96..111
    for (int f : {1, 6})
        for (int k = 0; k < 16; ++k) expected.push_back(16 * f + k);
    EXPECT_EQ(loop.creases.holes, expected);
}

TEST(Holes, BoundaryNoneMakesTheFacesAtSmoothBoundaryVerticesHoles) {
    // 4 x 4 grid: the 12 faces of the outer ring touch a boundary vertex; the inner 4 do not.
    PolyMesh grid = quad_grid(4);
    tag_boundary_faces_as_holes(grid, build_poly_connectivity(grid));
    EXPECT_EQ(grid.creases.holes, (std::vector<int>{0, 1, 2, 3, 4, 7, 8, 11, 12, 13, 14, 15}));

    // A boundary whose every edge is tagged infinitely sharp keeps its faces (Far tests the
    // sharpness the tags gave before it sharpens the boundary): here the bottom row's edges,
    // so only the bottom-left and bottom-right corners keep a smooth boundary edge.
    PolyMesh sharp = quad_grid(4);
    for (int i = 0; i < 4; ++i) sharp.creases.edges.push_back({i, i + 1, 10.0f});
    tag_boundary_faces_as_holes(sharp, build_poly_connectivity(sharp));
    // Vertices 1, 2, 3 (bottom, inner) have only sharp boundary edges: faces 1 and 2 are left
    // unless a vertex of theirs on another side is smooth -- none is.
    EXPECT_EQ(sharp.creases.holes, (std::vector<int>{0, 3, 4, 7, 8, 11, 12, 13, 14, 15}));
}

TEST(SmoothTriangles, EdgePointBetweenTwoTrianglesWeighsTheirCentroids) {
    // The unit square split along 0-2: triangles (0,1,2) and (0,2,3). The diagonal's edge
    // point under TRI_SUB_SMOOTH is 0.03 (p0 + p2) + 0.47 (c0 + c1) with the centroids
    // c0 = (2/3, 1/3), c1 = (1/3, 2/3): x = 0.03 + 0.47 = 0.5, y = 0.5; and with a bump
    // z2 = 1: z = 0.03 + 0.47 (1/3 + 1/3) = 0.03 + 0.31333...
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1), Vec3(0, 1, 0)};
    m.add_face({0, 1, 2});
    m.add_face({0, 2, 3});
    CatmullClarkOptions o{CatmullClarkBoundary::EdgeOnly};
    o.smooth_triangles = true;
    const PolyMesh smooth = catmull_clark_subdivide(m, o, 1);
    const PolyMesh plain = catmull_clark_subdivide(m, {CatmullClarkBoundary::EdgeOnly}, 1);
    // Refined vertices: 4 old, 2 face points, then edges in order of first corner: 0-1, 1-2, 2-0.
    const int diagonal = 4 + 2 + 2;
    EXPECT_DOUBLE_EQ(smooth.positions[diagonal].x(), 0.5);
    EXPECT_DOUBLE_EQ(smooth.positions[diagonal].z(), 0.03 + 0.47 * (2.0 / 3.0));
    EXPECT_DOUBLE_EQ(plain.positions[diagonal].z(), 0.25 + 0.25 * (2.0 / 3.0));  // 1/4 each
    // Only edge points between faces change; boundary edges stay midpoints.
    EXPECT_EQ(smooth.positions[4 + 2], plain.positions[4 + 2]);

    // Between a triangle and a quad: the endpoints 0.14 each, the face points 0.36 each.
    const CatmullClarkEdgeWeights mixed = catmull_clark_edge_weights(true, true, false);
    EXPECT_DOUBLE_EQ(mixed.end, 0.14);
    EXPECT_DOUBLE_EQ(mixed.face, 0.36);
    const CatmullClarkEdgeWeights quads = catmull_clark_edge_weights(true, false, false);
    EXPECT_EQ(quads.end, 0.25);
    EXPECT_EQ(quads.face, 0.25);
}

}  // namespace
}  // namespace crossdiv
