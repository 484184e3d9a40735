// Face-varying channels: OBJ texture coordinates read and written exactly, refused by
// file:line when they do not fit, and refined under the six rules with hand-computed values.
#include <gtest/gtest.h>

#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/face_varying_limit.h"
#include "crossdiv/subdiv/face_varying_refinement.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "crossdiv/subdiv/loop.h"

#include "parse_errors.h"

namespace crossdiv {
namespace {

PolyMesh obj(const std::string& text) {
    std::istringstream in(text);
    return read_obj(in, "uv.obj");
}

std::string obj_error(const std::string& text) {
    return test::parse_error([](std::istream& in, const std::string& n) { return read_obj(in, n); }, text, "uv.obj");
}

const std::string kQuadWithUvs = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                 "vt 0 0\nvt 1 0\nvt 0.1 0.30000000000000004\nvt 0 2\n"
                                 "f 1/1 2/2 3/3 4/4\n";

TEST(FaceVarying, ObjTextureCoordinatesAreAChannelReadAndWrittenExactly) {
    const PolyMesh m = obj(kQuadWithUvs);
    ASSERT_EQ(m.face_varying.size(), 1u);
    const FaceVaryingChannel& uv = m.face_varying[0];
    EXPECT_EQ(uv.name, "uv");
    EXPECT_EQ(uv.dimension, 2);
    EXPECT_EQ(uv.corner_values, (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(uv.values, (std::vector<double>{0, 0, 1, 0, 0.1, 0.30000000000000004, 0, 2}));
    std::ostringstream out;
    write_obj(out, m);
    EXPECT_NE(out.str().find("vt 0.10000000000000001 0.30000000000000004\n"), std::string::npos) << out.str();
    EXPECT_NE(out.str().find("f 1/1 2/2 3/3 4/4\n"), std::string::npos);
    const PolyMesh back = obj(out.str());
    ASSERT_EQ(back.face_varying.size(), 1u);
    EXPECT_EQ(back.face_varying[0].values, uv.values);  // bit for bit
    EXPECT_EQ(back.face_varying[0].corner_values, uv.corner_values);
    // With normals: v/t/n.
    std::ostringstream with_normals;
    const std::vector<Vec3> n(4, Vec3(0, 0, 1));
    write_obj(with_normals, m, n);
    EXPECT_NE(with_normals.str().find("f 1/1/1 2/2/2 3/3/3 4/4/4\n"), std::string::npos);
}

TEST(FaceVarying, ObjTextureIndicesMayBeRelativeOrSharedAndTakeAW) {
    // Two triangles sharing a seam-free edge: corners 2 and 3 share texture values by index.
    const PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0 0.5\nvt 1 0\nvt 1 1\nvt 0 1\n"
                           "f 1/-4/1 2/-3 3/-2\nf 1/1 3/3/2 4/4\n");
    ASSERT_EQ(m.face_varying.size(), 1u);
    EXPECT_EQ(m.face_varying[0].dimension, 3);  // one vt has a w
    EXPECT_EQ(m.face_varying[0].corner_values, (std::vector<int>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(m.face_varying[0].value(1)[2], 0.0);  // w absent: 0
    // Texture coordinates no face uses make no channel.
    EXPECT_TRUE(obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\n").face_varying.empty());
}

TEST(FaceVarying, ObjCornersThatMixTextureIndicesGiveTheGeometryAndANote) {
    // As modelling tools write files whose objects have texture coordinates and others not:
    // the faces are read, the texture coordinates are not, and a note says where they part
    // (within a face, and across two).
    const struct {
        const char* text;
        int faces;
        const char* note;
    } cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3\n", 1,
         "uv.obj: texture coordinates not read: the corners of line 5 have none, those of line 5 have one "
         "(a channel needs one at every corner)"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nf 1 2 3\nf 2/1 4/1 3/1\n", 2,
         "uv.obj: texture coordinates not read: the corners of line 7 have one, those of line 6 have none "
         "(a channel needs one at every corner)"},
    };
    for (const auto& c : cases) {
        const PolyMesh m = obj(c.text);
        EXPECT_EQ(m.num_faces(), c.faces);
        EXPECT_TRUE(m.face_varying.empty());
        EXPECT_EQ(m.source.notes, std::vector<std::string>{c.note});
    }
}

TEST(FaceVarying, ObjRefusesTextureIndicesThatDoNotFit) {
    EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n"),
              "uv.obj:5: texture coordinate index 2 out of range: the file has 1 texture coordinates");
    EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/0 3/1\n"),
              "uv.obj:5: texture coordinate index 0: OBJ indices start at 1");
    EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/-2 3/1\n"),
              "uv.obj:5: relative texture coordinate index -2 points before the first texture coordinate");
    EXPECT_EQ(obj_error("vt 0 nan\n"), "uv.obj:1: texture coordinate v is nan; numbers must be finite");
    EXPECT_EQ(obj_error("vt 0 0 0 1\n"), "uv.obj:1: a texture coordinate has at most 3 components (u v w)");
    EXPECT_EQ(obj_error("vt\n"), "uv.obj:1: missing texture coordinate u");
}

TEST(FaceVarying, TheFileTagNamesTheRuleAsOpenSubdivsReaderDoes) {
    EXPECT_EQ(obj(kQuadWithUvs + "t facevaryinginterpolateboundary 1/0/0 2\n").creases.face_varying,
              FaceVaryingRule::CornersPlus1);
    EXPECT_EQ(obj(kQuadWithUvs + "t facevaryinginterpolateboundary 1/0/0 5\n").creases.face_varying, FaceVaryingRule::All);
    EXPECT_EQ(obj_error(kQuadWithUvs + "t facevaryinginterpolateboundary 1/0/0 6\n"),
              "uv.obj:10: tag 'facevaryinginterpolateboundary': expects one integer, 0 (none), 1 (corners-only), 2 "
              "(corners-plus1), 3 (corners-plus2), 4 (boundaries) or 5 (all)");
    EXPECT_EQ(face_varying_rule_from_string("corners-plus2"), FaceVaryingRule::CornersPlus2);
    EXPECT_THROW(face_varying_rule_from_string("linear"), InputError);
}

TEST(FaceVarying, AChannelThatDoesNotFitIsRefusedByFace) {
    PolyMesh m = obj(kQuadWithUvs);
    m.face_varying[0].corner_values[2] = 9;
    try {
        check_face_varying(m);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "face 0 (uv.obj:9): face-varying channel 'uv' index 9 at corner 2 is out of range (4 values)");
    }
    m.face_varying[0].corner_values.pop_back();
    EXPECT_THROW(check_face_varying(m), InputError);
}

