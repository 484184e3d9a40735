// Marching cubes with the asymptotic decider: hand values on one cube (a corner, an ambiguous
// face both ways), watertightness against the minority rule on a field whose every face is
// ambiguous, a sphere's topology, orientation and volume, and the refusals.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <numbers>

#include "crossdiv/error.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/surfaces/surface_mesh.h"
#include "crossdiv/volume/marching_cubes.h"

using namespace crossdiv;

namespace {

/// One cube, corner c (i + 2 j + 4 k) holding values[c].
ScalarGrid cube(const std::array<double, 8>& values) {
    ScalarGrid g;
    g.size = {2, 2, 2};
    g.values.assign(values.begin(), values.end());
    return g;
}

struct EdgeCounts {
    int edges = 0, boundary = 0, over_two = 0;
};
EdgeCounts edge_counts(const TriMesh& m) {
    std::map<std::pair<int, int>, int> uses;
    for (const Triangle& t : m.triangles)
        for (int j = 0; j < 3; ++j) ++uses[std::minmax(t[j], t[(j + 1) % 3])];
    EdgeCounts c;
    for (const auto& [e, n] : uses) ++c.edges, c.boundary += n == 1, c.over_two += n > 2;
    return c;
}

bool has_errors(const TriMesh& m) {
    PolyMesh p;
    p.positions = m.positions;
    for (const Triangle& t : m.triangles) p.add_face(t);
    for (const MeshIssue& i : check_mesh(p))
        if (i.severity == Severity::Error) return true;
    return false;
}

}  // namespace

TEST(MarchingCubes, OneInsideCornerMakesOneTriangleAtTheLinearCrossings) {
    // Corner 0 at -1; its neighbours along x, y, z at 1, 3, 0.5: the crossings are at
    // t = 1/2, 1/4, 2/3 along those edges.
    const Isosurface s = marching_cubes(cube({-1, 1, 3, 1, 0.5, 1, 1, 1}), {});
    ASSERT_EQ(s.mesh.num_vertices(), 3);
    ASSERT_EQ(s.mesh.num_faces(), 1);
    EXPECT_EQ(s.mesh.positions[0], Vec3(0.5, 0, 0));  // x edge first, then y, then z
    EXPECT_EQ(s.mesh.positions[1], Vec3(0, 0.25, 0));
    EXPECT_EQ(s.mesh.positions[2], Vec3(0, 0, 2.0 / 3));
    EXPECT_EQ(s.vertex_edge, (std::vector<int64_t>{0, 8, 16}));  // axis * 8 + sample 0
    // The triangle faces away from the inside corner at the origin.
    const Triangle& t = s.mesh.triangles[0];
    const Vec3 n = (s.mesh.positions[t[1]] - s.mesh.positions[t[0]]).cross(s.mesh.positions[t[2]] - s.mesh.positions[t[0]]);
    EXPECT_GT(n.x(), 0);
    EXPECT_GT(n.y(), 0);
    EXPECT_GT(n.z(), 0);
    EXPECT_EQ(s.ambiguous_faces, 0);
}

TEST(MarchingCubes, InsideAboveReversesTheTriangles) {
    const std::array<double, 8> values{-1, 1, 3, 1, 0.5, 1, 1, 1};
    const Isosurface below = marching_cubes(cube(values), {});
    // The same values with the solid above the level: the same crossings, the solid is now
    // the seven other corners, and the triangle faces the other way.
    const Isosurface above = marching_cubes(cube(values), {0, InsideIs::Above});
    ASSERT_EQ(above.mesh.positions, below.mesh.positions);
    ASSERT_EQ(above.mesh.num_faces(), 1);
    const Triangle &a = above.mesh.triangles[0], &b = below.mesh.triangles[0];
    EXPECT_EQ(std::set<int>(a.begin(), a.end()), std::set<int>(b.begin(), b.end()));
    EXPECT_LT(signed_volume(above.mesh) * signed_volume(below.mesh), 0);
}

TEST(MarchingCubes, DeciderJoinsAnAmbiguousFaceWhenTheSaddleIsInside) {
    // Corners 0 and 3 (diagonal on the face z = 0) at -1, corners 1 and 2 at a, the top at 1.
    // The saddle is inside iff (-1)(-1) > a a.
    for (const auto& [a, joined] : {std::pair{0.5, true}, std::pair{2.0, false}}) {
        const Isosurface s = marching_cubes(cube({-1, a, a, -1, 1, 1, 1, 1}), {});
        EXPECT_EQ(s.mesh.num_vertices(), 6);
        EXPECT_EQ(s.ambiguous_faces, 1);
        EXPECT_EQ(s.joined_faces, joined ? 1 : 0);
        // Joined: one hexagon round both corners (a fan: 4 triangles); separated: a triangle each.
        EXPECT_EQ(s.mesh.num_faces(), joined ? 4 : 2) << "a = " << a;
        EXPECT_EQ(s.centred_polygons, 0);
        EXPECT_EQ(edge_counts(s.mesh).over_two, 0);
    }
    // The minority rule separates the two inside corners whatever the values.
    const Isosurface m = marching_cubes(cube({-1, 0.5, 0.5, -1, 1, 1, 1, 1}), {0, InsideIs::Below, AmbiguousFaceRule::SeparateMinority});
    EXPECT_EQ(m.mesh.num_faces(), 2);
    EXPECT_EQ(m.joined_faces, 0);
}

