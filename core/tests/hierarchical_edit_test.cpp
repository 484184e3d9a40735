// Hierarchical edits: the shape-file tags read and written back, and core's Catmull-Clark
// applying them level by level -- on the 3 x 3 quad square of OpenSubdiv's hedit shapes, a
// flat regular grid where every refined position is known by hand.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/subdiv/bilinear.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "parse_errors.h"

namespace crossdiv {
namespace {

/// The square of OpenSubdiv's catmark_square_hedit shapes: 4 x 4 vertices from -1 to 1 in
/// z = 0, 9 quads, edge-and-corner boundary; `tags` appended.
std::string square(const std::string& tags) {
    std::string s;
    char line[96];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            std::snprintf(line, sizeof line, "v %.17g %.17g 0\n", -1 + 2.0 * i / 3, -1 + 2.0 * j / 3);  // every bit
            s += line;
        }
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            const int a = 4 * j + i + 1;
            s += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 5) + " " + std::to_string(a + 4) + "\n";
        }
    return s + "t interpolateboundary 1/0/0 1\n" + tags;
}

PolyMesh read_square(const std::string& text) {
    std::istringstream in(text);
    return read_obj(in, "square.obj");
}

std::string square_error(const std::string& text) {
    return test::parse_error([](std::istream& in, const std::string& n) { return read_obj(in, n); }, text, "square.obj");
}

CatmullClarkOptions edge_and_corner() {
    CatmullClarkOptions o;
    o.boundary = CatmullClarkBoundary::EdgeAndCorner;
    return o;
}

/// The vertex of `m` nearest (x, y) in the plane.
int nearest(const PolyMesh& m, double x, double y) {
    int best = -1;
    double d = 1e300;
    for (int v = 0; v < m.num_vertices(); ++v) {
        const double e = (m.positions[v].head<2>() - Eigen::Vector2d(x, y)).squaredNorm();
        if (e < d) d = e, best = v;
    }
    return best;
}

TEST(HierarchicalEdit, ReadsVertexEditsAsHbrsReaderDoes) {
    // catmark_square_hedit0's first tag: four paths of length 3 (face 0, child 1, vertex j),
    // three floats each, one operation.
    const PolyMesh m = read_square(square("t vertexedit 16/12/3 3 0 1 0 3 0 1 1 3 0 1 2 3 0 1 3 0 0 1 0 0 2 0 0 3 0 0 4 add P value\n"));
    ASSERT_EQ(m.creases.edits.size(), 4u);
    for (int j = 0; j < 4; ++j) {
        const HierarchicalEdit& e = m.creases.edits[static_cast<size_t>(j)];
        EXPECT_EQ(e.target, EditTarget::Position);
        EXPECT_EQ(e.op, EditOperation::Add);
        EXPECT_EQ(e.face, 0);
        EXPECT_EQ(e.children, std::vector<int>{1});
        EXPECT_EQ(e.element, j);
        EXPECT_EQ(e.level(), 1);
        EXPECT_EQ(e.value[2], j + 1.0);  // each path takes its own three floats
        EXPECT_EQ(e.line, 27);  // after 16 vertices, 9 faces and the boundary tag
    }
    EXPECT_FALSE(m.creases.empty());
    EXPECT_EQ(m.creases.describe(), "0 crease and 0 corner tag(s), and 4 hierarchical edit(s)");
}

TEST(HierarchicalEdit, TwoOperationsTakeTheirFloatsInTurnPerPath) {
    // hedit1-like, both operations on one line: per path 3 floats of the value, then 1 of the sharpness.
    const PolyMesh m = read_square(square("t vertexedit 8/8/6 3 4 1 0 3 4 1 1 0 0 1 10 0 0 2 7 add P value set P sharpness\n"));
    ASSERT_EQ(m.creases.edits.size(), 4u);
    // Operation by operation, path by path, as Hbr makes them.
    EXPECT_EQ(m.creases.edits[0].target, EditTarget::Position);
    EXPECT_EQ(m.creases.edits[1].value[2], 2.0);
    EXPECT_EQ(m.creases.edits[2].target, EditTarget::VertexSharpness);
    EXPECT_EQ(m.creases.edits[2].value[0], 10.0);
    EXPECT_EQ(m.creases.edits[3].value[0], 7.0);
    EXPECT_EQ(m.creases.edits[3].element, 1);
}