/// One Catmull-Clark level of `m` with its channel under `rule`.
PolyMesh catmull_clark_uv(const PolyMesh& m, FaceVaryingRule rule, bool corners_sharp, int levels = 1) {
    const CatmullClarkOptions o{corners_sharp ? CatmullClarkBoundary::EdgeAndCorner : CatmullClarkBoundary::EdgeOnly};
    return subdivide_with_face_varying(m, FaceVaryingScheme::CatmullClark, {rule, corners_sharp}, levels,
                                       [&](const PolyMesh& p, const PolyConnectivity& c) { return catmull_clark_step(p, c, o); });
}

/// The value child corner `c` has.
std::array<double, 2> uv_at(const PolyMesh& m, int c) {
    const FaceVaryingChannel& ch = m.face_varying.at(0);
    const double* x = ch.value(ch.corner_values[static_cast<size_t>(c)]);
    return {x[0], x[1]};
}

/// The value vertex `v` has in child face `f`.
std::array<double, 2> uv_of(const PolyMesh& m, int f, int v) {
    for (int c = m.face_start[f]; c < m.face_start[f + 1]; ++c)
        if (m.face_vertices[c] == v) return uv_at(m, c);
    ADD_FAILURE() << "vertex " << v << " is not in face " << f;
    return {};
}

using UV = std::array<double, 2>;

