// Creases for Loop and Catmull-Clark (OpenSubdiv's rules): the rules of crease_mask.h on
// hand-picked sharpness values, then refined points computed by hand on the cube and the
// octahedron, the identities the rules imply, the decayed tags, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/crease_mask.h"
#include "crossdiv/subdiv/doo_sabin.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/sqrt3.h"
#include "loop_test_meshes.h"
#include "test_meshes.h"

namespace crossdiv {
namespace {

using test::cube;
using test::octahedron;

const CatmullClarkOptions kCC{CatmullClarkBoundary::EdgeOnly};
using test::kLoopEdge;

/// The cube with all twelve edges tagged `s`.
PolyMesh creased_cube(float s) {
    PolyMesh m = cube();
    const PolyConnectivity conn = build_poly_connectivity(m);
    for (const auto& e : conn.edge_vertices) m.creases.edges.push_back({e[0], e[1], s});
    return m;
}

PolyMesh with_equator(PolyMesh m, float s) {
    for (auto [a, b] : {std::array{0, 2}, {2, 1}, {1, 3}, {3, 0}}) m.creases.edges.push_back({a, b, s});
    return m;
}

void expect_point(const Vec3& p, double x, double y, double z) {
    EXPECT_DOUBLE_EQ(p.x(), x);
    EXPECT_DOUBLE_EQ(p.y(), y);
    EXPECT_DOUBLE_EQ(p.z(), z);
}

TEST(CreaseMask, UniformDecayDropsOnePerLevel) {
    EXPECT_EQ(decrement_sharpness(2.5f), 1.5f);
    EXPECT_EQ(decrement_sharpness(1.0f), 0.0f);
    EXPECT_EQ(decrement_sharpness(0.5f), 0.0f);
    EXPECT_EQ(decrement_sharpness(0.0f), 0.0f);
    EXPECT_EQ(decrement_sharpness(10.0f), kSharpnessInfinite);  // infinite stays
    EXPECT_EQ(decrement_sharpness(12.0f), kSharpnessInfinite);
}

TEST(CreaseMask, ChaikinAveragesWithTheOtherSemiSharpEdges) {
    const std::vector<float> around = {2.0f, 4.0f, 0.0f, 10.0f};  // 0 and 10 are not semi-sharp
    // 3/4 * 2 + 1/4 * 4 - 1 = 1.5; 3/4 * 4 + 1/4 * 2 - 1 = 2.5
    EXPECT_EQ(child_edge_sharpness(CreaseMethod::Chaikin, 2.0f, around), 1.5f);
    EXPECT_EQ(child_edge_sharpness(CreaseMethod::Chaikin, 4.0f, around), 2.5f);
    EXPECT_EQ(child_edge_sharpness(CreaseMethod::Chaikin, 10.0f, around), kSharpnessInfinite);
    EXPECT_EQ(child_edge_sharpness(CreaseMethod::Chaikin, 0.0f, around), 0.0f);
    EXPECT_EQ(child_edge_sharpness(CreaseMethod::Uniform, 2.0f, around), 1.0f);
    // 1.2 next to 0.2: 0.9 + 0.05 - 1 < 0, so the half is smooth although 1.2 > 1.
    const std::vector<float> fading = {1.2f, 0.2f};
    EXPECT_EQ(child_edge_sharpness(CreaseMethod::Chaikin, 1.2f, fading), 0.0f);
}

TEST(CreaseMask, RuleFollowsTheNumberOfSharpEdges) {
    EXPECT_EQ(vertex_rule(0.0f, 0), VertexRule::Smooth);
    EXPECT_EQ(vertex_rule(0.0f, 1), VertexRule::Dart);
    EXPECT_EQ(vertex_rule(0.0f, 2), VertexRule::Crease);
    EXPECT_EQ(vertex_rule(0.0f, 3), VertexRule::Corner);
    EXPECT_EQ(vertex_rule(0.5f, 0), VertexRule::Corner);
}

TEST(CreaseMask, TransitionWeightAveragesWhatDecayed) {
    EXPECT_EQ(transition_weight(0.0f, 0.0f, std::vector<float>{0.5f, 0.5f, 0.0f}, std::vector<float>{0, 0, 0}), 0.5f);
    // Only the edge that decayed counts: 2 -> 1 stays sharp, 0.3 -> 0 decays.
    EXPECT_EQ(transition_weight(0.0f, 0.0f, std::vector<float>{2.0f, 0.3f}, std::vector<float>{1.0f, 0.0f}), 0.3f);
    EXPECT_EQ(transition_weight(0.4f, 0.0f, std::vector<float>{}, std::vector<float>{}), 0.4f);
    EXPECT_EQ(transition_weight(0.0f, 0.0f, std::vector<float>{1.5f}, std::vector<float>{0.0f}), 1.0f);  // clamped
}

// Hbr's rule change: the average of the sharpnesses strictly between 0 and 1 (a vertex of
// exactly 1 is left out: it is still sharp in Hbr's next rule).
TEST(CreaseMask, HbrsTransitionWeightAveragesWhatLiesBelowOne) {
    EXPECT_EQ(hbr_transition_weight(1.0f, std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f}), 0.5f);
    EXPECT_EQ(hbr_transition_weight(0.5f, std::vector<float>{0.25f, 2.0f}), 0.375f);
    EXPECT_EQ(hbr_transition_weight(0.0f, std::vector<float>{1.0f, 10.0f}), 0.0f);
    EXPECT_EQ(hbr_child_rule_sharpness(1.0f), 1.0f);
    EXPECT_EQ(hbr_child_rule_sharpness(0.999f), 0.0f);
}

// A 2x2 grid of quads whose centre (1,1,1/2) is a corner of sharpness 1 with its four edges at
// 1/2: Far blends the corner (z = 1/2) with the smooth point (z = 1/4 + (4 x 1/8)/16 = 9/32) by
// the average of 1 and four 1/2, 3/5 (in float, as Sdc): 0.6 x 1/2 + 0.4 x 9/32 = 0.4125. Hbr's
// rule keeps the corner whole: 1/2.
TEST(Creases, HbrsTransitionKeepsAVertexOfSharpnessOneSharp) {
    PolyMesh m;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) m.positions.emplace_back(x, y, x == 1 && y == 1 ? 0.5 : 0.0);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) m.add_face({3 * y + x, 3 * y + x + 1, 3 * y + x + 4, 3 * y + x + 3});
    m.creases.vertices.push_back({4, 1.0f});
    for (int b : {1, 3, 5, 7}) m.creases.edges.push_back({4, b, 0.5f});
    CatmullClarkOptions far{CatmullClarkBoundary::EdgeOnly};
    const double p = 0.6f;
    EXPECT_NEAR(catmull_clark_subdivide(m, far, 1).positions[4].z(), p * 0.5 + (1 - p) * 9.0 / 32.0, 1e-15);
    CatmullClarkOptions hbr = far;
    hbr.crease_rules = CreaseRules::Hbr;
    EXPECT_EQ(catmull_clark_subdivide(m, hbr, 1).positions[4].z(), 0.5);
}