TEST(MarchingCubes, DeciderIsWatertightWhereTheMinorityRuleLeavesHoles) {
    // Pseudo-random values inside an outside shell: many ambiguous faces, between cubes with
    // a minority of inside corners and cubes with a majority.
    ScalarGrid g;
    g.size = {9, 9, 9};
    g.values.resize(g.num_samples());
    uint32_t state = 12345;
    for (int k = 0; k < 9; ++k)
        for (int j = 0; j < 9; ++j)
            for (int i = 0; i < 9; ++i) {
                state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG: a fixed field
                const bool shell = i == 0 || j == 0 || k == 0 || i == 8 || j == 8 || k == 8;
                g.values[g.index(i, j, k)] = shell ? 1.0 : (state >> 8) / double(1 << 24) * 2 - 1;
            }
    const Isosurface decider = marching_cubes(g, {});
    EXPECT_GT(decider.ambiguous_faces, 0);
    EXPECT_GT(decider.joined_faces, 0);
    EXPECT_LT(decider.joined_faces, decider.ambiguous_faces);
    const EdgeCounts d = edge_counts(decider.mesh);
    EXPECT_EQ(d.boundary, 0);
    EXPECT_EQ(d.over_two, 0);
    EXPECT_FALSE(has_errors(decider.mesh));

    const Isosurface minority = marching_cubes(g, {0, InsideIs::Below, AmbiguousFaceRule::SeparateMinority});
    EXPECT_GT(edge_counts(minority.mesh).boundary, 0);
}

TEST(MarchingCubes, SphereIsClosedOutwardAndEnclosesItsVolume) {
    constexpr double kPi = std::numbers::pi;
    const Vec3 centre(0.0123, -0.0234, 0.0345);  // off the grid's symmetry: no sample on the sphere
    const ScalarGrid g = sample_grid([&](const Vec3& p) { return (p - centre).norm() - 1.0; }, Vec3(-1.3, -1.3, -1.3),
                                     Vec3(1.3, 1.3, 1.3), {27, 27, 27});
    const Isosurface s = marching_cubes(g, {});
    const EdgeCounts e = edge_counts(s.mesh);
    EXPECT_EQ(e.boundary, 0);
    EXPECT_EQ(s.mesh.num_vertices() - e.edges + s.mesh.num_faces(), 2);
    EXPECT_FALSE(has_errors(s.mesh));
    const double h = 0.1;
    for (const Vec3& p : s.mesh.positions) EXPECT_LT(std::abs((p - centre).norm() - 1.0), h * h);
    // Linear interpolation of a distance function cuts the sphere's chords: the volume is a
    // little short, by O(h^2).
    const double v = signed_volume(s.mesh), exact = 4 * kPi / 3;
    EXPECT_GT(v, 0);
    EXPECT_LT(std::abs(v - exact) / exact, h * h);
}

TEST(MarchingCubes, RefusesALevelThatOverflowsAndNamesTheRules) {
    EXPECT_THROW(marching_cubes(cube({-1, 1, 1, 1, 1, 1, 1, 1}), {std::numeric_limits<double>::quiet_NaN()}), InputError);
    try {
        marching_cubes(cube({-1, 1, 1, 1, 1, 1, 1, -1.7e308}), {1.7e308});
        FAIL() << "an overflowing value minus level was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("sample (1, 1, 1)"), std::string::npos) << e.what();
    }
    EXPECT_EQ(ambiguous_face_rule_from_string("decider"), AmbiguousFaceRule::AsymptoticDecider);
    EXPECT_EQ(ambiguous_face_rule_from_string(to_string(AmbiguousFaceRule::SeparateMinority)), AmbiguousFaceRule::SeparateMinority);
    EXPECT_THROW(ambiguous_face_rule_from_string("mc33"), InputError);
}

TEST(ScalarGrid, SamplingChecksTheFunctionAndTheBox) {
    const ScalarGrid g = sample_grid([](const Vec3& p) { return p.x() + 10 * p.y() + 100 * p.z(); }, Vec3(0, 0, 0), Vec3(1, 2, 4), {2, 3, 5});
    EXPECT_EQ(g.spacing, Vec3(1, 1, 1));
    EXPECT_EQ(g.at(1, 2, 4), 1 + 20 + 400);
    try {
        sample_grid([](const Vec3& p) { return p.x() > 0.5 ? std::nan("") : 0.0; }, Vec3(0, 0, 0), Vec3(1, 1, 1), {2, 2, 2});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("sample (1, 0, 0) is not finite"), std::string::npos) << e.what();
    }
    EXPECT_THROW(sample_grid([](const Vec3&) { return 0.0; }, Vec3(0, 0, 0), Vec3(1, 1, 1), {1, 2, 2}), InputError);
    EXPECT_THROW(sample_grid([](const Vec3&) { return 0.0; }, Vec3(1, 0, 0), Vec3(0, 1, 1), {2, 2, 2}), InputError);
    EXPECT_THROW(sample_grid([](const Vec3&) { return 0.0; }, Vec3(0, 0, 0), Vec3(1, 1, 1), {1 << 10, 1 << 10, 1 << 10}), InputError);
}
