// Mesh statistics on meshes whose counts are known by construction.
#include <gtest/gtest.h>

#include "crossdiv/error.h"
#include "crossdiv/mesh/mesh_statistics.h"

namespace crossdiv {
namespace {

PolyMesh polygons_of(int vertices, std::vector<std::vector<int>> faces) {
    PolyMesh m;
    for (int v = 0; v < vertices; ++v) m.positions.emplace_back(v, v * v, 0.5 * v);
    for (const auto& f : faces) m.add_face(f);
    return m;
}

PolyMesh tetrahedron() { return polygons_of(4, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}); }

TEST(MeshStatistics, ATetrahedronIsOneClosedSphere) {
    const MeshStatistics s = mesh_statistics(tetrahedron());
    EXPECT_EQ(s.vertices, 4);
    EXPECT_EQ(s.edges, 6);
    EXPECT_EQ(s.faces, 4);
    EXPECT_EQ(s.triangles, 4);
    EXPECT_EQ(s.euler_characteristic, 2);
    EXPECT_EQ(s.components, 1);
    EXPECT_EQ(s.boundary_edges, 0);
    EXPECT_EQ(s.boundary_loops, 0);
    EXPECT_EQ(s.genus, 0);
    EXPECT_EQ(s.non_manifold_edges + s.non_manifold_vertices + s.inconsistent_edges + s.isolated_vertices, 0);
}

TEST(MeshStatistics, AQuadTorusHasGenusOne) {
    // A 4 x 4 grid of quads with both directions wrapped: V 16, E 32, F 16, chi 0, genus 1.
    std::vector<std::vector<int>> faces;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            faces.push_back({4 * i + j, 4 * ((i + 1) % 4) + j, 4 * ((i + 1) % 4) + (j + 1) % 4, 4 * i + (j + 1) % 4});
    const MeshStatistics s = mesh_statistics(polygons_of(16, faces));
    EXPECT_EQ(s.edges, 32);
    EXPECT_EQ(s.quads, 16);
    EXPECT_EQ(s.euler_characteristic, 0);
    EXPECT_EQ(s.genus, 1);
    EXPECT_EQ(s.components, 1);
}

TEST(MeshStatistics, OpenPiecesCountTheirBoundaryLoopsAndComponents) {
    // Two triangles forming a square (one loop of 4 edges), a pentagon apart (a loop of 5), an
    // isolated vertex 9: V 10, 9 used, E 5 + 5, F 3, chi 9 - 10 + 3 = 2; each piece a disc.
    const MeshStatistics s = mesh_statistics(polygons_of(10, {{0, 1, 2}, {0, 2, 3}, {4, 5, 6, 7, 8}}));
    EXPECT_EQ(s.components, 2);
    EXPECT_EQ(s.boundary_edges, 9);
    EXPECT_EQ(s.boundary_loops, 2);
    EXPECT_EQ(s.isolated_vertices, 1);
    EXPECT_EQ(s.larger_faces, 1);
    EXPECT_EQ(s.euler_characteristic, 2);
    EXPECT_EQ(s.genus, 0);
}

TEST(MeshStatistics, NonManifoldAndBrokenElementsAreCountedAndLeaveNoGenus) {
    // A bowtie: two triangles sharing vertex 0 only.
    MeshStatistics s = mesh_statistics(polygons_of(5, {{0, 1, 2}, {0, 3, 4}}));
    EXPECT_EQ(s.non_manifold_vertices, 1);
    EXPECT_EQ(s.components, 1);
    EXPECT_EQ(s.genus, -1);
    // Three triangles on edge 0-1.
    s = mesh_statistics(polygons_of(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}));
    EXPECT_EQ(s.non_manifold_edges, 1);
    EXPECT_EQ(s.genus, -1);
    // Two triangles running their shared edge the same way, and a face naming a vertex twice.
    s = mesh_statistics(polygons_of(5, {{0, 1, 2}, {0, 1, 3}, {2, 4, 2}}));
    EXPECT_EQ(s.inconsistent_edges, 1);
    EXPECT_EQ(s.degenerate_faces, 1);
    EXPECT_EQ(s.triangles, 3);
    EXPECT_EQ(s.non_manifold_vertices, 0);  // faces around 0 and 1 still meet across the edge
    EXPECT_EQ(s.genus, -1);
    EXPECT_THROW(mesh_statistics(polygons_of(3, {{0, 1, 7}})), InputError);
}

}  // namespace
}  // namespace crossdiv