TEST(CreaseMask, BlendTakesWhatTheParentLacksFromTheChild) {
    VertexPointMask corner, smooth;
    corner.set_corner();
    smooth.vertex = 1.0 / 3.0;
    smooth.has_edges = true;
    smooth.edge.assign(3, 1.0 / 9.0);
    smooth.face.assign(3, 1.0 / 9.0);
    blend_vertex_masks(corner, smooth, 0.5);
    EXPECT_DOUBLE_EQ(corner.vertex, 0.5 + 0.5 / 3.0);
    ASSERT_EQ(corner.edge.size(), 3u);
    EXPECT_DOUBLE_EQ(corner.edge[1], 0.5 / 9.0);
    EXPECT_DOUBLE_EQ(corner.face[2], 0.5 / 9.0);
}

TEST(CatmullClarkCreases, InfinitelySharpCubeKeepsItsCornersAndEdges) {
    const PolyMesh r = catmull_clark_subdivide(creased_cube(kSharpnessInfinite), kCC, 1);
    // Corners stay, edge points are midpoints, face points centroids: the cube itself.
    for (int v = 0; v < 8; ++v) EXPECT_EQ(r.positions[v], cube().positions[v]);
    for (int e = 0; e < 12; ++e) {
        const Vec3& p = r.positions[8 + 6 + e];
        EXPECT_EQ(p.cwiseAbs().maxCoeff(), 1.0);
        EXPECT_EQ(p.cwiseAbs().sum(), 2.0);  // one coordinate 0, two +-1
    }
    // The tags decay into the child: 24 halves of sharpness 10, the method carried.
    EXPECT_EQ(r.creases.edges.size(), 24u);
    for (const SharpEdge& e : r.creases.edges) EXPECT_EQ(e.sharpness, kSharpnessInfinite);
    // And at every further level the surface stays on the cube.
    const PolyMesh r3 = catmull_clark_subdivide(creased_cube(kSharpnessInfinite), kCC, 3);
    for (const Vec3& p : r3.positions) EXPECT_EQ(p.cwiseAbs().maxCoeff(), 1.0);
}

