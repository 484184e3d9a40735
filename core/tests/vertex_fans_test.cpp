// One vertex per fan of faces: the bowtie's centre becomes two vertices, a manifold mesh stays.
#include <gtest/gtest.h>

#include "crossdiv/mesh/vertex_fans.h"

namespace crossdiv {
namespace {

// Two triangles touching at vertex 0 only: 0 is in two fans. The second fan's corner of 0
// becomes vertex 5, at 0's position; the first keeps 0.
TEST(VertexFans, TheBowtiesCentreBecomesOneVertexPerFan) {
    PolyMesh bowtie;
    bowtie.positions = {{0, 0, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
    bowtie.add_face({0, 1, 2});
    bowtie.add_face({0, 3, 4});
    std::vector<int> original;
    const PolyMesh split = split_vertex_fans(bowtie, &original);
    ASSERT_EQ(split.num_vertices(), 6);
    EXPECT_EQ(split.face_vertices, (std::vector<int>{0, 1, 2, 5, 3, 4}));
    EXPECT_EQ(split.positions[5], Vec3(0, 0, 0));
    EXPECT_EQ(original, (std::vector<int>{0, 1, 2, 3, 4, 0}));
}

// Four quads around a centre, closed by edges with two faces each: one fan everywhere.
// Open a gap (drop one quad) and the centre is still one fan: a boundary ends a fan, it
// does not make two.
TEST(VertexFans, AManifoldMeshIsUnchanged) {
    PolyMesh grid;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) grid.positions.emplace_back(x, y, 0);
    grid.add_face({0, 1, 4, 3});
    grid.add_face({1, 2, 5, 4});
    grid.add_face({3, 4, 7, 6});
    grid.add_face({4, 5, 8, 7});
    EXPECT_EQ(split_vertex_fans(grid).face_vertices, grid.face_vertices);
    PolyMesh open = grid;
    open.face_vertices.resize(12);
    open.face_start.resize(4);
    EXPECT_EQ(split_vertex_fans(open).num_vertices(), grid.num_vertices());
}

// Two quads of the grid that share only the centre (diagonal): two fans at the centre.
// Two faces running an edge the same way do not join their corners either.
TEST(VertexFans, OnlyAnEdgeWithTwoOppositeFacesJoinsTwoFaces) {
    PolyMesh diagonal;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) diagonal.positions.emplace_back(x, y, 0);
    diagonal.add_face({0, 1, 4, 3});
    diagonal.add_face({4, 5, 8, 7});
    EXPECT_EQ(split_vertex_fans(diagonal).num_vertices(), 10);
    PolyMesh flipped;
    flipped.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    flipped.add_face({0, 1, 2});
    flipped.add_face({0, 1, 3});  // runs 0 -> 1 like the first
    EXPECT_EQ(split_vertex_fans(flipped).num_vertices(), 6);
}

}  // namespace
}  // namespace crossdiv
