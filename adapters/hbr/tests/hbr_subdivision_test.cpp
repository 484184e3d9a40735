// OpenSubdiv's Hbr through the adapter: what each scheme makes of tiny meshes, by hand, and
// what Hbr cannot hold, refused by name.
//
// Hbr computes its weights in float (1/n^2, beta from a float cosine), so a value whose weights
// are not exact in float is held to kFloatWeights: 2^-20 of the unit-sized inputs, a few ulps of
// float (2^-24) on each of the few weights summed.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "crossdiv/adapters/hbr.h"

namespace crossdiv::adapters::hbr {
namespace {

constexpr double kFloatWeights = 0x1p-20;

/// The Catmull-Clark and Loop options Hbr has: its own crease rules.
CatmullClarkOptions catmark(CatmullClarkBoundary boundary) {
    CatmullClarkOptions o{boundary};
    o.crease_rules = CreaseRules::Hbr;
    return o;
}
LoopOptions loop_options(LoopWeights weights = LoopWeights::Loop, LoopBoundary boundary = LoopBoundary::EdgeOnly) {
    LoopOptions o{weights, boundary};
    o.crease_rules = CreaseRules::Hbr;
    return o;
}

/// The unit square as one quad, counter-clockwise from (0,0).
PolyMesh square() {
    PolyMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.add_face({0, 1, 2, 3});
    return m;
}

/// A four-triangle pyramid: apex 0 at (0,0,1) over the corners 1..4 at (1,0,0), (0,1,0),
/// (-1,0,0), (0,-1,0). The apex is interior (valence 4), the corners are on the boundary.
PolyMesh pyramid() {
    PolyMesh m;
    m.positions = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    for (int k = 0; k < 4; ++k) m.add_face({0, 1 + k, 1 + (k + 1) % 4});
    return m;
}

/// The vertex of `level` born from vertex `v` of the level before.
int child_of_vertex(const LevelBirths& births, int level, int v) {
    const std::vector<VertexBirth>& born = births[static_cast<size_t>(level - 1)];
    for (size_t i = 0; i < born.size(); ++i)
        if (born[i].kind == VertexBirth::Kind::Vertex && born[i].a == v) return static_cast<int>(i);
    return -1;
}

bool has_point(const PolyMesh& mesh, const Vec3& p) {
    for (const Vec3& q : mesh.positions)
        if ((q - p).norm() <= kFloatWeights) return true;
    return false;
}

// One quad, every edge a boundary: the face point is the centre, edge points the midpoints.
// Edge-only: a corner (two boundary edges) takes the crease rule, 3/4 of itself and 1/8 of
// each neighbour, (1/8, 1/8) for (0,0). Edge-and-corner keeps it. 4 faces, 9 vertices.
TEST(HbrSubdivision, CatmullClarkOnOneQuadTakesTheBoundaryRuleItIsGiven) {
    LevelBirths births;
    const LevelTrace edge_only = catmull_clark(square(), catmark(CatmullClarkBoundary::EdgeOnly), 1, &births);
    ASSERT_EQ(edge_only.size(), 2u);
    EXPECT_EQ(edge_only[1].num_faces(), 4);
    EXPECT_EQ(edge_only[1].num_vertices(), 9);
    ASSERT_EQ(births.size(), 1u);
    EXPECT_EQ(edge_only[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 0))], Vec3(0.125, 0.125, 0));
    EXPECT_EQ(edge_only[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 2))], Vec3(0.875, 0.875, 0));
    EXPECT_TRUE(has_point(edge_only[1], Vec3(0.5, 0.5, 0)));
    EXPECT_TRUE(has_point(edge_only[1], Vec3(0.5, 0, 0)));

    births.clear();
    const LevelTrace corners = catmull_clark(square(), catmark(CatmullClarkBoundary::EdgeAndCorner), 1, &births);
    EXPECT_EQ(corners[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 0))], Vec3(0, 0, 0));
    EXPECT_EQ(corners[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 2))], Vec3(1, 1, 0));
}