TEST(HierarchicalEdit, ReadsEdgeAndFaceEditsAndWritesEveryKindBack) {
    const PolyMesh m = read_square(square("t vertexedit 4/3/3 3 4 1 0 0.25 -0.5 1 subtract P value\n"
                                   "t edgeedit 4/1/3 3 4 1 2 10 set P sharpness\n"
                                   "t faceedit 4/0/1 3 4 1 1 hole\n"));
    ASSERT_EQ(m.creases.edits.size(), 3u);
    EXPECT_EQ(m.creases.edits[1].target, EditTarget::EdgeSharpness);
    EXPECT_EQ(m.creases.edits[1].element, 2);
    EXPECT_EQ(m.creases.edits[2].target, EditTarget::Hole);
    EXPECT_EQ(m.creases.edits[2].children, (std::vector<int>{1, 1}));
    EXPECT_EQ(m.creases.edits[2].element, -1);
    std::ostringstream out;
    write_obj(out, m);
    const PolyMesh back = read_square(out.str());
    ASSERT_EQ(back.creases.edits.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        HierarchicalEdit a = m.creases.edits[i], b = back.creases.edits[i];
        a.line = b.line = 0;
        EXPECT_EQ(a, b) << describe(a) << " came back as " << describe(b);
    }
}

TEST(HierarchicalEdit, ABadTagIsAnErrorNamingItsLine) {
    EXPECT_NE(square_error(square("t vertexedit 4/3/3 3 9 1 0 0 0 1 add P value\n")).find("square.obj:27: hierarchical edit: face 9 out of range"),
              std::string::npos);
    EXPECT_NE(square_error(square("t vertexedit 4/3/3 3 0 4 0 0 0 1 add P value\n")).find("square.obj:27: hierarchical edit: child 4 at level 1"),
              std::string::npos);
    EXPECT_NE(square_error(square("t vertexedit 4/3/3 3 0 1 5 0 0 1 add P value\n")).find("vertex 5 is not one of the face's 4 corners"),
              std::string::npos);
    EXPECT_NE(square_error(square("t vertexedit 3/3/3 3 0 1 0 0 1 add P value\n")).find("runs past the integers given"), std::string::npos);
    EXPECT_NE(square_error(square("t vertexedit 4/2/3 3 0 1 0 0 1 add P value\n")).find("2 float(s) for 1 path(s) of 3 value(s) each"),
              std::string::npos);
    // More floats than the paths take: the first ones are read, as Hbr reads them, and noted.
    const PolyMesh extra = read_square(square("t vertexedit 4/6/3 3 0 1 0 0 0 1 7 7 7 add P value\n"));
    ASSERT_EQ(extra.creases.edits.size(), 1u);
    EXPECT_EQ(extra.creases.edits[0].value, (std::array<double, 3>{0, 0, 1}));
    ASSERT_FALSE(extra.source.notes.empty());
    EXPECT_NE(extra.source.notes.back().find("gives 6 floats for 1 path(s) of 3 value(s); the first 3 are read"), std::string::npos);
    EXPECT_NE(square_error(square("t vertexedit 4/3/3 3 0 1 0 0 0 1 multiply P value\n")).find("'multiply' is not set, add or subtract"),
              std::string::npos);
    EXPECT_NE(square_error(square("t vertexedit 4/3/3 3 0 1 0 0 0 1 add N value\n")).find("variable 'N' is not supported"),
              std::string::npos);
    EXPECT_NE(square_error(square("t edgeedit 4/3/3 3 0 1 0 0 0 1 add P value\n")).find("'value' is not sharpness"), std::string::npos);
    EXPECT_NE(square_error(square("t faceedit 3/0/1 2 0 1 attributes\n")).find("'attributes' is not supported"), std::string::npos);
    EXPECT_NE(square_error(square("t edgeedit 4/1/3 3 0 1 0 -2 set P sharpness\n")).find("sharpness -2.000000 is negative"),
              std::string::npos);
}

