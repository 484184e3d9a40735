// The half-edge mesh, its validity checker, flip and split on meshes small enough to draw,
// vertex normals with hand-computed weights, and Loop by split and flip against the
// index-based driver.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "crossdiv/error.h"
#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/mesh/halfedge_validity.h"
#include "crossdiv/mesh/vertex_normals.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_split_flip.h"

namespace crossdiv {
namespace {

// The unit square (0,0) (1,0) (1,1) (0,1) as two triangles along the diagonal 0-2. Edges in
// TriConnectivity's order: 0-1, 1-2, 2-0 (e2, the diagonal, runs 2->0 in face 0), 2-3, 3-0.
TriMesh two_triangle_square() {
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

TriMesh tetrahedron() {
    TriMesh m;
    m.positions = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    return m;
}

// A closed surface of two triangles on the same three vertices (a "pillow").
TriMesh pillow() {
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    m.triangles = {{0, 1, 2}, {1, 0, 2}};
    return m;
}

// n x n quads, each split along one diagonal: boundary, interior valence 6.
TriMesh grid(int n) {
    TriMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.positions.emplace_back(i, j, 0.1 * ((i * 7 + j * 3) % 5));
    auto id = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

std::string issues_text(const HalfedgeMesh& m) {
    std::string s;
    for (const HalfedgeIssue& i : check_halfedge_mesh(m)) s += std::string(to_string(i.kind)) + ": " + i.message + "\n";
    return s;
}

// Faces as a sorted list of triangles, each rotated to start at its smallest vertex.
std::vector<Triangle> canonical(std::vector<Triangle> faces) {
    for (Triangle& t : faces) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    std::sort(faces.begin(), faces.end());
    return faces;
}

TEST(HalfedgeMesh, SquareHasOneBoundaryLoopOfFour) {
    const HalfedgeMesh m = HalfedgeMesh::from_triangles(two_triangle_square());
    EXPECT_EQ(issues_text(m), "");
    EXPECT_EQ(m.num_edges(), 5);
    EXPECT_EQ(m.num_halfedges(), 10);
    ASSERT_EQ(m.num_boundary_loops(), 1);
    int len = 0;
    HalfedgeId h = m.loop_halfedge(0);
    do {
        EXPECT_TRUE(m.is_boundary(h));
        ++len;
        h = m.next(h);
    } while (h != m.loop_halfedge(0));
    EXPECT_EQ(len, 4);
    // Edge 2 is the diagonal, half-edge 4 runs 2->0 inside face 0.
    EXPECT_EQ(m.origin(HalfedgeId(4)), VertexId(2));
    EXPECT_EQ(m.target(HalfedgeId(4)), VertexId(0));
    EXPECT_EQ(m.face(HalfedgeId(4)), FaceId(0));
    EXPECT_EQ(m.face(HalfedgeId(5)), FaceId(1));
    EXPECT_EQ(m.valence(VertexId(0)), 3);
    EXPECT_EQ(m.valence(VertexId(1)), 2);
    EXPECT_TRUE(m.is_boundary(VertexId(1)));
    EXPECT_EQ(m.triangles(), two_triangle_square().triangles);  // built and converted back without reordering
}

TEST(HalfedgeMesh, FlipReplacesTheDiagonal) {
    HalfedgeMesh m = HalfedgeMesh::from_triangles(two_triangle_square());
    ASSERT_EQ(m.flip(EdgeId(2)), FlipRefusal::None);
    EXPECT_EQ(issues_text(m), "");
    // Before: f0 = (a, b, c) = (2, 0, 1) along 2->0, f1 = (b, a, d) = (0, 2, 3).
    // After: f0 = (d, c, a) = (3, 1, 2), f1 = (c, d, b) = (1, 3, 0).
    EXPECT_EQ(m.triangles(), (std::vector<Triangle>{{3, 1, 2}, {1, 3, 0}}));
    EXPECT_EQ(m.num_edges(), 5);
    EXPECT_EQ(m.valence(VertexId(0)), 2);
    EXPECT_EQ(m.valence(VertexId(1)), 3);
    // Flipping back restores the original faces (rotated to the new half-edges).
    ASSERT_EQ(m.flip(EdgeId(2)), FlipRefusal::None);
    EXPECT_EQ(canonical(m.triangles()), canonical(two_triangle_square().triangles));
}

TEST(HalfedgeMesh, FlipRefusalsLeaveTheMeshUnchanged) {
    HalfedgeMesh sq = HalfedgeMesh::from_triangles(two_triangle_square());
    EXPECT_EQ(sq.flip(EdgeId(0)), FlipRefusal::BoundaryEdge);
    EXPECT_EQ(sq.triangles(), two_triangle_square().triangles);

    // Every vertex of a tetrahedron has valence 3: the other diagonal is already an edge.
    HalfedgeMesh tet = HalfedgeMesh::from_triangles(tetrahedron());
    for (int e = 0; e < 6; ++e) EXPECT_EQ(tet.flip(EdgeId(e)), FlipRefusal::EdgeExists) << "edge " << e;
    EXPECT_EQ(tet.triangles(), tetrahedron().triangles);

    HalfedgeMesh p = HalfedgeMesh::from_triangles(pillow());
    EXPECT_EQ(issues_text(p), "");
    EXPECT_EQ(p.flip(EdgeId(0)), FlipRefusal::OppositeVerticesCoincide);
    EXPECT_EQ(p.triangles(), pillow().triangles);
}

TEST(HalfedgeMesh, SplitInteriorEdgeMakesFourFaces) {
    HalfedgeMesh m = HalfedgeMesh::from_triangles(two_triangle_square());
    std::vector<Vec3> p = two_triangle_square().positions;
    const VertexId v = split_at_midpoint(m, p, EdgeId(2));
    EXPECT_EQ(issues_text(m), "");
    EXPECT_EQ(v, VertexId(4));
    EXPECT_EQ(p[4], Vec3(0.5, 0.5, 0));
    // a = 2, b = 0, c = 1, d = 3, m = 4: f0 = (a, m, c), f1 = (m, a, d), f2 = (m, b, c), f3 = (b, m, d).
    EXPECT_EQ(m.triangles(), (std::vector<Triangle>{{2, 4, 1}, {4, 2, 3}, {4, 0, 1}, {0, 4, 3}}));
    EXPECT_EQ(m.num_edges(), 8);  // one for the second half, one per face
    EXPECT_EQ(m.valence(v), 4);
    EXPECT_EQ(HalfedgeMesh::edge(m.find_halfedge(VertexId(2), v)), EdgeId(2));  // e keeps the half at origin(2e)
    EXPECT_EQ(HalfedgeMesh::edge(m.find_halfedge(v, VertexId(0))), EdgeId(5));
    EXPECT_EQ(HalfedgeMesh::edge(m.find_halfedge(v, VertexId(1))), EdgeId(6));
    EXPECT_EQ(HalfedgeMesh::edge(m.find_halfedge(v, VertexId(3))), EdgeId(7));
}

TEST(HalfedgeMesh, SplitBoundaryEdgeMakesTwoFacesAndLengthensTheLoop) {
    HalfedgeMesh m = HalfedgeMesh::from_triangles(two_triangle_square());
    std::vector<Vec3> p = two_triangle_square().positions;
    const VertexId v = split_at_midpoint(m, p, EdgeId(0));  // 0-1, on the boundary
    EXPECT_EQ(issues_text(m), "");
    EXPECT_EQ(p[v.idx], Vec3(0.5, 0, 0));
    EXPECT_EQ(m.triangles(), (std::vector<Triangle>{{0, 4, 2}, {0, 2, 3}, {4, 1, 2}}));
    EXPECT_EQ(m.num_edges(), 7);
    EXPECT_TRUE(m.is_boundary(v));
    EXPECT_EQ(m.valence(v), 3);
    int len = 0;
    HalfedgeId h = m.loop_halfedge(0);
    do ++len, h = m.next(h);
    while (h != m.loop_halfedge(0));
    EXPECT_EQ(len, 5);
}

TEST(HalfedgeValidity, NamesTheVertexWhoseHalfedgeDoesNotLeaveIt) {
    HalfedgeMesh m = HalfedgeMesh::from_triangles(two_triangle_square());
    m.set_vertex_halfedge(VertexId(3), HalfedgeId(0));  // half-edge 0 leaves vertex 0
    const auto issues = check_halfedge_mesh(m);
    ASSERT_EQ(issues.size(), 1u) << issues_text(m);
    EXPECT_EQ(issues[0].kind, HalfedgeIssueKind::VertexLink);
    EXPECT_EQ(issues[0].message.rfind("vertex 3: its halfedge 0 leaves vertex 0, should leave 3", 0), 0u) << issues[0].message;

    m.set_vertex_halfedge(VertexId(3), HalfedgeId(99));
    ASSERT_FALSE(check_halfedge_mesh(m).empty());
    EXPECT_EQ(check_halfedge_mesh(m)[0].kind, HalfedgeIssueKind::OutOfRange);
}

// Random flips and splits keep every invariant and the Euler characteristic (both operations
// preserve V - E + F: a flip changes nothing, a split adds 1 - 3 + 2 or 1 - 2 + 1).
TEST(HalfedgeMesh, RandomFlipsAndSplitsKeepEveryInvariant) {
    for (const TriMesh& base : {tetrahedron(), grid(3)}) {
        HalfedgeMesh m = HalfedgeMesh::from_triangles(base);
        std::vector<Vec3> p = base.positions;
        const int chi = m.num_vertices() - m.num_edges() + m.num_faces();
        std::mt19937_64 rng(7);
        int flips = 0;
        for (int op = 0; op < 600; ++op) {
            const EdgeId e(static_cast<int>(rng() % static_cast<uint64_t>(m.num_edges())));
            if (rng() % 3) flips += m.flip(e) == FlipRefusal::None;
            else split_at_midpoint(m, p, e);
            ASSERT_EQ(issues_text(m), "") << "after operation " << op;
            ASSERT_EQ(m.num_vertices() - m.num_edges() + m.num_faces(), chi);
        }
        EXPECT_GT(flips, 100);  // the test exercised flips, not only refusals
    }
}

TEST(VertexNormals, WeightingsOnTwoPerpendicularFaces) {
    // Vertex 0 has a face in the xy-plane (area 1/2, angle 90 degrees, normal +z) and one in
    // the yz-plane (area 1, angle 135 degrees, normal -x).
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -2, -2)};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    const auto area = vertex_normals(m, NormalWeighting::Area);
    const auto angle = vertex_normals(m, NormalWeighting::Angle);
    const auto uniform = vertex_normals(m, NormalWeighting::Uniform);
    constexpr double kTol = 4 * 2.220446049250313e-16;  // a few roundings of a unit vector
    // Area: (0, 0, 1) + (-2, 0, 0) = (-2, 0, 1), over sqrt 5.
    EXPECT_LT((area[0] - Vec3(-2, 0, 1) / std::sqrt(5.0)).norm(), kTol);
    // Angle: pi/2 (0, 0, 1) + 3 pi/4 (-1, 0, 0), proportional to (-3, 0, 2), over sqrt 13.
    EXPECT_LT((angle[0] - Vec3(-3, 0, 2) / std::sqrt(13.0)).norm(), kTol);
    // Uniform: (-1, 0, 1) over sqrt 2.
    EXPECT_LT((uniform[0] - Vec3(-1, 0, 1) / std::sqrt(2.0)).norm(), kTol);
    // Vertex 1 has one face: every weighting gives that face's normal exactly.
    for (const auto* n : {&area, &angle, &uniform}) EXPECT_EQ((*n)[1], Vec3(0, 0, 1));
}

TEST(VertexNormals, IsolatedVertexAndOutOfRangeIndex) {
    TriMesh m = two_triangle_square();
    m.positions.emplace_back(5, 5, 5);
    EXPECT_EQ(vertex_normals(m, NormalWeighting::Area)[4], Vec3::Zero());
    m.triangles.push_back({0, 1, 9});
    EXPECT_THROW(vertex_normals(m, NormalWeighting::Angle), InputError);
    EXPECT_EQ(parse_normal_weighting("angle"), NormalWeighting::Angle);
    EXPECT_FALSE(parse_normal_weighting("cotan").has_value());
}

// Loop by split and flip is the index-based Loop, bit for bit, with the same vertex numbers.
TEST(LoopSplitFlip, EqualsIndexBasedLoopBitForBit) {
    TriMesh colored = grid(3);
    for (const Vec3& p : colored.positions) colored.colors.push_back(0.1 * p);
    for (const TriMesh& base : {tetrahedron(), two_triangle_square(), grid(3), colored})
        for (LoopWeights w : kAllLoopWeights)
            for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
                const LoopOptions opt{w, b};
                const TriMesh index = loop_subdivide(base, opt, 1);
                const TriMesh local = loop_by_split_and_flip(base, opt);
                EXPECT_EQ(local.positions, index.positions);
                EXPECT_EQ(local.colors, index.colors);
                EXPECT_EQ(canonical(local.triangles), canonical(index.triangles));
                EXPECT_EQ(issues_text(HalfedgeMesh::from_triangles(local)), "");
            }
}

// The pillow's refinement has two edges between the same pair of new vertices (index-based
// Loop makes them); a flip never duplicates an edge, so the method stops and says why.
TEST(LoopSplitFlip, RefusesADoubledTriangleNamingTheEdge) {
    const TriMesh index = loop_subdivide(pillow(), {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    EXPECT_EQ(index.num_faces(), 8);
    try {
        loop_by_split_and_flip(pillow(), {LoopWeights::Loop, LoopBoundary::EdgeOnly});
        ADD_FAILURE() << "expected a refusal";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("the flipped edge already exists"), std::string::npos) << e.what();
    }
}

TEST(LoopSplitFlip, RefusesWhatLoopRefuses) {
    TriMesh m = two_triangle_square();
    m.positions[2].x() = std::nan("");
    EXPECT_THROW(loop_by_split_and_flip(m, {LoopWeights::Loop, LoopBoundary::EdgeOnly}), InputError);
}

}  // namespace
}  // namespace crossdiv
