// The streaming Catmull-Clark driver on tiny meshes computed by hand, and against
// catmull_clark_subdivide bit for bit: the same numbering, the same quads, the same sums.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/catmull_clark_streaming.h"
#include "test_meshes.h"

namespace crossdiv {
namespace {

using test::kEdgeAndCorner;
using test::kEdgeOnly;
using test::kMidpointAverage;

/// Every position, color and face of the two drivers, bit for bit.
void expect_identical(const PolyMesh& m, const CatmullClarkOptions& o, int levels) {
    const PolyMesh a = catmull_clark_subdivide_streaming(m, o, levels);
    const PolyMesh b = catmull_clark_subdivide(m, o, levels);
    EXPECT_EQ(a.face_start, b.face_start);
    EXPECT_EQ(a.face_vertices, b.face_vertices);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (size_t v = 0; v < a.positions.size(); ++v)
        for (int k = 0; k < 3; ++k)  // bits, signed zeros included
            ASSERT_EQ(std::signbit(a.positions[v][k]), std::signbit(b.positions[v][k])) << v;
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.colors, b.colors);
}

TEST(CatmullClarkStreaming, OneQuadByHandUnderEveryBoundaryRule) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(8, 0, 0), Vec3(8, 8, 0), Vec3(0, 8, 0)};
    m.add_face({0, 1, 2, 3});
    const PolyMesh e = catmull_clark_subdivide_streaming(m, kEdgeOnly, 1);
    ASSERT_EQ(e.num_vertices(), 4 + 1 + 4);
    EXPECT_EQ(e.positions[0], Vec3(1, 1, 0));  // 3/4 itself + 1/8 each boundary neighbour
    EXPECT_EQ(e.positions[2], Vec3(7, 7, 0));
    EXPECT_EQ(e.positions[4], Vec3(4, 4, 0));  // the face point
    EXPECT_EQ(e.positions[5], Vec3(4, 0, 0));  // edge 0 = (0, 1): boundary edges are midpoints
    EXPECT_EQ(e.positions[8], Vec3(0, 4, 0));  // edge 3 = (3, 0)
    // Corner c becomes the quad (v_c, E(c), F, E(c - 1)).
    EXPECT_EQ(e.face_vertices, (std::vector<int>{0, 5, 4, 8, 1, 6, 4, 5, 2, 7, 4, 6, 3, 8, 4, 7}));
    EXPECT_EQ(catmull_clark_subdivide_streaming(m, kEdgeAndCorner, 1).positions[0], Vec3(0, 0, 0));  // a corner stays
    // Midpoint-average: the vertex averaged with its two edge midpoints, 1/3 each.
    EXPECT_EQ(catmull_clark_subdivide_streaming(m, kMidpointAverage, 1).positions[0], Vec3(8.0 / 6, 8.0 / 6, 0));
}

TEST(CatmullClarkStreaming, CubeByHandAtTwoLevels) {
    // Level 1 as in CatmullClark.CubeHandValues; level 2 reads level 1's quads, built from
    // level 0's connectivity by the split's closed forms: the corner vertex, valence 3, keeps
    // moving along the diagonal, and every old vertex stays where catmull_clark_subdivide puts it.
    const PolyMesh one = catmull_clark_subdivide_streaming(test::cube(), kEdgeOnly, 1);
    EXPECT_NEAR(one.positions[7].x(), 5.0 / 9.0, 1e-15);
    const PolyMesh two = catmull_clark_subdivide_streaming(test::cube(), kEdgeOnly, 2);
    ASSERT_EQ(two.num_faces(), 96);
    ASSERT_EQ(two.num_vertices(), 26 + 24 + 48);
    const Vec3 c = two.positions[7];
    EXPECT_DOUBLE_EQ(c.x(), c.y());
    EXPECT_DOUBLE_EQ(c.y(), c.z());
    EXPECT_LT(c.x(), 5.0 / 9.0);
    expect_identical(test::cube(), kEdgeOnly, 3);
}

/// A mesh with every kind of vertex the driver meets: quads, a pentagon and a triangle; an open
/// boundary with corners of one face; interior vertices of valence 3 (5) and 4 (4); an
/// isolated vertex (10); colors.
PolyMesh mixed_patch() {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0.1),  Vec3(1, 0, 0),   Vec3(2, 0, 0.3),  Vec3(0, 1, 0),  Vec3(1, 1, 0.5),
                   Vec3(2, 1, -0.2), Vec3(0, 2, 0.4), Vec3(1, 2.2, 0),  Vec3(2, 2, 0.1), Vec3(1.5, 3, 0.2),
                   Vec3(9, 9, 9)};
    m.add_face({0, 1, 4, 3});
    m.add_face({1, 2, 5, 4});
    m.add_face({3, 4, 7, 6});
    m.add_face({4, 5, 8, 9, 7});  // a pentagon
    m.add_face({5, 2, 8});        // a triangle closing vertex 5's fan
    m.colors.resize(m.positions.size());
    for (size_t v = 0; v < m.colors.size(); ++v) m.colors[v] = Vec3(0.1 * v, 1 - 0.05 * v, 0.5);
    return m;
}