TEST(FaceVarying, OneQuadUnderTheRulesByHand) {
    // Values A (0,0), B (1,0), C (1,1), D (0,2) at the corners (not affine: D has v = 2).
    // Catmull-Clark child quad k keeps corner k's vertex; its corners are (v_k, E, F, E').
    PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 2\nf 1/1 2/2 3/3 4/4\n");
    // all: bilinear. Face point (1/2, 3/4), edge points the midpoints, corners kept.
    const PolyMesh all = catmull_clark_uv(m, FaceVaryingRule::All, false);
    EXPECT_EQ(uv_of(all, 0, 0), (UV{0, 0}));
    EXPECT_EQ(uv_at(all, 1), (UV{0.5, 0}));     // E(AB)
    EXPECT_EQ(uv_at(all, 2), (UV{0.5, 0.75}));  // the face point
    EXPECT_EQ(uv_at(all, 3), (UV{0, 1}));       // E(DA)
    // none, edge-only geometry: corner A matches the vertex topology and takes the vertex's
    // boundary rule 3/4 A + 1/8 B + 1/8 D = (1/8, 1/4).
    EXPECT_EQ(uv_of(catmull_clark_uv(m, FaceVaryingRule::None, false), 0, 0), (UV{0.125, 0.25}));
    // corners-only, edge-only geometry: a value with one face is sharpened, A stays.
    EXPECT_EQ(uv_of(catmull_clark_uv(m, FaceVaryingRule::CornersOnly, false), 0, 0), (UV{0, 0}));
    // none, edge-and-corner geometry: A is a corner of the geometry, whose mask keeps it.
    EXPECT_EQ(uv_of(catmull_clark_uv(m, FaceVaryingRule::None, true), 0, 0), (UV{0, 0}));
}

TEST(FaceVarying, ASeamBetweenTwoQuadsByHand) {
    // Quads L = (0 1 4 3) and R = (1 2 5 4) in the plane; the shared edge 1-4 is a seam: L has
    // (1,0) and (1,1) there, R (3,0) and (3,3).
    const PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
                           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 3 0\nvt 4 0\nvt 4 1\nvt 3 3\n"
                           "f 1/1 2/2 5/3 4/4\nf 2/5 3/6 6/7 5/8\n");
    // none: each side of vertex 4 is a crease along its face's two edges at 4:
    //   L: 3/4 (1,1) + 1/8 (1,0) + 1/8 (0,1) = (7/8, 7/8);
    //   R: 3/4 (3,3) + 1/8 (4,1) + 1/8 (3,0) = (25/8, 19/8).
    const PolyMesh none = catmull_clark_uv(m, FaceVaryingRule::None, false);
    EXPECT_EQ(uv_of(none, 2, 4), (UV{0.875, 0.875}));  // child quads 0..3 are L's, 4..7 R's
    EXPECT_EQ(uv_of(none, 7, 4), (UV{3.125, 2.375}));
    // The seam's edge point has one value per side, each the midpoint of its side.
    const int e14 = none.face_vertices[4 * 1 + 1];  // quad of L's corner 1 (vertex 1): (1, E(1 4), F, E(0 1))
    EXPECT_EQ(uv_of(none, 1, e14), (UV{1, 0.5}));
    EXPECT_EQ(uv_of(none, 7, e14), (UV{3, 1.5}));  // R's corner 3 (vertex 4): (4, E(4 1), F, E(5 4))
    // corners-only: each side of vertex 4 has one face, a corner: kept.
    const PolyMesh corners = catmull_clark_uv(m, FaceVaryingRule::CornersOnly, false);
    EXPECT_EQ(uv_of(corners, 2, 4), (UV{1, 1}));
    EXPECT_EQ(uv_of(corners, 7, 4), (UV{3, 3}));
    // Holes keep their channel corners with their faces: the emitted mesh drops R's quads.
    PolyMesh holed = m;
    holed.creases.holes = {1};
    const PolyMesh emitted = without_hole_faces(catmull_clark_uv(holed, FaceVaryingRule::None, false));
    ASSERT_EQ(emitted.num_faces(), 4);
    EXPECT_EQ(emitted.face_varying[0].corner_values.size(), 16u);
    EXPECT_EQ(uv_of(emitted, 2, 4), (UV{0.875, 0.875}));
}

/// The limit value of vertex v's value in face f of `mesh` under `rule` (Catmull-Clark).
UV limit_of(const PolyMesh& mesh, int f, int v, FaceVaryingRule rule, bool corners_sharp) {
    PolyMesh limit = mesh;
    limit.face_varying[0] = face_varying_limit(mesh, mesh.face_varying[0], FaceVaryingScheme::CatmullClark,
                                               FaceVaryingOptions{rule, corners_sharp});
    return uv_of(limit, f, v);
}