// Every child face of a quad is a quad; each face of level 1 has the parent's face point.
TEST(HbrSubdivision, EveryChildOfAQuadSharesItsFacePoint) {
    LevelBirths births;
    const LevelTrace t = catmull_clark(square(), catmark(CatmullClarkBoundary::EdgeOnly), 2, &births);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[2].num_faces(), 16);
    EXPECT_EQ(t[2].num_vertices(), 25);
    int face_point = -1;
    for (size_t i = 0; i < births[0].size(); ++i)
        if (births[0][i].kind == VertexBirth::Kind::Face) face_point = static_cast<int>(i);
    ASSERT_GE(face_point, 0);
    for (int f = 0; f < t[1].num_faces(); ++f) {
        ASSERT_EQ(t[1].face_size(f), 4);
        const int* c = t[1].face(f);
        EXPECT_TRUE(c[0] == face_point || c[1] == face_point || c[2] == face_point || c[3] == face_point) << "face " << f;
    }
}

// Loop's weights: the apex (valence 4, beta = (5/8 - (3/8 + cos(pi/2)/4)^2)/4 = 31/256) goes to
// (1 - 4 beta) (0,0,1) = (0,0,132/256) (Hbr's float cosine of pi/2 is -4.4e-8, not 0); a
// corner (boundary) to 3/4 of itself plus 1/8 of each boundary neighbour, (3/4, 0, 0); the
// edge apex-corner 1 to 3/8 of its ends plus 1/8 of its two opposite corners, (3/8, 0, 3/8).
TEST(HbrSubdivision, LoopMovesTheVerticesByLoopsWeights) {
    LevelBirths births;
    const LevelTrace t = loop(pyramid(), loop_options(), 1, &births);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[1].num_vertices(), 13);
    EXPECT_EQ(t[1].num_faces(), 16);
    const Vec3 apex = t[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 0))];
    EXPECT_NEAR((apex - Vec3(0, 0, 0.515625)).norm(), 0.0, kFloatWeights);
    EXPECT_EQ(t[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 1))], Vec3(0.75, 0, 0));
    EXPECT_TRUE(has_point(t[1], Vec3(0.375, 0, 0.375)));
    EXPECT_TRUE(has_point(t[1], Vec3(0.5, 0.5, 0)));
}

// An infinitely sharp crease (sharpness 10) across a strip of two quads whose shared edge
// rises to z = 1 at its far end: tagged, the edge point of the shared edge is its midpoint;
// smooth, it is the average of its ends and the two face points.
TEST(HbrSubdivision, AnInfinitelySharpCreaseKeepsItsEdgeStraight) {
    PolyMesh strip;
    strip.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 1}, {2, 1, 0}};
    strip.add_face({0, 1, 4, 3});
    strip.add_face({1, 2, 5, 4});
    const LevelTrace smooth = catmull_clark(strip, catmark(CatmullClarkBoundary::EdgeOnly), 1);
    strip.creases.edges.push_back({1, 4, 10.0f});
    const LevelTrace sharp = catmull_clark(strip, catmark(CatmullClarkBoundary::EdgeOnly), 1);
    // Smooth: the edge point of 1-4 averages its ends and the two face points,
    // ((1,0,0) + (1,1,1) + (0.5,0.5,0.25) + (1.5,0.5,0.25)) / 4 = (1, 0.5, 0.375).
    EXPECT_TRUE(has_point(smooth[1], Vec3(1, 0.5, 0.375)));
    EXPECT_FALSE(has_point(sharp[1], Vec3(1, 0.5, 0.375)));
    EXPECT_TRUE(has_point(sharp[1], Vec3(1, 0.5, 0.5)));
}

// A hole is refined around like any face, its children are holes too, as in Far.
TEST(HbrSubdivision, AHoleFacesChildrenAreHoles) {
    PolyMesh strip;
    strip.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    strip.add_face({0, 1, 4, 3});
    strip.add_face({1, 2, 5, 4});
    strip.creases.holes = {1};
    const LevelTrace t = catmull_clark(strip, catmark(CatmullClarkBoundary::EdgeOnly), 2);
    EXPECT_EQ(t[2].num_faces(), 32);
    EXPECT_EQ(t[2].creases.holes.size(), 16u);
}