TEST(CatmullClarkCreases, FractionalSharpnessBlendsByHand) {
    // Sharpness 0.5 decays to 0 in one step: every mask is half sharp, half smooth.
    const PolyMesh r = catmull_clark_subdivide(creased_cube(0.5f), kCC, 1);
    // Corner (1,1,1): 1/2 * itself + 1/2 * the smooth point (F + 2R)/3 = 5/9 -> 7/9.
    expect_point(r.positions[7], 7.0 / 9.0, 7.0 / 9.0, 7.0 / 9.0);
    // Edge 3-7 (x = y = 1): (1/2 * 1/2 + 1/2 * 1/4) on each end, 1/2 * 1/4 on each face point.
    const PolyConnectivity conn = build_poly_connectivity(cube());
    int e37 = -1;
    for (int e = 0; e < conn.num_edges(); ++e)
        if ((conn.edge_vertices[e][0] == 3 && conn.edge_vertices[e][1] == 7) ||
            (conn.edge_vertices[e][0] == 7 && conn.edge_vertices[e][1] == 3))
            e37 = e;
    ASSERT_GE(e37, 0);
    expect_point(r.positions[8 + 6 + e37], 0.875, 0.875, 0.0);
    EXPECT_TRUE(r.creases.empty());  // all decayed
}

TEST(CatmullClarkCreases, ChaikinTransitionWeightIsNotClamped) {
    // Bottom loop 1.2, 0.2, 1.2, 0.2 under Chaikin: a 1.2 edge's halves become
    // 3/4 * 1.2 + 1/4 * 0.2 - 1 < 0, smooth, so the edge point blends with weight s = 1.2 as
    // OpenSubdiv does (no clamp): ends 1.2 * 1/2 - 0.2 * 1/4 = 0.55, face points -0.2 * 1/4.
    PolyMesh m = cube();
    m.creases.edges = {{0, 1, 1.2f}, {1, 3, 0.2f}, {3, 2, 1.2f}, {2, 0, 0.2f}};
    const PolyMesh r = catmull_clark_subdivide(m, {CatmullClarkBoundary::EdgeOnly, CreaseMethod::Chaikin}, 1);
    const PolyConnectivity conn = build_poly_connectivity(m);
    int e01 = -1;
    for (int e = 0; e < conn.num_edges(); ++e)
        if (std::min(conn.edge_vertices[e][0], conn.edge_vertices[e][1]) == 0 &&
            std::max(conn.edge_vertices[e][0], conn.edge_vertices[e][1]) == 1)
            e01 = e;
    ASSERT_GE(e01, 0);
    // 0.55 * ((-1,-1,-1) + (1,-1,-1)) - 0.05 * ((0,0,-1) + (0,-1,0)) = (0, -1.05, -1.05),
    // outside the cube -- with s the float nearest 1.2, as tags are stored.
    const double sharp = 1.2f, end = sharp * 0.5 + (1 - sharp) * 0.25, face = (1 - sharp) * 0.25;
    const Vec3 p = r.positions[8 + 6 + e01];
    EXPECT_NEAR(end, 0.55, 1e-7);
    EXPECT_NEAR(p.x(), 0.0, 1e-15);
    EXPECT_NEAR(p.y(), -2 * end - face, 1e-15);
    EXPECT_NEAR(p.z(), -2 * end - face, 1e-15);
    EXPECT_LT(p.y(), -1.0499);
    // Uniform decay keeps the halves at 0.2: a crease, the midpoint.
    const PolyMesh u = catmull_clark_subdivide(m, kCC, 1);
    EXPECT_EQ(u.positions[8 + 6 + e01], Vec3(0, -1, -1));
}