TEST(FaceVarying, LimitValuesOfAQuadGridByHand) {
    // The 2 x 2 quad grid, UVs (x, y) but for the centre (1, 1.5) and the boundary vertex
    // (1, 0) given (1, 0.3): not affine, so that every mask shows.
    const PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\n"
                           "vt 0 0\nvt 1 0.3\nvt 2 0\nvt 0 1\nvt 1 1.5\nvt 2 1\nvt 0 2\nvt 1 2\nvt 2 2\n"
                           "f 1/1 2/2 5/5 4/4\nf 2/2 3/3 6/6 5/5\nf 4/4 5/5 8/8 7/7\nf 5/5 6/6 9/9 8/8\n");
    // The centre, smooth and regular: (16 v + 4 sum e + sum f) / 36 with edge neighbours (1, 0.3),
    // (2, 1), (1, 2), (0, 1) and face neighbours (0, 0), (2, 0), (2, 2), (0, 2):
    // u = (16 + 16 + 4) / 36 = 1, v = (24 + 4 (4.3) + 4) / 36 = 45.2 / 36.
    const UV centre = limit_of(m, 0, 4, FaceVaryingRule::None, false);
    EXPECT_DOUBLE_EQ(centre[0], 1.0);
    EXPECT_DOUBLE_EQ(centre[1], 45.2 / 36.0);
    // Every rule but all smooths an interior value; all keeps it.
    EXPECT_EQ(limit_of(m, 0, 4, FaceVaryingRule::CornersOnly, false), centre);
    EXPECT_EQ(limit_of(m, 0, 4, FaceVaryingRule::All, false), (UV{1, 1.5}));
    // The boundary vertex (1, 0): the crease limit along the boundary, 2/3 (1, 0.3) + 1/6 (0, 0)
    // + 1/6 (2, 0) = (1, 0.2); `boundaries` makes it linear: kept.
    const UV b = limit_of(m, 0, 1, FaceVaryingRule::None, false);
    EXPECT_DOUBLE_EQ(b[0], 1.0);
    EXPECT_DOUBLE_EQ(b[1], 0.2);
    EXPECT_EQ(limit_of(m, 0, 1, FaceVaryingRule::Boundaries, false), (UV{1, 0.3}));
    // The corner (0, 0) under edge-only and none: the crease limit too, 2/3 (0, 0) + 1/6 (1, 0.3)
    // + 1/6 (0, 1); under edge-and-corner (a sharp corner), or a rule that sharpens one-face
    // values, it stays.
    const UV c = limit_of(m, 0, 0, FaceVaryingRule::None, false);
    EXPECT_DOUBLE_EQ(c[0], 1.0 / 6.0);
    EXPECT_DOUBLE_EQ(c[1], 1.3 / 6.0);
    EXPECT_EQ(limit_of(m, 0, 0, FaceVaryingRule::None, true), (UV{0, 0}));
    EXPECT_EQ(limit_of(m, 0, 0, FaceVaryingRule::CornersOnly, false), (UV{0, 0}));
}

TEST(FaceVarying, LimitValuesOnASeamByHand) {
    // The two quads of ASeamBetweenTwoQuadsByHand: under none, each side of vertex 4 is a
    // crease along its own face's edges: L 2/3 (1,1) + 1/6 (1,0) + 1/6 (0,1) = (5/6, 5/6);
    // R 2/3 (3,3) + 1/6 (4,1) + 1/6 (3,0) = (19/6, 13/6). corners-only keeps both.
    const PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
                           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 3 0\nvt 4 0\nvt 4 1\nvt 3 3\n"
                           "f 1/1 2/2 5/3 4/4\nf 2/5 3/6 6/7 5/8\n");
    const UV l = limit_of(m, 0, 4, FaceVaryingRule::None, false), r = limit_of(m, 1, 4, FaceVaryingRule::None, false);
    EXPECT_DOUBLE_EQ(l[0], 5.0 / 6.0);
    EXPECT_DOUBLE_EQ(l[1], 5.0 / 6.0);
    EXPECT_DOUBLE_EQ(r[0], 19.0 / 6.0);
    EXPECT_DOUBLE_EQ(r[1], 13.0 / 6.0);
    EXPECT_EQ(limit_of(m, 1, 4, FaceVaryingRule::CornersOnly, false), (UV{3, 3}));
}