// Bilinear: face points are centroids and nothing moves.
TEST(HbrSubdivision, BilinearKeepsTheCornersAndSplitsAtMidpoints) {
    LevelBirths births;
    const LevelTrace t = bilinear(square(), 1, &births);
    EXPECT_EQ(t[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 0))], Vec3(0, 0, 0));
    EXPECT_TRUE(has_point(t[1], Vec3(0.5, 0.5, 0)));
    EXPECT_TRUE(has_point(t[1], Vec3(1, 0.5, 0)));
}

// A 2x2 grid of quads whose centre (1,1,1/2) is a corner of sharpness c with its four edges
// at 1/2. Its smooth vertex point is 1/2 of itself plus 1/16 of its four neighbours and of the
// four face points: z = 1/4 + 0 + (4 x 1/8)/16 = 9/32; the corner keeps z = 1/2.
// c = 1 is still sharp in Hbr's next rule (sharpness >= 1): corner and corner, no blend, 1/2.
// (Far blends 3/5 corner, the average of 1 and the four 1/2: 0.4125.) c = 0.9 is smooth in
// both, and both weigh the corner by (0.9 + 4 x 0.5) / 5 = 0.58: 0.58/2 + 0.42 x 9/32 = 0.408125.
TEST(HbrSubdivision, AVertexOfSharpnessOneStaysACornerBesideSofterEdges) {
    const auto centre_z = [](float corner) {
        PolyMesh m;
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) m.positions.emplace_back(x, y, x == 1 && y == 1 ? 0.5 : 0.0);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) m.add_face({3 * y + x, 3 * y + x + 1, 3 * y + x + 4, 3 * y + x + 3});
        m.creases.vertices.push_back({4, corner});
        for (int b : {1, 3, 5, 7}) m.creases.edges.push_back({4, b, 0.5f});
        LevelBirths births;
        const LevelTrace t = catmull_clark(m, catmark(CatmullClarkBoundary::EdgeOnly), 1, &births);
        return t[1].positions[static_cast<size_t>(child_of_vertex(births, 1, 4))].z();
    };
    EXPECT_EQ(centre_z(1.0f), 0.5);
    EXPECT_NEAR(centre_z(0.9f), 0.408125, kFloatWeights);
    CatmullClarkOptions far{CatmullClarkBoundary::EdgeOnly};
    EXPECT_THROW(catmull_clark(square(), far, 1), Rejected);  // Far's crease rules: not Hbr's to give
}

// What Hbr cannot hold is refused by name, before Hbr sees it.
TEST(HbrSubdivision, RefusesAMeshItCannotHoldByTheFaceOrVertex) {
    PolyMesh fin;  // three triangles on the edge 0-1
    fin.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    fin.add_face({0, 1, 2});
    fin.add_face({1, 0, 3});
    fin.add_face({0, 1, 4});
    try {
        loop(fin, loop_options(), 1);
        FAIL() << "three faces on one edge were accepted";
    } catch (const Rejected& e) {
        EXPECT_NE(std::string(e.what()).find("edge 0-1"), std::string::npos) << e.what();
    }
    PolyMesh lonely = pyramid();
    lonely.positions.emplace_back(5, 5, 5);
    EXPECT_THROW(loop(lonely, loop_options(), 1), Rejected);
    EXPECT_THROW(loop(square(), loop_options(), 1), Rejected);
    EXPECT_THROW(loop(pyramid(), loop_options(LoopWeights::Warren), 1), Rejected);
    PolyMesh twice;
    twice.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    twice.add_face({0, 1, 0, 2});
    EXPECT_THROW(catmull_clark(twice, catmark(CatmullClarkBoundary::EdgeOnly), 1), Rejected);
}