TEST(HierarchicalEdit, APositionEditMovesItsVertexAndTheLevelsAfterItSeeTheMove) {
    const PolyMesh plain = read_square(square(""));
    const PolyMesh edited = read_square(square("t vertexedit 4/3/3 3 0 1 0 0 0 1 add P value\n"));
    const std::vector<PolyMesh> a = catmull_clark_levels(plain, edge_and_corner(), 2);
    const std::vector<PolyMesh> b = catmull_clark_levels(edited, edge_and_corner(), 2);
    // Face 0 = (0 1 5 4); Hbr's child 1 sits at corner 1 and its slot 0 is the point of the
    // edge before that corner, (0, 1): the boundary midpoint (-2/3, -1).
    const int v = nearest(a[1], -2.0 / 3, -1);
    ASSERT_LT((a[1].positions[v] - Vec3(-2.0 / 3, -1, 0)).norm(), 1e-15);
    EXPECT_EQ(b[1].positions[v], a[1].positions[v] + Vec3(0, 0, 1));
    for (int w = 0; w < a[1].num_vertices(); ++w)
        if (w != v) {
            EXPECT_EQ(b[1].positions[w], a[1].positions[w]) << "vertex " << w;
        }
    // Level 2: the boundary vertex rule 3/4, 1/8, 1/8 keeps 3/4 of the lift; each boundary
    // edge point beside it, 1/2.
    EXPECT_DOUBLE_EQ(b[2].positions[v].z(), 0.75);
    EXPECT_DOUBLE_EQ(b[2].positions[nearest(a[2], -2.0 / 3 + 1.0 / 6, -1)].z(), 0.5);
    EXPECT_DOUBLE_EQ(b[2].positions[nearest(a[2], -2.0 / 3 - 1.0 / 6, -1)].z(), 0.5);
    // catmull_clark_subdivide gives the last level.
    EXPECT_EQ(catmull_clark_subdivide(edited, edge_and_corner(), 2).positions, b[2].positions);
    EXPECT_TRUE(b[2].creases.edits.empty());
}

TEST(HierarchicalEdit, PathsFollowHbrsTurnOfAQuadsChildren) {
    // Face 4 = (5 6 10 9), the centre quad. Child 1 is at corner 6, (1/3, -1/3); its child 1 at
    // Hbr's slot 1, the same corner; slot 0 of that grandchild is the point of the edge from
    // the level-1 point of edge (5, 6) to corner 6: (1/6, -1/3) on the flat level-2 grid.
    // Without the turn, slot 0 would be the corner itself.
    const PolyMesh edited = read_square(square("t vertexedit 5/3/3 4 4 1 1 0 0 0 1 add P value\n"));
    const std::vector<PolyMesh> b = catmull_clark_levels(edited, edge_and_corner(), 2);
    const int v = nearest(b[2], 1.0 / 6, -1.0 / 3);
    EXPECT_LT((b[2].positions[v].head<2>() - Eigen::Vector2d(1.0 / 6, -1.0 / 3)).norm(), 1e-15);
    EXPECT_DOUBLE_EQ(b[2].positions[v].z(), 1.0);
    int lifted = 0;
    for (const Vec3& p : b[2].positions) lifted += p.z() != 0.0;
    EXPECT_EQ(lifted, 1);
    // Slot 2 of the same grandchild: the point of the level-1 edge leaving corner 6 upward,
    // (1/3, -1/6); slot 3: the level-1 quad [0, 1/3] x [-1/3, 0]'s face point, (1/6, -1/6).
    const PolyMesh edge_point = read_square(square("t vertexedit 5/3/3 4 4 1 1 2 0 0 1 add P value\n"));
    const std::vector<PolyMesh> c = catmull_clark_levels(edge_point, edge_and_corner(), 2);
    EXPECT_DOUBLE_EQ(c[2].positions[nearest(c[2], 1.0 / 3, -1.0 / 6)].z(), 1.0);
    const PolyMesh face_point = read_square(square("t vertexedit 5/3/3 4 4 1 1 3 0 0 1 add P value\n"));
    const std::vector<PolyMesh> d = catmull_clark_levels(face_point, edge_and_corner(), 2);
    EXPECT_DOUBLE_EQ(d[2].positions[nearest(d[2], 1.0 / 6, -1.0 / 6)].z(), 1.0);
}