TEST(FaceVarying, TheLimitOfASmoothVertexAmongTrianglesNeedsAQuadLevel) {
    // A smooth vertex with a triangle around it: Catmull-Clark's limit mask is for quads.
    const PolyMesh fan = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n"
                             "vt 0 0\nvt 1 0\nvt 0 1\nvt -1 0\nvt 0 -1\n"
                             "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\nf 1/1 4/4 5/5\nf 1/1 5/5 2/2\n");
    try {
        face_varying_limit(fan, fan.face_varying[0], FaceVaryingScheme::CatmullClark, {FaceVaryingRule::None, false});
        FAIL() << "a triangle around a smooth vertex was taken";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 0 has a face of 3 corners"), std::string::npos) << e.what();
    }
    // Loop takes it: the valence-4 mask with Loop's beta on the ring (symmetric: the centre stays).
    const FaceVaryingChannel loop =
        face_varying_limit(fan, fan.face_varying[0], FaceVaryingScheme::Loop, {FaceVaryingRule::None, false});
    EXPECT_NEAR(loop.value(fan.face_varying[0].corner_values[0])[0], 0.0, 1e-15);
}

TEST(FaceVarying, LoopRefinesAChannelToo) {
    // One triangle, values (0,0) (1,0) (0,2); all: the edge points are the midpoints.
    const PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 2\nf 1/1 2/2 3/3\n");
    const LoopOptions o{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    auto loop = [&](FaceVaryingRule rule) {
        return subdivide_with_face_varying(m, FaceVaryingScheme::Loop, {rule, false}, 1,
                                           [&](const PolyMesh& p, const PolyConnectivity& c) { return loop_step(p, c, o); });
    };
    const PolyMesh all = loop(FaceVaryingRule::All);
    EXPECT_EQ(uv_of(all, 3, all.face_vertices[9]), (UV{0.5, 0}));  // the middle triangle (m0 m1 m2): m0 on edge 0-1
    // none: vertex 0 takes the boundary rule, 3/4 (0,0) + 1/8 (1,0) + 1/8 (0,2).
    EXPECT_EQ(uv_of(loop(FaceVaryingRule::None), 0, 0), (UV{0.125, 0.25}));
}

TEST(FaceVarying, ASemiSharpCreaseInsideASpanBlendsAtItsLastLevelByHand) {
    // The 2 x 2 grid, one seam from (1,0) to (1,1) on the right of the centre vertex 4 = (1,1):
    // face 1 gives vertex 4 its own value (5,5). Vertex 4's other value spans faces 0, 2, 3,
    // across the edges 4-3 (x = 0..1, y = 1) and 4-7 (x = 1, y = 1..2); edge 4-3 has
    // sharpness 1, which decays to 0 in the first level: the crease mask is blended toward the
    // corner's by that edge's transition weight, 1 (its sharpness, clamped to 1):
    // value 4 stays (1,1) under `none` at level 1.
    PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\n"
                     "vt 0 0\nvt 1 0\nvt 2 0\nvt 0 1\nvt 1 1\nvt 2 1\nvt 0 2\nvt 1 2\nvt 2 2\nvt 5 5\n"
                     "f 1/1 2/2 5/5 4/4\nf 2/2 3/3 6/6 5/10\nf 4/4 5/5 8/8 7/7\nf 5/5 6/6 9/9 8/8\n"
                     "t crease 2/1/0 4 3 1\n");
    const PolyMesh sharp = catmull_clark_uv(m, FaceVaryingRule::None, false);
    EXPECT_EQ(uv_of(sharp, 2, 4), (UV{1, 1}));  // child quad k keeps corner k: quad 2, face 0's corner at vertex 4
    // At sharpness 0.5 the weight is 0.5: half the crease mask along the span's ends, which
    // are vertex 1's value (1,0) in face 0 and vertex 5's (2,1) in face 3:
    // 1/2 (1,1) + 1/2 (3/4 (1,1) + 1/8 (1,0) + 1/8 (2,1)) = (17/16, 15/16).
    m.creases.edges[0].sharpness = 0.5f;
    const PolyMesh half = catmull_clark_uv(m, FaceVaryingRule::None, false);
    EXPECT_EQ(uv_of(half, 2, 4), (UV{17.0 / 16, 15.0 / 16}));
}

