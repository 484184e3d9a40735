// The streaming Loop driver on tiny meshes computed by hand, and against loop_subdivide: the
// same numbering, the same triangles, edge points bit for bit.
#include <gtest/gtest.h>

#include <string>

#include <cmath>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "loop_test_meshes.h"

namespace crossdiv {
namespace {

using test::kLoopCorner;
using test::kLoopEdge;
using test::kWarrenEdge;
using test::tri_octahedron;

TEST(LoopStreaming, SingleTriangleUnderBothBoundaryRules) {
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(8, 0, 0), Vec3(0, 8, 0)};
    m.triangles = {{0, 1, 2}};
    const TriMesh e = loop_subdivide_streaming(m, kLoopEdge, 1);
    EXPECT_EQ(e.positions[0], Vec3(1, 1, 0));  // 3/4 itself + 1/8 each other corner
    EXPECT_EQ(e.positions[1], Vec3(6, 1, 0));
    EXPECT_EQ(e.positions[2], Vec3(1, 6, 0));
    const TriMesh c = loop_subdivide_streaming(m, kLoopCorner, 1);
    for (int v = 0; v < 3; ++v) EXPECT_EQ(c.positions[v], m.positions[v]);  // one face each: corners stay
    for (const TriMesh* r : {&e, &c}) {
        EXPECT_EQ(r->positions[3], Vec3(4, 0, 0));  // edges 0->1, 1->2, 2->0: midpoints
        EXPECT_EQ(r->positions[4], Vec3(4, 4, 0));
        EXPECT_EQ(r->positions[5], Vec3(0, 4, 0));
        EXPECT_EQ(r->triangles, (std::vector<Triangle>{{0, 3, 5}, {1, 4, 3}, {2, 5, 4}, {3, 4, 5}}));
    }
}

TEST(LoopStreaming, OpenFanTakesItsBoundaryNeighboursOnly) {
    // Centre 0 with triangles (0,1,2), (0,2,3), (0,3,4): a boundary vertex with 3 faces whose
    // boundary neighbours are 1 and 4; 2 and 3 are its interior neighbours, not summed.
    TriMesh m;
    m.positions = {Vec3(0, 0, 8), Vec3(8, 0, 0), Vec3(0, 8, 0), Vec3(-8, 0, 0), Vec3(0, -8, 0)};
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
    const auto& p = m.positions;
    const TriMesh e = loop_subdivide_streaming(m, kLoopEdge, 1);
    EXPECT_EQ(e.positions[0], 0.75 * p[0] + 0.125 * (p[1] + p[4]));
    EXPECT_EQ(e.positions[2], 0.75 * p[2] + 0.125 * (p[1] + p[3]));
    const TriMesh c = loop_subdivide_streaming(m, kLoopCorner, 1);
    EXPECT_EQ(c.positions[1], p[1]);
    EXPECT_EQ(c.positions[4], p[4]);
    // The interior edge (0, 2): 3/8 (p0 + p2) + 1/8 (p1 + p3), bit for bit as loop_subdivide.
    EXPECT_EQ(e.positions, loop_subdivide(m, kLoopEdge, 1).positions);
}

TEST(LoopStreaming, OctahedronByHandBothFamilies) {
    // Valence 4, each ring sums to zero: v' = (1 - 4 beta) v; Loop 33/64, Warren 5/8. The
    // edge (+x, +y) is edge 0 of triangle 0: 3/8 (x + y) + 1/8 (z - z).
    const TriMesh m = tri_octahedron();
    const struct { LoopOptions opt; double scale; } cases[] = {{kLoopEdge, 33.0 / 64.0}, {kWarrenEdge, 5.0 / 8.0}};
    for (const auto& c : cases) {
        const TriMesh r = loop_subdivide_streaming(m, c.opt, 1);
        ASSERT_EQ(r.num_vertices(), 18);
        for (int v = 0; v < 6; ++v) EXPECT_EQ(r.positions[v], c.scale * m.positions[v]);
        EXPECT_EQ(r.positions[6], Vec3(0.375, 0.375, 0.0));
    }
}

TEST(LoopStreaming, LevelsNumberedAsLoopSubdivideWithColors) {
    TriMesh m = tri_octahedron();
    for (const Vec3& p : m.positions) m.colors.push_back(0.5 * (p + Vec3::Ones()));
    for (int levels = 0; levels <= 3; ++levels) {
        const TriMesh a = loop_subdivide(m, kLoopEdge, levels), b = loop_subdivide_streaming(m, kLoopEdge, levels);
        EXPECT_EQ(a.triangles, b.triangles) << levels;
        ASSERT_EQ(a.positions.size(), b.positions.size());
        ASSERT_EQ(a.colors.size(), b.colors.size());
        // The ring is summed in another order: a few ulps of the unit coordinates.
        for (size_t v = 0; v < a.positions.size(); ++v) {
            EXPECT_LE((a.positions[v] - b.positions[v]).cwiseAbs().maxCoeff(), 8 * 0x1p-52) << v;
            EXPECT_LE((a.colors[v] - b.colors[v]).cwiseAbs().maxCoeff(), 8 * 0x1p-52) << v;
        }
    }
}

/// A bumpy grid of n x n squares cut into triangles along alternating diagonals (valences 4 to 8
/// inside, a boundary with corners), with a square hole in the middle: big enough that every
/// pass of the second level is split among threads.
TriMesh bumpy_grid_with_hole(int n) {
    TriMesh m;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            m.positions.emplace_back(i, j, std::sin(0.7 * i) * std::cos(1.3 * j));
            m.colors.emplace_back(i / double(n), j / double(n), 0.5);
        }
    const auto at = [&](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            if (std::abs(2 * i - n) < n / 4 && std::abs(2 * j - n) < n / 4) continue;  // the hole
            if ((i + j) % 2) {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    return m;
}

TEST(LoopStreaming, AnyNumberOfThreadsGivesTheBitsOfOne) {
    // The passes are split only from 8192 elements on: 2 x 40 x 40 triangles are 12,000 (less
    // the hole) after one level, 48,000 after two.
    const TriMesh grid = bumpy_grid_with_hole(40);
    for (const LoopOptions& o : {kLoopEdge, kLoopCorner, kWarrenEdge}) {
        const TriMesh one = loop_subdivide_streaming(grid, o, 3);
        ASSERT_GT(one.num_faces(), 100000);
        for (int threads : {2, 3, 8}) {
            const TriMesh many = loop_subdivide_streaming(grid, o, 3, threads);
            EXPECT_EQ(many.triangles, one.triangles) << threads;
            // Bit for bit, not within a tolerance: each point is the same sum in the same order.
            EXPECT_EQ(many.positions, one.positions) << threads;
            EXPECT_EQ(many.colors, one.colors) << threads;
        }
    }
    // And the order is loop_subdivide's but for the ring sums: a few ulps of the coordinates.
    const TriMesh a = loop_subdivide(grid, kLoopEdge, 2), b = loop_subdivide_streaming(grid, kLoopEdge, 2, 2);
    EXPECT_EQ(a.triangles, b.triangles);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (size_t v = 0; v < a.positions.size(); ++v)
        ASSERT_LE((a.positions[v] - b.positions[v]).cwiseAbs().maxCoeff(), 64 * 0x1p-52) << v;
    EXPECT_THROW(loop_subdivide_streaming(grid, kLoopEdge, 1, 0), InputError);
}

TEST(LoopStreaming, RefusesWhatLoopSubdivideRefuses) {
    TriMesh bowtie;
    bowtie.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)};
    bowtie.triangles = {{0, 1, 2}, {0, 3, 4}};
    EXPECT_THROW(loop_subdivide_streaming(bowtie, kLoopEdge, 1), InputError);
    TriMesh nan = tri_octahedron();
    nan.positions[3].x() = NAN;
    EXPECT_THROW(loop_subdivide_streaming(nan, kLoopEdge, 1), InputError);
    TriMesh big = tri_octahedron();
    for (Vec3& p : big.positions) p = 1e307 * p + Vec3(1.6e308, 0, 0);  // finite; any sum of two x overflows
    EXPECT_THROW(loop_subdivide_streaming(big, kLoopEdge, 1), InputError);
    EXPECT_THROW(loop_subdivide_streaming(tri_octahedron(), kLoopEdge, -1), InputError);
}

TEST(LoopStreaming, OnTwoThreadsABowtieInALargeMeshIsRefusedAndNamedAsOnOne) {
    // 9,600 half-edges and more: the fan check runs beside the building of the topology, which
    // on a vertex of two fans counts its ends short; the refusal is the same either way.
    TriMesh grid = bumpy_grid_with_hole(40);
    const int corner = grid.triangles.front()[0], n = grid.num_vertices();
    grid.positions.push_back(grid.positions[corner] + Vec3(-1, -1, 0));
    grid.positions.push_back(grid.positions[corner] + Vec3(-1, -2, 0));
    grid.triangles.push_back({corner, n + 1, n});  // touches the grid at one vertex only
    ASSERT_GE(3 * grid.num_faces(), 8192);
    std::string one, two;
    try {
        loop_subdivide_streaming(grid, kLoopEdge, 1);
    } catch (const InputError& e) {
        one = e.what();
    }
    try {
        loop_subdivide_streaming(grid, kLoopEdge, 1, 2);
    } catch (const InputError& e) {
        two = e.what();
    }
    EXPECT_NE(one, "");
    EXPECT_EQ(two, one);
}

}  // namespace
}  // namespace crossdiv