// Two triangles back to back, beside an open pyramid: Hbr's Loop makes level 1 (4 triangles
// each), and would loop without end making level 2, so two levels are refused naming the pair.
// Catmull-Clark refines the pair: 3 quads per triangle, then 4 per quad.
TEST(HbrSubdivision, RefusesLoopsSecondLevelOfTwoTrianglesBackToBack) {
    PolyMesh mesh = pyramid();
    const int a = mesh.num_vertices();
    mesh.positions.insert(mesh.positions.end(), {{5, 0, 0}, {6, 0, 0}, {5, 1, 0}});
    mesh.add_face({a, a + 1, a + 2});
    mesh.add_face({a, a + 2, a + 1});
    const int pair = mesh.num_faces() - 2;
    EXPECT_EQ(loop(mesh, loop_options(), 1).back().num_faces(), 4 * mesh.num_faces());
    try {
        loop(mesh, loop_options(), 2);
        FAIL() << "two levels of two triangles back to back were run";
    } catch (const Rejected& e) {
        EXPECT_NE(std::string(e.what()).find("faces " + std::to_string(pair) + " and " + std::to_string(pair + 1)), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(catmull_clark(mesh, catmark(CatmullClarkBoundary::EdgeOnly), 2).back().num_faces(), 12 * mesh.num_faces());
}

// Two unit quads side by side, each with UV values of its own (a seam along their shared edge):
// face 0 maps to [0,1] x [0,1], face 1 to [2,3] x [0,1]. Under "all" (Hbr's "none" method:
// linear everywhere) every child corner's value is the bilinear one of its parent face: a
// vertex's own value there, an edge's midpoint, the face's centre, on both sides of the seam.
// The values are dyadic, so Hbr's float sums are exact.
TEST(HbrSubdivision, FaceVaryingValuesUnderAllAreLinearOnEachSideOfASeam) {
    PolyMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    m.add_face({0, 1, 4, 3});
    m.add_face({1, 2, 5, 4});
    FaceVaryingChannel uv;
    uv.values = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 3, 0, 3, 1, 2, 1};
    uv.corner_values = {0, 1, 2, 3, 4, 5, 6, 7};
    m.face_varying.push_back(uv);
    LevelBirths births;
    const LevelTrace t = catmull_clark_face_varying(m, catmark(CatmullClarkBoundary::EdgeOnly), FaceVaryingRule::All, 1, &births);
    ASSERT_EQ(t.size(), 2u);
    const PolyMesh& fine = t[1];
    ASSERT_EQ(fine.num_faces(), 8);
    ASSERT_EQ(fine.face_varying.size(), 1u);
    const FaceVaryingChannel& out = fine.face_varying[0];
    ASSERT_EQ(out.corner_values.size(), fine.face_vertices.size());
    // The value of parent face p at its corner on vertex v.
    const auto parent_value = [&](int p, int v) {
        for (int k = 0; k < 4; ++k)
            if (m.face(p)[k] == v) return std::array<double, 2>{uv.values[2 * (4 * p + k)], uv.values[2 * (4 * p + k) + 1]};
        ADD_FAILURE() << "vertex " << v << " is not a corner of face " << p;
        return std::array<double, 2>{NAN, NAN};
    };
    for (int f = 0; f < fine.num_faces(); ++f) {
        const int p = f / 4;  // Hbr's children of face p, in order
        for (int k = 0; k < 4; ++k) {
            const int corner = fine.face_start[static_cast<size_t>(f)] + k;
            const VertexBirth& b = births[0][static_cast<size_t>(fine.face(f)[k])];
            std::array<double, 2> want{0, 0};
            if (b.kind == VertexBirth::Kind::Vertex) {
                want = parent_value(p, b.a);
            } else if (b.kind == VertexBirth::Kind::Edge) {
                const std::array<double, 2> x = parent_value(p, b.a), y = parent_value(p, b.b);
                want = {(x[0] + y[0]) / 2, (x[1] + y[1]) / 2};
            } else {
                for (int j = 0; j < 4; ++j) {
                    const std::array<double, 2> x = parent_value(p, m.face(p)[j]);
                    want = {want[0] + x[0] / 4, want[1] + x[1] / 4};
                }
            }
            const double* got = out.value(out.corner_values[static_cast<size_t>(corner)]);
            EXPECT_EQ(got[0], want[0]) << "face " << f << " corner " << k;
            EXPECT_EQ(got[1], want[1]) << "face " << f << " corner " << k;
        }
    }
}

TEST(HbrSubdivision, FaceVaryingRefusesCornersOnlyAndAMeshWithoutAChannel) {
    PolyMesh m = square();
    EXPECT_THROW(catmull_clark_face_varying(m, catmark(CatmullClarkBoundary::EdgeOnly), FaceVaryingRule::None, 1), Rejected);
    FaceVaryingChannel uv;
    uv.values = {0, 0, 1, 0, 1, 1, 0, 1};
    uv.corner_values = {0, 1, 2, 3};
    m.face_varying.push_back(uv);
    try {
        catmull_clark_face_varying(m, catmark(CatmullClarkBoundary::EdgeOnly), FaceVaryingRule::CornersOnly, 1);
        ADD_FAILURE() << "corners-only was not refused";
    } catch (const Rejected& e) {
        EXPECT_NE(std::string(e.what()).find("no corners-only face-varying rule"), std::string::npos) << e.what();
    }
    // One face alone: every rule but all keeps its four corners' values (UV corners are sharp
    // under corners-plus1, corners-plus2 and boundaries; none smooths them as its positions).
    const LevelTrace t = catmull_clark_face_varying(m, catmark(CatmullClarkBoundary::EdgeOnly), FaceVaryingRule::Boundaries, 1);
    ASSERT_EQ(t.back().face_varying.size(), 1u);
    const FaceVaryingChannel& out = t.back().face_varying[0];
    int kept = 0;
    for (int v = 0; v < out.num_values(); ++v)
        for (int c = 0; c < 4; ++c) kept += out.value(v)[0] == uv.values[2 * c] && out.value(v)[1] == uv.values[2 * c + 1];
    EXPECT_EQ(kept, 4);
}

}  // namespace
}  // namespace crossdiv::adapters::hbr