/// `levels` Catmull-Clark levels of `m` (edge-only) with its channel under `rule` and whose rules.
PolyMesh catmull_clark_uv_by(const PolyMesh& m, FaceVaryingRule rule, CreaseRules rules, int levels) {
    CatmullClarkOptions o{CatmullClarkBoundary::EdgeOnly};  // the boundary has no default: left out it was read indeterminate
    o.crease_rules = rules;
    return subdivide_with_face_varying(m, FaceVaryingScheme::CatmullClark, {rule, false, CreaseMethod::Uniform, rules}, levels,
                                       [&](const PolyMesh& p, const PolyConnectivity& c) { return catmull_clark_step(p, c, o); });
}

TEST(FaceVarying, HbrsRulesMakeASemiSharpEdgeAFaceVaryingBoundaryForGoodByHand) {
    // The 2 x 2 grid with UVs (x, y) but (1, 2.4) at vertex 7 (not affine), no seam; the middle
    // line 3-4-5 has sharpness 0.5. Under `none`, Far treats vertex 4 by its own mask: the
    // crease rule and the smooth one blended half and half. Smooth: v = 1/2 1 + (0 + 1 + 1 +
    // 2.4) / 16 + (0.5 + 0.5 + 1.6 + 1.6) / 16 = 1.0375, u = 1; crease: (1, 1); so (1, 1.01875).
    // Hbr makes any sharp edge a face-varying boundary: vertex 4 has two, the boundary rule
    // 3/4 (1, 1) + 1/8 (0, 1) + 1/8 (2, 1) = (1, 1) exactly.
    PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nv 0 2 0\nv 1 2 0\nv 2 2 0\n"
                     "vt 0 0\nvt 1 0\nvt 2 0\nvt 0 1\nvt 1 1\nvt 2 1\nvt 0 2\nvt 1 2.4\nvt 2 2\n"
                     "f 1/1 2/2 5/5 4/4\nf 2/2 3/3 6/6 5/5\nf 4/4 5/5 8/8 7/7\nf 5/5 6/6 9/9 8/8\n"
                     "t crease 2/1/0 3 4 0.5\nt crease 2/1/0 4 5 0.5\n");
    const PolyMesh far = catmull_clark_uv_by(m, FaceVaryingRule::None, CreaseRules::OpenSubdiv, 1);
    const UV far_centre = uv_of(far, 2, 4);  // child quad 2: face 0's corner at vertex 4
    EXPECT_DOUBLE_EQ(far_centre[0], 1.0);
    EXPECT_DOUBLE_EQ(far_centre[1], 1.01875);
    const PolyMesh hbr = catmull_clark_uv_by(m, FaceVaryingRule::None, CreaseRules::Hbr, 1);
    EXPECT_EQ(uv_of(hbr, 2, 4), (UV{1, 1}));
    // The point of edge 4-3 (child quad 2's corner 1): Hbr's midpoint (0.5, 1); Far blends the
    // midpoint with the smooth edge rule, v = 1/2 1 + 1/2 (2/4 + 0.5/4 + 1.6/4) = 1.0125.
    EXPECT_EQ(uv_at(hbr, 9), (UV{0.5, 1}));
    EXPECT_DOUBLE_EQ(uv_at(far, 9)[1], 1.0125);
    // The sharpness is gone at level 1, but in Hbr the halves of the edges stay face-varying
    // boundaries: vertex 4 again 3/4 (1, 1) + 1/8 (0.5, 1) + 1/8 (1.5, 1) = (1, 1); Far's
    // level 2 is smooth there and keeps the asymmetry.
    EXPECT_EQ(uv_of(catmull_clark_uv_by(m, FaceVaryingRule::None, CreaseRules::Hbr, 2), 8, 4), (UV{1, 1}));
    EXPECT_GT(uv_of(catmull_clark_uv_by(m, FaceVaryingRule::None, CreaseRules::OpenSubdiv, 2), 8, 4)[1], 1.001);
    // Hbr has no corners-only rule.
    EXPECT_THROW(catmull_clark_uv_by(m, FaceVaryingRule::CornersOnly, CreaseRules::Hbr, 1), InputError);
}

}  // namespace
}  // namespace crossdiv
