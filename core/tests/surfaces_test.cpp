// Surfaces: Bezier patches, welding, the sweep mesher, revolution and generalized
// cylinders, on inputs small enough to compute by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <numeric>
#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/io/patch_io.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/surfaces/bezier_patch.h"
#include "crossdiv/surfaces/generalized_cylinder.h"
#include "crossdiv/surfaces/revolution.h"
#include "crossdiv/surfaces/sweep_surface.h"
#include "test_points.h"

using namespace crossdiv;

namespace {

using crossdiv::test::kEps;

/// A bicubic patch whose control points are the grid (c/3, r/3, z(r, c)).
BezierPatch grid_patch(double (*z)(int, int)) {
    BezierPatch p;
    p.rows = p.cols = 4;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) p.control.emplace_back(c / 3.0, r / 3.0, z(r, c));
    return p;
}

/// A polyline through `pts` with chord directions as tangents (the average at inner samples).
Polyline polyline(std::vector<Vec3> pts) {
    Polyline p;
    p.positions = pts;
    for (size_t i = 0; i < pts.size(); ++i) {
        const Vec3 a = pts[i > 0 ? i - 1 : i], b = pts[i + 1 < pts.size() ? i + 1 : i];
        p.tangents.push_back((b - a).normalized());
        p.normals.push_back(Vec3::Zero());
        p.params.push_back(static_cast<double>(i));
    }
    return p;
}

bool watertight_and_clean(const SurfaceMesh& s) {
    for (const MeshIssue& i : check_mesh(to_poly_mesh(s.mesh)))
        if (i.severity == Severity::Error) return false;
    return boundary_edge_count(s.mesh) == 0;
}

}  // namespace

TEST(BezierPatch, FlatGridIsTheParameterPlane) {
    const BezierPatch p = grid_patch([](int, int) { return 0.0; });
    const PatchJet j = patch_jet(p, 0.25, 0.75);
    // Linear precision: control points spaced evenly reproduce (u, v) exactly up to rounding.
    EXPECT_NEAR(j.position.x(), 0.25, 4 * kEps);
    EXPECT_NEAR(j.position.y(), 0.75, 4 * kEps);
    EXPECT_NEAR((j.du - Vec3(1, 0, 0)).norm(), 0, 16 * kEps);
    EXPECT_NEAR((j.dv - Vec3(0, 1, 0)).norm(), 0, 16 * kEps);
    EXPECT_NEAR(j.duv.norm(), 0, 16 * kEps);
    NormalSource src;
    EXPECT_EQ(patch_normal(p, 0.25, 0.75, &src), Vec3(0, 0, 1));
    EXPECT_EQ(src, NormalSource::Derivatives);
}

TEST(BezierPatch, AModelLargerThanDoubleCanMeasureIsRefusedNotWeldedIntoOneVertex) {
    // The flat grid stretched to +-1e308: every position is finite, but the bounding box's
    // diagonal (about 2.8e308) is not, and a weld tolerance derived from it would join every
    // vertex. Scaled to 1e307 it tessellates and welds as the unit grid does.
    BezierPatch p = grid_patch([](int, int) { return 0.0; });
    for (Vec3& c : p.control) c = (c - Vec3(0.5, 0.5, 0)) * 2.0 * 1e308;
    try {
        tessellate_patches(std::vector<BezierPatch>{p}, 4);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("larger than double can measure"), std::string::npos) << e.what();
    }
    for (Vec3& c : p.control) c *= 0.05;
    const SurfaceMesh s = tessellate_patches(std::vector<BezierPatch>{p}, 4);
    EXPECT_EQ(s.mesh.num_vertices(), 25);
    EXPECT_EQ(s.mesh.num_faces(), 32);
}

TEST(BezierPatch, BumpHeightIsTheProductOfBernsteinValues) {
    // z = 1 at control point (1, 1) only: z(u, v) = B_1(u) B_1(v), B_1(t) = 3 t (1 - t)^2.
    const BezierPatch p = grid_patch([](int r, int c) { return r == 1 && c == 1 ? 1.0 : 0.0; });
    EXPECT_NEAR(patch_point(p, 0.5, 0.5).z(), 0.375 * 0.375, 2 * kEps);             // 0.140625
    EXPECT_NEAR(patch_point(p, 0.25, 0.5).z(), 3 * 0.25 * 0.5625 * 0.375, 2 * kEps);  // 0.158203125
    // du of z at (0.5, 0.5): B_1'(0.5) B_1(0.5) = 3 (1 - 0.5)(1 - 1.5) * 0.375 = -0.28125.
    EXPECT_NEAR(patch_jet(p, 0.5, 0.5).du.z(), -0.28125, 4 * kEps);
    for (double u : {0.0, 0.1, 0.5, 0.9, 1.0})
        for (double v : {0.0, 0.3, 1.0}) EXPECT_NEAR((patch_point(p, u, v) - patch_bernstein_point(p, u, v)).norm(), 0, 4 * kEps);
}