namespace crossdiv::adapters::hbr {
namespace {

/// A 2 x 2 grid of unit quads, face j*2 + i with lower-left corner (i, j), in z = 0.
PolyMesh grid2() {
    PolyMesh m;
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 2; ++i) m.positions.emplace_back(i, j, 0);
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            const int a = 3 * j + i;
            m.add_face({a, a + 1, a + 4, a + 3});
        }
    return m;
}

TEST(HbrSubdivision, AppliesAHierarchicalVertexEditWhereItsPathLeads) {
    // Face 3 = (4 5 8 7), lower-left corner (1, 1). Its child 2 sits at corner 8, (2, 2); that
    // child's slot 3 (Hbr turns a quad's children to start at their corner) is the point of
    // edge (7, 8): (1.5, 2) on the boundary, lifted by 1 at level 1 and kept 3/4 of at level 2.
    PolyMesh m = grid2();
    m.creases.edits = {HierarchicalEdit{EditTarget::Position, EditOperation::Add, 3, {2}, 3, {0, 0, 1}, 0}};
    const LevelTrace t = catmull_clark(m, catmark(CatmullClarkBoundary::EdgeOnly), 2);
    int lifted1 = -1;
    for (int v = 0; v < t[1].num_vertices(); ++v)
        if (t[1].positions[v].z() != 0) {
            EXPECT_EQ(lifted1, -1) << "a second lifted vertex";
            lifted1 = v;
        }
    ASSERT_GE(lifted1, 0);
    EXPECT_EQ(t[1].positions[lifted1], Vec3(1.5, 2, 1));
    double top = 0;
    for (const Vec3& p : t[2].positions) top = std::max(top, p.z());
    EXPECT_NEAR(top, 0.75, kFloatWeights);
    // The same edit through Hbr's Loop: refused by name, never dropped.
    PolyMesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.add_face({0, 1, 2});
    tri.creases.edits = {HierarchicalEdit{EditTarget::Position, EditOperation::Add, 0, {0}, 0, {0, 0, 1}, 0}};
    EXPECT_THROW(loop(tri, loop_options(), 1), Rejected);
    // A path off the mesh is refused before Hbr walks it.
    m.creases.edits[0].children = {7};
    EXPECT_THROW(catmull_clark(m, catmark(CatmullClarkBoundary::EdgeOnly), 1), Rejected);
}

}  // namespace
}  // namespace crossdiv::adapters::hbr
