// The OpenMesh adapter on meshes whose Loop refinement is known by hand.
#include <gtest/gtest.h>

#include <string>

#include "crossdiv/adapters/openmesh.h"
#include "crossdiv/datasets/bundled.h"

namespace crossdiv::adapters {
namespace {

TEST(OpenMeshLoop, OctahedronByHand) {
    // Valence 4, the ring sums to zero: v' = (1 - 4 * 31/256) v = 33/64 v.
    const TriMesh m = to_tri_mesh(datasets::bundled_mesh("octahedron"));
    const LevelTrace t = openmesh::loop(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[0].positions, m.positions);
    EXPECT_EQ(t[2].num_faces(), 8 * 16);
    for (int v = 0; v < 6; ++v) EXPECT_NEAR((t[1].positions[v] - 33.0 / 64.0 * m.positions[v]).norm(), 0.0, 1e-15);
}

TEST(OpenMeshLoop, BoundaryVertexIsOneSixOne) {
    TriMesh tri;
    tri.positions = {Vec3(0, 0, 0), Vec3(8, 0, 0), Vec3(0, 8, 0)};
    tri.triangles = {{0, 1, 2}};
    const LevelTrace t = openmesh::loop(tri, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    EXPECT_EQ(t[1].positions[0], Vec3(1, 1, 0));
}

TEST(OpenMeshLoop, HighValenceBeyondItsDefaultTable) {
    // LoopT's default weight table stops at valence 49; the adapter sizes it, so the poles of
    // valence 64 get Loop's weight. The ring is a circle around the pole: v' = (1 - n beta) v
    // + beta * sum(ring), and sum(ring) = 64 * (0, 0, z_ring).
    const TriMesh m = to_tri_mesh(datasets::bundled_mesh("pole-64"));
    const LevelTrace t = openmesh::loop(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    const double beta = loop_beta(LoopWeights::Loop, 64), z_ring = m.positions[1].z();
    EXPECT_NEAR(t[1].positions[0].z(), (1 - 64 * beta) * 1.0 + beta * 64 * z_ring, 1e-14);
}

TEST(OpenMeshLoop, RejectsWhatItLacksAndBadFaces) {
    const TriMesh m = to_tri_mesh(datasets::bundled_mesh("tetrahedron"));
    EXPECT_THROW(openmesh::loop(m, {LoopWeights::Warren, LoopBoundary::EdgeOnly}, 1), Rejected);
    EXPECT_THROW(openmesh::loop(m, {LoopWeights::Loop, LoopBoundary::EdgeAndCorner}, 1), Rejected);
    TriMesh bad;
    bad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
    bad.triangles = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};  // edge (0, 1) in three faces
    EXPECT_THROW(openmesh::loop(bad, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1), Rejected);
}

TEST(OpenMeshCatmullClark, AQuadNamingAVertexTwiceIsAnInvalidResultNamingTheFace) {
    // add_face accepts the quad (1, 0, 0, 9) beside a 2x2 grid and stores a face whose vertex
    // circulator never returns to its start. Reading it stops after as many corners as the
    // mesh has halfedges, at once, instead of filling memory until std::bad_alloc.
    PolyMesh m;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) m.positions.emplace_back(i, j, 0.0);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) m.add_face({3 * j + i, 3 * j + i + 1, 3 * j + i + 4, 3 * j + i + 3});
    m.positions.emplace_back(0.0, -1.0, 0.0);
    m.add_face({1, 0, 0, 9});
    try {
        openmesh::catmull_clark(m, 1);
        ADD_FAILURE() << "OpenMesh's face that never closes was read as a mesh";
    } catch (const InvalidResult& e) {
        EXPECT_NE(std::string(e.what()).find("OpenMesh's face 4 of the input as add_face stored it"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace crossdiv::adapters