TEST(BezierPatch, CollapsedRowTakesTheLimitNormal) {
    // Row 0 collapsed to the origin: P(u, v) = v (1, u, 0), du = (0, v, 0) vanishes at v = 0;
    // du x dv = (0, 0, -v), so the normal is -z everywhere, at v = 0 as a limit.
    BezierPatch p;
    p.rows = p.cols = 4;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) p.control.push_back(r / 3.0 * Vec3(1, c / 3.0, 0));
    NormalSource src;
    EXPECT_NEAR((patch_normal(p, 0.5, 0.5, &src) - Vec3(0, 0, -1)).norm(), 0, 4 * kEps);
    EXPECT_EQ(src, NormalSource::Derivatives);
    EXPECT_NEAR((patch_normal(p, 0.3, 0.0, &src) - Vec3(0, 0, -1)).norm(), 0, 4 * kEps);
    EXPECT_EQ(src, NormalSource::Limit);
}

TEST(BezierPatch, NeighbouringPatchesWeldIntoOneMesh) {
    const BezierPatch a = grid_patch([](int, int) { return 0.0; });
    BezierPatch b = a;
    for (Vec3& c : b.control) c.x() += 1;  // [1, 2] x [0, 1], sharing the edge x = 1
    const std::vector<BezierPatch> both{a, b};
    const SurfaceMesh s = tessellate_patches(both, 2);
    EXPECT_EQ(s.mesh.num_vertices(), 15);  // 5 columns x 3 rows: the shared column once
    EXPECT_EQ(s.mesh.num_faces(), 16);
    EXPECT_EQ(boundary_edge_count(s.mesh), 12);  // the 2 x 1 rectangle's perimeter, 4 + 2 + 4 + 2
    int shared = 0;
    EXPECT_EQ(max_boundary_gap(both, 8, &shared), 0.0);
    EXPECT_EQ(shared, 1);
    for (const Vec3& n : s.normals) EXPECT_EQ(n, Vec3(0, 0, 1));
    EXPECT_THROW(tessellate_patches(both, 0), InputError);
}

TEST(BezierPatch, BezReaderReadsRowsAndNamesTheLine) {
    std::ostringstream text;
    text << "1\n";
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) text << c << ' ' << r << " 0   ";
        text << '\n';
    }
    std::istringstream in(text.str());
    const std::vector<BezierPatch> p = read_bez(in, "one.bez");
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].at(2, 3), Vec3(3, 2, 0));
    EXPECT_EQ(p[0].line, 2);
    std::istringstream short_in("1\n0 0 0 1 0 0\n");
    try {
        read_bez(short_in, "short.bez");
        FAIL() << "a patch of 2 points was read";
    } catch (const ParseError& e) {
        EXPECT_EQ(std::string(e.what()), "short.bez:2: unexpected end of file: expected x of point 3 (row 1) of patch 1 of 1");
    }
    std::istringstream nan_in("1\n0 0 nan\n");
    EXPECT_THROW(read_bez(nan_in, "nan.bez"), ParseError);
}

TEST(Weld, JoinsPointsWithinTheToleranceTransitively) {
    const std::vector<Vec3> pts{{0, 0, 0}, {1e-12, 0, 0}, {1, 0, 0}, {2e-12, 0, 0}, {1, 5e-10, 0}};
    EXPECT_EQ(weld_classes(pts, 1e-9), (std::vector<int>{0, 0, 2, 0, 2}));
    EXPECT_EQ(weld_classes(pts, 0), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(Weld, ClassesAreTheConnectedComponentsOfTheWithinTolGraph) {
    // Against the definition, all pairs compared: 1500 points in clusters on a lattice of
    // spacing 1 (points jittered by up to 0.3 per axis), welded at tol 0.5, so some clusters
    // chain together and some do not; plus a dense clump of 500 points within 1e-3 (one cell).
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> site(0, 9);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3), tiny(0.0, 1e-3);
    std::vector<Vec3> p;
    for (int i = 0; i < 1500; ++i) p.emplace_back(site(rng) + jitter(rng), site(rng) + jitter(rng), jitter(rng));
    for (int i = 0; i < 500; ++i) p.emplace_back(20 + tiny(rng), tiny(rng), tiny(rng));
    const double tol = 0.5;
    std::vector<int> expect(p.size());
    std::iota(expect.begin(), expect.end(), 0);
    const auto root = [&](int i) {
        while (expect[i] != i) i = expect[i];
        return i;
    };
    for (size_t i = 0; i < p.size(); ++i)
        for (size_t j = i + 1; j < p.size(); ++j)
            if ((p[i] - p[j]).norm() <= tol) {
                const int a = root(static_cast<int>(i)), b = root(static_cast<int>(j));
                if (a != b) expect[std::max(a, b)] = std::min(a, b);
            }
    for (size_t i = 0; i < p.size(); ++i) expect[i] = root(static_cast<int>(i));
    EXPECT_EQ(weld_classes(p, tol), expect);
    EXPECT_EQ(weld_classes(p, tol)[1999], 1500);  // the clump is one class, led by its first point
}

TEST(Weld, VolumeOfTheUnitTetrahedron) {
    TriMesh t;
    t.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    t.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};  // counterclockwise from outside
    EXPECT_NEAR(signed_volume(t), 1.0 / 6, kEps);
    EXPECT_EQ(boundary_edge_count(t), 0);
    t.triangles.pop_back();
    EXPECT_EQ(boundary_edge_count(t), 3);
}