TEST(HierarchicalEdit, ASharpnessEditMakesACornerAndAnEdgeEditACrease) {
    // hedit1: lift a level-1 vertex and make it infinitely sharp: at level 2 it stays put.
    const PolyMesh corner = read_square(square("t vertexedit 4/4/6 3 4 1 0 0 0 1 10 add P value set P sharpness\n"));
    const std::vector<PolyMesh> b = catmull_clark_levels(corner, edge_and_corner(), 2);
    const int v = nearest(b[1], 0, -1.0 / 3);  // slot 0 of child 1 of face 4: the point of edge (5, 6)
    const std::vector<PolyMesh> plain = catmull_clark_levels(read_square(square("")), edge_and_corner(), 1);
    EXPECT_EQ(b[1].positions[v], plain[1].positions[v] + Vec3(0, 0, 1));
    EXPECT_EQ(b[2].positions[v], b[1].positions[v]);  // the corner rule: the vertex itself
    // An infinitely sharp level-1 edge: its level-2 point is the midpoint of its ends.
    const PolyMesh crease = read_square(square("t vertexedit 4/3/3 3 4 1 0 0 0 1 add P value\nt edgeedit 4/1/3 3 4 1 0 10 set P sharpness\n"));
    const std::vector<PolyMesh> c = catmull_clark_levels(crease, edge_and_corner(), 2);
    // Edge 0 of that child runs from slot 0 (the lifted edge point) to slot 1, corner 6.
    const int a = nearest(c[1], 0, -1.0 / 3), d = nearest(c[1], 1.0 / 3, -1.0 / 3);
    const Vec3 mid = 0.5 * (c[1].positions[a] + c[1].positions[d]);
    EXPECT_EQ(c[2].positions[nearest(c[2], 1.0 / 6, -1.0 / 3)], mid);
}

TEST(HierarchicalEdit, AHoleEditMakesAFaceOfItsLevelAHole) {
    const PolyMesh m = read_square(square("t faceedit 4/0/1 3 4 1 1 hole\n"));
    const std::vector<PolyMesh> b = catmull_clark_levels(m, edge_and_corner(), 3);
    EXPECT_TRUE(b[1].creases.holes.empty());
    // Face 4's child at corner 1 is level-1 face 16 + 1 = 17; its child at Hbr's slot 1 (turned
    // by 1) is core's child 0: 4 * 17 + 0.
    EXPECT_EQ(b[2].creases.holes, std::vector<int>{68});
    EXPECT_EQ(b[3].creases.holes, (std::vector<int>{272, 273, 274, 275}));
}

TEST(HierarchicalEdit, OtherRefinementsRefuseAnEditedMesh) {
    const PolyMesh m = read_square(square("t vertexedit 4/3/3 3 0 1 0 0 0 1 add P value\n"));
    EXPECT_THROW(bilinear_subdivide(m, 1), InputError);
    PolyMesh tri;
    tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    tri.add_face({0, 1, 2});
    tri.creases.edits = {HierarchicalEdit{EditTarget::Position, EditOperation::Add, 0, {0}, 0, {0, 0, 1}, 0}};
    try {
        loop_subdivide(tri, LoopOptions{}, 1);
        ADD_FAILURE() << "Loop applied or dropped a hierarchical edit";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("Loop subdivision does not apply them"), std::string::npos) << e.what();
    }
    EXPECT_THROW(catmull_clark_step(m, build_poly_connectivity(m), edge_and_corner()), InputError);
}

}  // namespace
}  // namespace crossdiv
