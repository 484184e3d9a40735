// Generalized cylinders along sweeps with corners: the corner rotation and mitre by hand, the
// square frame (a square profile around a square path) whose volume is exact, the wall
// thickness kept at every corner, and the frames turned by each corner without twist.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/surfaces/surface_mesh.h"
#include "crossdiv/surfaces/sweep_corners.h"
#include "crossdiv/surfaces/sweep_surface.h"
#include "test_points.h"

using namespace crossdiv;

namespace {

using crossdiv::test::kEps;

CurveFile corners_swp(const std::string& text) {
    std::istringstream in(text);
    return read_swp(in, "corners.swp");
}

// A square of side `side` centred on the origin in the xy-plane as a closed bez2 chain of
// straight pieces (control points at thirds of each side).
std::string square_profile(const std::string& name, double side) {
    const double h = side / 2;
    const double corner[5][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}};
    std::ostringstream s;
    s << "bez2 " << name << " 1 13";
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i < 3; ++i) {
            const double t = i / 3.0;
            s << " [" << corner[k][0] + t * (corner[k + 1][0] - corner[k][0]) << " "
              << corner[k][1] + t * (corner[k + 1][1] - corner[k][1]) << "]";
        }
    s << " [" << -h << " " << -h << "]\n";
    return s.str();
}

}  // namespace

TEST(SweepCorners, RotationAndMitreByHand) {
    const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    // A right-angle turn from +x to +y is the quarter turn about +z.
    const Eigen::Matrix3d r = corner_rotation(x, y);
    EXPECT_LE((r * x - y).norm(), kEps);
    EXPECT_LE((r * z - z).norm(), kEps);
    EXPECT_LE((r * y + x).norm(), kEps);
    EXPECT_EQ(corner_rotation(x, x), Eigen::Matrix3d::Identity());
    // Mitre of the right-angle turn: the plane through the corner with normal (1,1,0)/sqrt 2,
    // x + y = 0. Offset +y (inside the turn) meets it along the arriving direction at (-1, 1, 0),
    // offset -y (outside) at (1, -1, 0): each is sqrt 2 from the corner, 1 from either axis.
    EXPECT_LE((mitre_offset(y, x, y) - Vec3(-1, 1, 0)).norm(), 2 * kEps);
    EXPECT_LE((mitre_offset(-y, x, y) - Vec3(1, -1, 0)).norm(), 2 * kEps);
    // Offsets along the turn's axis stay where they are.
    EXPECT_LE((mitre_offset(z, x, y) - z).norm(), kEps);
}

// A square profile of side a around a square path of side L: the square frame, whose volume is
// (L + a)^2 a - (L - a)^2 a = 4 L a^2, and which is watertight and outward.
TEST(SweepCorners, SquareFrameHasTheExactVolume) {
    const double side = 4, a = 1;
    const std::string path = "bez3 path 1 13 [0 0 0] [1.3333333333333333 0 0] [2.6666666666666665 0 0] [4 0 0] "
                             "[4 1.3333333333333333 0] [4 2.6666666666666665 0] [4 4 0] [2.6666666666666665 4 0] "
                             "[1.3333333333333333 4 0] [0 4 0] [0 2.6666666666666665 0] [0 1.3333333333333333 0] [0 0 0]\n";
    for (FrameMethod m : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        const CurveFile f = corners_swp(square_profile("box", a) + path + "gcyl frame box path\n");
        SweepOptions o;
        o.frames = m;
        const SweepSurface s = build_sweep(f, 0, o);
        ASSERT_EQ(s.corners.size(), 4u);
        EXPECT_EQ(s.corners[0].sample, 0);  // the seam is a corner too
        EXPECT_TRUE(s.closed);
        EXPECT_NEAR(std::abs(s.closure_angle), 0.0, 1e-15);  // four quarter turns about z close
        EXPECT_NEAR(signed_volume(s.surface.mesh), 4 * side * a * a, 64 * kEps * 16) << to_string(m);
        EXPECT_EQ(boundary_edge_count(s.surface.mesh), 0) << to_string(m);
        EXPECT_TRUE(check_mesh(to_poly_mesh(s.surface.mesh)).empty()) << to_string(m);
        // 4 rings (one per corner: the straight pieces add no samples) of 4 profile points.
        EXPECT_EQ(s.surface.mesh.num_vertices(), 16);
    }
}

// Wall thickness at each corner: every ring point lies at its profile distance from the
// arriving tube's axis line and from the leaving one's.
TEST(SweepCorners, KeepTheWallThicknessAtEveryCorner) {
    const CurveFile f = corners_swp("crc2 round 8 6 [0.3 0] [0.15 0.26] [-0.15 0.26] [-0.3 0] [-0.15 -0.26] [0.15 -0.26]\n"
                            "bez3 path 6 10 [0 0 0] [1 0 0] [2 0 0] [3 0 0] [3.5 1 0.2] [4 2 0.5] [4 3 1] "
                            "[3 3.5 2] [2 4 2.5] [1 4 3]\n"
                            "gcyl tube round path\n");
    for (FrameMethod m : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        SweepOptions o;
        o.frames = m;
        const SweepSurface s = build_sweep(f, 0, o);
        ASSERT_EQ(s.corners.size(), 2u) << "joints at (3,0,0) and (4,3,1) are corners";
        const Polyline profile = tessellate_record(f.curves[0], {});
        const Polyline sweep = tessellate_record(f.curves[1], {});
        double worst = 0;
        for (const SweepCorner& c : s.corners) {
            const Vec3& v = sweep.positions[c.sample];
            for (int j = 0; j + 1 < profile.size(); ++j) {
                const double r = profile.positions[j].head<2>().norm();
                const Vec3 p = s.grid.at(c.sample, j) - v;
                for (const Vec3& axis : {c.in, c.out})
                    worst = std::max(worst, std::abs((p - p.dot(axis) * axis).norm() - r));
            }
        }
        EXPECT_LE(worst, 1e-14) << to_string(m);
    }
}

TEST(SweepCorners, RefuseATurnBackOnItself) {
    const CurveFile f = corners_swp("circ ring 8 0.2\nbez3 path 2 7 [0 0 0] [1 0 0] [2 0 0] [3 0 0] [2 0.01 0] [1 0.01 0] [0 0.01 0]\n"
                            "gcyl tube ring path\n");
    try {
        build_sweep(f, 0, {});
        ADD_FAILURE();
    } catch (const ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("corners.swp:3: tube: the sweep turns by 179."), std::string::npos) << e.what();
    }
}