TEST(CatmullClarkCreases, SharpnessOneIsOneSharpLevelThenSmooth) {
    // s = 1 decays to 0 with transition weight 1: level 1 is exactly the infinitely sharp
    // one, and what follows is plain Catmull-Clark.
    const PolyMesh one = catmull_clark_subdivide(creased_cube(1.0f), kCC, 2);
    PolyMesh sharp = catmull_clark_subdivide(creased_cube(kSharpnessInfinite), kCC, 1);
    sharp.creases = {};
    const PolyMesh expected = catmull_clark_subdivide(sharp, kCC, 1);
    EXPECT_EQ(one.positions, expected.positions);
    EXPECT_EQ(one.face_vertices, expected.face_vertices);
}

TEST(CatmullClarkCreases, ZeroSharpnessTagsChangeNothing) {
    // Tags of sharpness 0 take the crease path; its masks must be the plain ones, bit for bit,
    // on a closed and an open mesh and under both boundary rules.
    for (CatmullClarkBoundary b : {CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner})
        for (const PolyMesh& base : {cube(), test::square()}) {
            PolyMesh tagged = base;
            tagged.creases.edges.push_back({base.face(0)[0], base.face(0)[1], 0.0f});
            const PolyMesh a = catmull_clark_subdivide(base, {b}, 2), t = catmull_clark_subdivide(tagged, {b}, 2);
            EXPECT_EQ(a.positions, t.positions);
            EXPECT_EQ(a.face_vertices, t.face_vertices);
        }
}

TEST(LoopCreases, EquatorCreaseByHand) {
    const PolyMesh r = loop_subdivide(with_equator(octahedron(), kSharpnessInfinite), kLoopEdge, 1);
    expect_point(r.positions[0], 0.75, 0.0, 0.0);  // 3/4 itself + 1/8 (0,1,0) + 1/8 (0,-1,0)
    // The pole has no sharp edge: Loop's valence-4 mask, 1 - 4 beta = 33/64 (beta = 31/256).
    expect_point(r.positions[4], 0.0, 0.0, 33.0 / 64.0);
    // Equator edge points are midpoints; a pole edge keeps the smooth 3/8, 1/8, whose two
    // opposite vertices (antipodal on the equator) cancel: 3/8 (a + b).
    const PolyConnectivity conn = build_poly_connectivity(octahedron());
    for (int e = 0; e < conn.num_edges(); ++e) {
        const Vec3& p = r.positions[6 + e];
        const Vec3 a = octahedron().positions[conn.edge_vertices[e][0]], b = octahedron().positions[conn.edge_vertices[e][1]];
        if (a.z() == 0 && b.z() == 0) EXPECT_EQ(p, 0.5 * (a + b)) << "edge " << e;
        else EXPECT_EQ(p, 0.375 * (a + b)) << "edge " << e;
    }
    EXPECT_EQ(r.creases.edges.size(), 8u);
}