TEST(Revolution, CappedCylinderHasPolesAndASharedSeam) {
    // Profile (0,1) -> (-1,1) -> (-1,-1) -> (0,-1): both ends on the axis, counterclockwise
    // with the axis (area +2), so the right of travel is outward. Four slices make a square
    // prism of half-diagonal 1: 2 poles + 2 rings of 4 vertices, 4 + 8 + 4 triangles, volume
    // (side sqrt 2)^2 * height 2 = 4.
    const Polyline p = polyline({{0, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {0, -1, 0}});
    RevolutionOptions o;
    o.slices = 4;
    const SurfaceMesh s = revolve(p, false, o);
    EXPECT_EQ(s.mesh.num_vertices(), 10);
    EXPECT_EQ(s.mesh.num_faces(), 16);
    EXPECT_EQ(s.collapsed_triangles, 8);
    EXPECT_TRUE(watertight_and_clean(s));
    EXPECT_NEAR(signed_volume(s.mesh), 4.0, 8 * kEps);
    // Slice 1 turns (-1, 1) by 90 degrees counterclockwise about +y: to (0, 1, 1).
    const SweepGrid g = revolution_grid(p, false, o);
    EXPECT_NEAR((g.at(1, 1) - Vec3(0, 1, 1)).norm(), 0, 2 * kEps);
    // The top edge runs along -x: its outward normal is +y, in every slice.
    EXPECT_NEAR((g.normals[1 * 4 + 0] - Vec3(0, 1, 0)).norm(), 0, 2 * kEps);
}

TEST(Revolution, ReversedProfileStillFacesOutward) {
    const Polyline p = polyline({{0, -1, 0}, {-1, -1, 0}, {-1, 1, 0}, {0, 1, 0}});  // clockwise: area -2
    RevolutionOptions o;
    o.slices = 6;
    const SurfaceMesh s = revolve(p, false, o);
    EXPECT_TRUE(watertight_and_clean(s));
    EXPECT_GT(signed_volume(s.mesh), 0);
}

TEST(Revolution, OpenProfileFollowsTheCourseConvention) {
    // A downward segment at x = -1 (encloses nothing): right of travel, (-1, 0), outward.
    const Polyline p = polyline({{-1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}});
    RevolutionOptions o;
    o.slices = 8;
    const SweepGrid g = revolution_grid(p, false, o);
    EXPECT_EQ(g.normals[1], Vec3(-1, 0, 0));
    const SurfaceMesh s = revolve(p, false, o);
    EXPECT_EQ(s.mesh.num_vertices(), 24);
    EXPECT_EQ(boundary_edge_count(s.mesh), 16);  // two rims of 8
}

TEST(Revolution, RefusesAProfileAcrossTheAxis) {
    const Polyline p = polyline({{-1, 1, 0}, {1, -1, 0}});
    RevolutionOptions o;
    o.slices = 8;
    try {
        revolve(p, false, o);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("crosses the axis"), std::string::npos) << e.what();
    }
    o.slices = 2;
    EXPECT_THROW(revolve(polyline({{-1, 1, 0}, {-1, -1, 0}}), false, o), InputError);
}

TEST(Revolution, Cs4620SlicesByMaximumAngleAboutZ) {
    RevolutionOptions o;
    o.convention = RevolutionConvention::CS4620;
    o.max_angle = std::numbers::pi / 5.5;  // 11 slices: the fewest with angle <= max
    o.scale = 2;
    EXPECT_EQ(revolution_slices(o), 11);
    const SweepGrid g = revolution_grid(polyline({{1, 1, 0}, {1, -1, 0}}), false, o);
    EXPECT_EQ(g.at(0, 0), Vec3(2, 0, 2));  // (x, y) -> scale (x, 0, y) at angle 0
}

