// The seed's connectivity tables on tiny meshes, and the errors for meshes they cannot describe.
#include <gtest/gtest.h>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_connectivity.h"

namespace crossdiv {
namespace {

TriMesh mesh_of(int nv, std::vector<Triangle> tris) {
    TriMesh m;
    for (int v = 0; v < nv; ++v) m.positions.push_back(Vec3(v, v * v, 1.0));
    m.triangles = std::move(tris);
    return m;
}

std::string error_of(const TriMesh& m) {
    try {
        build_tri_connectivity(m);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(TriConnectivity, TwoTrianglesSharingAnEdge) {
    // Triangle 0 = (0,1,2): its edge 1 runs 1->2; triangle 1 = (2,1,3): its edge 0 runs 2->1.
    const TriConnectivity c = build_tri_connectivity(mesh_of(4, {{0, 1, 2}, {2, 1, 3}}));
    EXPECT_EQ(c.neighbor_tris[0], (std::array<int, 3>{-1, 1, -1}));
    EXPECT_EQ(c.neighbor_edges[0], (std::array<int, 3>{-1, 0, -1}));
    EXPECT_EQ(c.neighbor_tris[1], (std::array<int, 3>{0, -1, -1}));
    EXPECT_EQ(c.neighbor_edges[1], (std::array<int, 3>{1, -1, -1}));
    // Edges numbered at their first corner in scan order: 0->1, 1->2, 2->0, 1->3, 3->2.
    ASSERT_EQ(c.num_edges(), 5);
    EXPECT_EQ(c.tri_edges[0], (std::array<int, 3>{0, 1, 2}));
    EXPECT_EQ(c.tri_edges[1], (std::array<int, 3>{1, 3, 4}));
    EXPECT_EQ(c.edge_vertices[1], (std::array<int, 2>{1, 2}));
    EXPECT_FALSE(c.is_boundary_edge(1));
    EXPECT_TRUE(c.is_boundary_edge(3));
    for (int v = 0; v < 4; ++v) EXPECT_TRUE(c.is_boundary_vertex(v));
}

TEST(TriConnectivity, BoundaryWalkStartsAtIncomingBoundaryEdge) {
    // Open fan around vertex 0: (0,1,2), (0,2,3), (0,3,4).
    const TriMesh m = mesh_of(5, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
    const TriConnectivity c = build_tri_connectivity(m);
    // Around 0 the triangle whose incoming edge (at 0) is on the boundary is (0,3,4): 4->0.
    EXPECT_EQ(c.vertex_corner[0], 3 * 2 + 0);
    int visited = 0;
    for (int k = c.vertex_corner[0]; k >= 0; k = c.next_around_vertex(k)) ++visited;
    EXPECT_EQ(visited, 3);
}

TEST(TriConnectivity, ClosedMeshHasNoBoundary) {
    const TriConnectivity c = build_tri_connectivity(mesh_of(4, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}));
    EXPECT_EQ(c.num_edges(), 6);
    for (int v = 0; v < 4; ++v) EXPECT_FALSE(c.is_boundary_vertex(v));
    for (int e = 0; e < 6; ++e) EXPECT_FALSE(c.is_boundary_edge(e));
}

TEST(TriConnectivity, IsolatedVertexHasNoCorner) {
    const TriConnectivity c = build_tri_connectivity(mesh_of(4, {{0, 1, 2}}));
    EXPECT_EQ(c.vertex_corner[3], -1);
    EXPECT_FALSE(c.is_boundary_vertex(3));
}

TEST(TriConnectivity, ErrorsNameTheElement) {
    EXPECT_NE(error_of(mesh_of(3, {{0, 1, 5}})).find("face 0: vertex index 5 out of range"), std::string::npos);
    EXPECT_NE(error_of(mesh_of(3, {{0, 1, 1}})).find("repeated vertex"), std::string::npos);
    EXPECT_NE(error_of(mesh_of(5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}})).find("shared by 3 triangles"),
              std::string::npos);
    EXPECT_NE(error_of(mesh_of(4, {{0, 1, 2}, {0, 1, 3}})).find("inconsistent orientation"), std::string::npos);
    // Two triangles touching only at vertex 0.
    EXPECT_NE(error_of(mesh_of(5, {{0, 1, 2}, {0, 3, 4}})).find("vertex 0 is non-manifold"), std::string::npos);
}

/// A closed fan of n triangles (0, 1+k, 1+(k+1)%n) around vertex 0, capped by a second fan
/// around vertex n+1: a bicone whose two poles have valence n.
std::vector<Triangle> bicone(int n) {
    std::vector<Triangle> t;
    for (int k = 0; k < n; ++k) t.push_back({0, 1 + k, 1 + (k + 1) % n});
    for (int k = 0; k < n; ++k) t.push_back({n + 1, 1 + (k + 1) % n, 1 + k});
    return t;
}

TEST(TriConnectivity, APoleOfHighValenceGetsTheTablesOfAFan) {
    // Valence 100. By hand:
    // triangle k's edge 0 (0 -> 1+k) is edge 2 of triangle k-1, its edge 1 (the rim) is edge
    // 1 of cap triangle n+k, its edge 2 (1+k+1 -> 0) is edge 0 of triangle k+1.
    const int n = 100;
    const TriConnectivity c = build_tri_connectivity(mesh_of(n + 2, bicone(n)));
    ASSERT_EQ(c.num_edges(), 3 * n);
    for (int k = 0; k < n; ++k) {
        EXPECT_EQ(c.neighbor_tris[k], (std::array<int, 3>{(k + n - 1) % n, n + k, (k + 1) % n})) << k;
        EXPECT_EQ(c.neighbor_edges[k], (std::array<int, 3>{2, 1, 0})) << k;
    }
    int visited = 0;
    for (int k = c.vertex_corner[0];; k = c.next_around_vertex(k)) {
        ++visited;
        if (c.next_around_vertex(k) == c.vertex_corner[0]) break;
    }
    EXPECT_EQ(visited, n);
}

TEST(TriConnectivity, ErrorsAtAPoleOfHighValenceNameTheElement) {
    const int n = 100;
    std::vector<Triangle> third = bicone(n);
    third.push_back({0, 2, 1});  // a third triangle on each edge of (0, 1, 2)
    EXPECT_NE(error_of(mesh_of(n + 2, third)).find("shared by 3 triangles"), std::string::npos);
    std::vector<Triangle> flipped = bicone(n);
    flipped[5] = {0, 7, 6};  // traverses 0 -> 7 as triangle 6 does
    EXPECT_NE(error_of(mesh_of(n + 2, flipped)).find("inconsistent orientation"), std::string::npos);
    std::vector<Triangle> bowtie = bicone(n);
    for (int k = 0; k < n; ++k) bowtie.push_back({0, n + 2 + k, n + 2 + (k + 1) % n});  // a second fan at 0
    EXPECT_NE(error_of(mesh_of(2 * n + 2, bowtie)).find("vertex 0 is non-manifold"), std::string::npos);
}

}  // namespace
}  // namespace crossdiv