TEST(CatmullClarkStreaming, IdenticalToTheStencilDriverOnEveryRuleAndLevel) {
    for (const CatmullClarkOptions& o : {kEdgeOnly, kEdgeAndCorner, kMidpointAverage})
        for (int levels = 1; levels <= 3; ++levels) {
            expect_identical(mixed_patch(), o, levels);
            expect_identical(test::square(), o, levels);
            expect_identical(test::octahedron(), o, levels);
        }
    CatmullClarkOptions smooth = kEdgeOnly;  // OpenSubdiv's TRI_SUB_SMOOTH: triangles at level 0 only
    smooth.smooth_triangles = true;
    expect_identical(test::octahedron(), smooth, 2);
    expect_identical(mixed_patch(), smooth, 2);
}

/// A bumpy n x n grid of quads, every third one cut into two triangles: an input of polygons
/// with over 8,192 corners at n = 50, so that its own level's passes are split among threads.
PolyMesh bumpy_mixed_grid(int n) {
    PolyMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.positions.emplace_back(i, j, std::sin(0.7 * i) * std::cos(1.3 * j));
    const auto at = [&](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if ((i + 2 * j) % 3) {
                m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                m.add_face({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    return m;
}

TEST(CatmullClarkStreaming, AnyNumberOfThreadsGivesTheBitsOfOne) {
    // Passes are split from 8,192 elements on: the mixed patch's 24 corners are 24,576 quads of
    // 6,144 x 4 corners at level 6 (its last pass over 24,576 vertices at 7 levels), the grid's
    // over 10,000 corners at level 0.
    const struct { PolyMesh mesh; int levels; } cases[] = {{mixed_patch(), 7}, {bumpy_mixed_grid(50), 2}};
    for (const auto& c : cases)
        for (const CatmullClarkOptions& o : {kEdgeOnly, kEdgeAndCorner}) {
            const PolyMesh one = catmull_clark_subdivide_streaming(c.mesh, o, c.levels);
            ASSERT_GT(one.num_faces(), 40000);
            for (int threads : {2, 3, 8}) {
                const PolyMesh many = catmull_clark_subdivide_streaming(c.mesh, o, c.levels, threads);
                EXPECT_EQ(many.face_vertices, one.face_vertices) << threads;
                EXPECT_EQ(many.face_start, one.face_start) << threads;
                EXPECT_EQ(many.positions, one.positions) << threads;  // bit for bit
                EXPECT_EQ(many.colors, one.colors) << threads;
            }
        }
    expect_identical(bumpy_mixed_grid(50), kEdgeOnly, 2);  // and one thread is the stencil driver's bits
    EXPECT_THROW(catmull_clark_subdivide_streaming(mixed_patch(), kEdgeOnly, 1, 0), InputError);
}

TEST(CatmullClarkStreaming, WhatItDoesNotTakeIsRefinedByTheStencilDriver) {
    // Crease tags, a bowtie (OpenSubdiv's non-manifold rules), zero levels: the same result.
    PolyMesh creased = test::cube();
    creased.creases.edges = {{0, 1, 2.0f}};
    expect_identical(creased, kEdgeOnly, 2);
    PolyMesh bowtie = test::square();
    bowtie.positions.push_back(Vec3(-1, -1, 0));
    bowtie.positions.push_back(Vec3(0, -1, 0.5));
    bowtie.positions.push_back(Vec3(-1, 0, 0.5));
    bowtie.add_face({0, 5, 4, 6});  // shares vertex 0 only
    expect_identical(bowtie, kEdgeOnly, 2);
    expect_identical(mixed_patch(), kEdgeOnly, 0);
    // Refused alike, with the same message naming the element: a bowtie under the refusing
    // rule, a NaN, an index out of range, a negative level count.
    const auto refusal = [](const auto& refine) -> std::string {
        try {
            refine();
        } catch (const InputError& e) {
            return e.what();
        }
        return "accepted";
    };
    const auto expect_same_refusal = [&](const PolyMesh& m, const CatmullClarkOptions& o, int levels) {
        const std::string a = refusal([&] { catmull_clark_subdivide_streaming(m, o, levels); });
        EXPECT_NE(a, "accepted");
        EXPECT_EQ(a, refusal([&] { catmull_clark_subdivide(m, o, levels); }));
    };
    CatmullClarkOptions refuse = kEdgeOnly;
    refuse.nonmanifold = NonManifoldRule::Refuse;
    expect_same_refusal(bowtie, refuse, 1);
    PolyMesh nan = test::cube();
    nan.positions[3].y() = std::numeric_limits<double>::quiet_NaN();
    expect_same_refusal(nan, kEdgeOnly, 1);
    PolyMesh bad = test::square();
    bad.face_vertices[2] = 7;
    expect_same_refusal(bad, kEdgeOnly, 2);
    expect_same_refusal(test::square(), kEdgeOnly, -1);
}

}  // namespace
}  // namespace crossdiv