TEST(GeneralizedCylinder, TorusIsWatertightAndOutward) {
    const CurveFile f = [] {
        std::istringstream in("circ profile 24 0.5\ncirc sweep 48 2\ngcyl torus profile sweep\n");
        return read_swp(in, "torus.swp");
    }();
    for (FrameMethod m : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        SweepOptions o;
        o.frames = m;
        const SweepSurface s = build_sweep(f, 0, o);
        EXPECT_TRUE(s.closed);
        EXPECT_EQ(s.surface.mesh.num_vertices(), 24 * 48);
        EXPECT_EQ(s.surface.mesh.num_faces(), 2 * 24 * 48);
        EXPECT_TRUE(watertight_and_clean(s.surface));
        // A polygonal torus inscribed in the exact one (2 pi^2 R r^2 = 9.8696): a little less.
        const double exact = 2 * std::numbers::pi * std::numbers::pi * 2 * 0.25;
        EXPECT_GT(signed_volume(s.surface.mesh), 0.98 * exact);
        EXPECT_LT(signed_volume(s.surface.mesh), exact);
    }
}

TEST(GeneralizedCylinder, ScaleCurveSizesTheProfile) {
    // Straight sweep along x from 0 to 3 (a B-spline with equal steps is the line); scale
    // curve y = 1 + x on the normalized parameter: the ring at the sweep's end is twice
    // as wide as at its start.
    std::istringstream in(
        "circ profile 16 1\n"
        "bez3 sweep 3 4 [0 0 0] [1 0 0] [2 0 0] [3 0 0]\n"
        "bez2 size 3 4 [0 1] [1 1.3333333333333333] [2 1.6666666666666667] [3 2]\n"
        "gcyl tube profile sweep size\n");
    const CurveFile f = read_swp(in, "tube.swp");
    ASSERT_EQ(f.sweeps[0].scale, "size");
    const SweepSurface s = build_sweep(f, 0, {});
    const SweepGrid& g = s.grid;
    auto radius = [&](int i) { return Vec3(0, g.at(i, 0).y(), g.at(i, 0).z()).norm(); };
    EXPECT_NEAR(radius(0), 1.0, 1e-15);
    EXPECT_NEAR(radius(g.rings - 1), 2.0, 1e-15);
    EXPECT_FALSE(s.closed);
    // The cone r = 1 + x / 3: its outward normal leans back along -x by 1 / sqrt(1 + 9)
    // (central differences of a linear scale are exact up to rounding).
    for (int i = 1; i + 1 < g.rings; ++i) EXPECT_NEAR(g.normals[i * g.ring_size].x(), -1 / std::sqrt(10.0), 1e-12) << "ring " << i;
}

TEST(Sweep, ASurfaceBeyondTheFaceLimitIsRefusedBeforeItIsBuilt) {
    // 300 x 300 steps: 2 x 300 x 300 = 180,000 triangles (profile and sweep closed, 301
    // samples each). Refused under a limit of 179,999, built under 180,000.
    std::istringstream in("circ profile 300 0.5\ncirc sweep 300 2\n\ngcyl tube profile sweep\n");
    const CurveFile f = read_swp(in, "tube.swp");
    SweepOptions o;
    o.max_triangles = 179'999;
    try {
        build_sweep(f, 0, o);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("would have 180000 triangles, more than the limit of 179999"),
                  std::string::npos)
            << e.what();
    }
    o.max_triangles = 180'000;
    EXPECT_EQ(build_sweep(f, 0, o).surface.mesh.num_faces(), 180'000);
    // Patches: 2 res^2 triangles each, counted before any is evaluated.
    const std::vector<BezierPatch> one{grid_patch([](int, int) { return 0.0; })};
    EXPECT_THROW(tessellate_patches(one, 8, 127), InputError);
    EXPECT_EQ(tessellate_patches(one, 8, 128).mesh.num_faces(), 128);
}

TEST(GeneralizedCylinder, NegativeScaleIsRefusedWithTheRecordLine) {
    std::istringstream in(
        "circ profile 8 1\nbez3 sweep 3 4 [0 0 0] [1 0 0] [2 0 0] [3 0 0]\nbez2 size 3 4 [0 1] [1 0] [2 -1] [3 -2]\n\n"
        "gcyl tube profile sweep size\n");
    const CurveFile f = read_swp(in, "neg.swp");
    try {
        build_sweep(f, 0, {});
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 5);
        EXPECT_NE(std::string(e.what()).find("scales must be positive"), std::string::npos) << e.what();
    }
}