TEST(LoopCreases, CornerAndDartByHand) {
    PolyMesh m = octahedron();
    m.creases.vertices.push_back({4, kSharpnessInfinite});  // the pole stays
    m.creases.edges.push_back({0, 2, kSharpnessInfinite});  // a dart at each end
    const PolyMesh r = loop_subdivide(m, kLoopEdge, 1);
    expect_point(r.positions[4], 0.0, 0.0, 1.0);
    expect_point(r.positions[0], 33.0 / 64.0, 0.0, 0.0);  // a dart keeps the smooth mask
    ASSERT_EQ(r.creases.vertices.size(), 1u);
    EXPECT_EQ(r.creases.vertices[0], (SharpVertex{4, kSharpnessInfinite}));
    // Corner sharpness 0.5 at the pole: half the corner, half the smooth point.
    PolyMesh half = octahedron();
    half.creases.vertices.push_back({4, 0.5f});
    EXPECT_DOUBLE_EQ(loop_subdivide(half, kLoopEdge, 1).positions[4].z(), 0.5 + 0.5 * 33.0 / 64.0);
}

TEST(LoopCreases, ZeroSharpnessMatchesTheFastDriver) {
    // The generic step sums term by term, the fast driver by groups: equal up to rounding
    // (a few ulps of coordinates of size 1). Level 1 has the same order; from level 2 on the
    // two number edges differently, so the positions are compared as sorted sets.
    constexpr double kRounding = 4e-16;
    PolyMesh tagged = octahedron();
    tagged.creases.edges.push_back({0, 2, 0.0f});
    const PolyMesh a = loop_subdivide(octahedron(), kLoopEdge, 1), t = loop_subdivide(tagged, kLoopEdge, 1);
    ASSERT_EQ(a.face_vertices, t.face_vertices);
    for (size_t v = 0; v < a.positions.size(); ++v) EXPECT_LE((a.positions[v] - t.positions[v]).norm(), kRounding);
    auto sorted = [](std::vector<Vec3> p) {
        std::sort(p.begin(), p.end(), [](const Vec3& x, const Vec3& y) {
            return std::tie(x.x(), x.y(), x.z()) < std::tie(y.x(), y.y(), y.z());
        });
        return p;
    };
    const std::vector<Vec3> a3 = sorted(loop_subdivide(octahedron(), kLoopEdge, 3).positions),
                            t3 = sorted(loop_subdivide(tagged, kLoopEdge, 3).positions);
    ASSERT_EQ(a3.size(), t3.size());
    double worst = 0;
    for (size_t v = 0; v < a3.size(); ++v) worst = std::max(worst, (a3[v] - t3[v]).norm());
    EXPECT_LE(worst, kRounding);
}

TEST(Creases, BadTagsNameTheTag) {
    PolyMesh m = octahedron();
    m.creases.edges.push_back({4, 5, 2.0f});  // the poles share no edge
    m.source.file = "oct.obj";
    m.creases.edge_line = {17};
    try {
        loop_subdivide(m, kLoopEdge, 1);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "crease tag (4, 5) (oct.obj:17): vertices 4 and 5 share no edge");
    }
    PolyMesh neg = octahedron();
    neg.creases.vertices.push_back({9, 1.0f});
    EXPECT_THROW(loop_subdivide(neg, kLoopEdge, 1), InputError);
    PolyMesh nan = octahedron();
    nan.creases.edges.push_back({0, 2, std::nanf("")});
    EXPECT_THROW(loop_subdivide(nan, kLoopEdge, 1), InputError);
}

TEST(Creases, SchemesWithoutCreaseRulesRefuseTags) {
    const PolyMesh tagged = with_equator(octahedron(), 2.0f);
    EXPECT_THROW(sqrt3_subdivide(tagged, {Sqrt3Parity::CountFromInput}, 1), InputError);
    EXPECT_THROW(doo_sabin_subdivide(tagged, {DooSabinBoundary::ChaikinBoundary}, 1), InputError);
    EXPECT_THROW(to_tri_mesh(tagged, "Loop subdivision"), InputError);  // the fast path would drop them
    EXPECT_THROW(catmull_clark_subdivide(creased_cube(1.0f), {CatmullClarkBoundary::MidpointAverage}, 1), InputError);
}

}  // namespace
}  // namespace crossdiv
