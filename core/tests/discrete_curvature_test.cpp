// Discrete curvature (Meyer et al. 2002): hand values on the octahedron, an obtuse triangle
// and a flat fan, Gauss-Bonnet on closed and open meshes, convergence and principal
// directions on a torus against the analytic values.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "crossdiv/error.h"
#include "crossdiv/mesh/discrete_curvature.h"
#include "test_points.h"

using namespace crossdiv;

namespace {

using crossdiv::test::kEps;
constexpr double kPi = std::numbers::pi;

TriMesh octahedron() {
    TriMesh m;
    m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

/// Torus (R + r cos v) (cos u, sin u) + r sin v z, nu x nv quads split in two, outward.
TriMesh torus(int nu, int nv, double R, double r) {
    TriMesh m;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
            m.positions.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                     r * std::sin(v));
        }
    auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

/// A flat hexagonal fan around vertex 0 at the origin, ring vertices wobbled in the plane.
TriMesh flat_fan() {
    TriMesh m;
    m.positions.push_back(Vec3(0, 0, 0));
    for (int k = 0; k < 6; ++k) {
        const double a = 2 * kPi * k / 6 + 0.1 * std::sin(3.0 * k);
        m.positions.push_back((1.0 + 0.2 * std::cos(5.0 * k)) * Vec3(std::cos(a), std::sin(a), 0));
    }
    for (int k = 0; k < 6; ++k) m.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
    return m;
}

}  // namespace

// The octahedron with vertices +-e_i: 4 equilateral faces (edge sqrt 2, area sqrt 3 / 2) at
// each vertex, so the angle defect is 2 pi - 4 pi / 3 = 2 pi / 3 and the mixed (Voronoi)
// area a third of the four faces, 2 sqrt 3 / 3. Every cotangent is 1 / sqrt 3 and the four
// edges x_i - x_j sum to 4 x_i, so |2 H n| = (1 / (2 A)) (2 / sqrt 3) 4 = 2: H = 1, as on the
// unit sphere the vertices lie on. K = (2 pi / 3) / A = pi / sqrt 3 > H^2: k1 = k2 = H.
TEST(DiscreteCurvature, OctahedronHandValues) {
    const DiscreteCurvature c = discrete_curvature(octahedron());
    ASSERT_EQ(c.num_estimated(), 6);
    for (int v = 0; v < 6; ++v) {
        EXPECT_NEAR(c.angle_defect[v], 2 * kPi / 3, 8 * kEps) << v;
        EXPECT_NEAR(c.mixed_area[v], 2 * std::sqrt(3.0) / 3, 8 * kEps) << v;
        EXPECT_NEAR(c.mean[v], 1.0, 8 * kEps) << v;
        EXPECT_NEAR(c.gaussian[v], kPi / std::sqrt(3.0), 16 * kEps) << v;
        EXPECT_NEAR(c.k1[v], 1.0, 8 * kEps) << v;
        EXPECT_NEAR(c.k2[v], 1.0, 8 * kEps) << v;
        EXPECT_NEAR(c.normal[v].norm(), 1.0, 4 * kEps);
    }
    EXPECT_EQ(c.euler_characteristic, 2);
    EXPECT_NEAR(c.total_angle_defect(), 4 * kPi, 32 * kEps);
}

// A triangle with an obtuse corner at vertex 2: half its area goes there, a quarter to each
// other corner (Meyer et al., fig. 4). Every vertex is on the boundary: not estimated; the
// turning angles pi - angle sum to 3 pi - pi = 2 pi chi with chi = 1.
TEST(DiscreteCurvature, ObtuseTriangleMixedAreaAndBoundary) {
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0.2, 0)};
    m.triangles = {{0, 1, 2}};
    const DiscreteCurvature c = discrete_curvature(m);
    EXPECT_NEAR(c.mixed_area[0], 0.05, 4 * kEps);
    EXPECT_NEAR(c.mixed_area[1], 0.05, 4 * kEps);
    EXPECT_NEAR(c.mixed_area[2], 0.1, 4 * kEps);
    for (int v = 0; v < 3; ++v) {
        EXPECT_EQ(c.status[v], CurvatureStatus::Boundary);
        EXPECT_EQ(c.mean[v], 0.0);
        EXPECT_EQ(c.gaussian[v], 0.0);
    }
    EXPECT_EQ(c.euler_characteristic, 1);
    EXPECT_NEAR(c.total_angle_defect(), 2 * kPi, 8 * kEps);
}

// A right triangle is not obtuse: Voronoi areas, where the right-angle corner's cotangent is
// 0. Legs 1 and 1: the corner at the right angle gets (1 * 1 + 1 * 1) / 8 = 1/4, each other
// corner (1 * 1 + 0 * 2) / 8 = 1/8; together the area 1/2.
TEST(DiscreteCurvature, RightTriangleVoronoiAreas) {
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    m.triangles = {{0, 1, 2}};
    const DiscreteCurvature c = discrete_curvature(m);
    EXPECT_NEAR(c.mixed_area[0], 0.25, 4 * kEps);
    EXPECT_NEAR(c.mixed_area[1], 0.125, 4 * kEps);
    EXPECT_NEAR(c.mixed_area[2], 0.125, 4 * kEps);
}

// A flat fan: the interior vertex has no curvature (angles sum to 2 pi, the cotangent
// Laplacian of a plane is 0), whatever the ring's shape.
TEST(DiscreteCurvature, FlatFanHasNone) {
    const DiscreteCurvature c = discrete_curvature(flat_fan());
    ASSERT_EQ(c.status[0], CurvatureStatus::Estimated);
    EXPECT_NEAR(c.angle_defect[0], 0.0, 16 * kEps);
    EXPECT_NEAR(c.mean[0], 0.0, 64 * kEps);
    for (int v = 1; v < 7; ++v) EXPECT_EQ(c.status[v], CurvatureStatus::Boundary);
    EXPECT_NEAR(c.total_angle_defect(), 2 * kPi, 32 * kEps);  // a disc
    TriMesh with_isolated = flat_fan();  // a vertex in no triangle: not counted in chi
    with_isolated.positions.push_back(Vec3(5, 5, 5));
    const DiscreteCurvature d = discrete_curvature(with_isolated);
    EXPECT_EQ(d.status[7], CurvatureStatus::Isolated);
    EXPECT_EQ(d.euler_characteristic, 1);
    EXPECT_EQ(d.angle_defect[7], 0.0);
}

// Gauss-Bonnet on the torus: chi = 0, so the angle defects cancel to rounding (each defect
// is about 2 pi minus six angles, each rounded to an ulp of pi).
TEST(DiscreteCurvature, GaussBonnetOnTheTorus) {
    const TriMesh m = torus(24, 12, 1.0, 0.4);
    const DiscreteCurvature c = discrete_curvature(m);
    EXPECT_EQ(c.num_estimated(), m.num_vertices());
    EXPECT_EQ(c.euler_characteristic, 0);
    EXPECT_NEAR(c.total_angle_defect(), 0.0, 8 * kEps * kPi * m.num_vertices());
}

// The torus R = 1, r = 0.4 against its analytic curvatures at the outer equator (v = 0):
// K = cos v / (r (R + r cos v)) = 1 / 0.56, H = (R + 2 r cos v) / (2 r (R + r cos v)) = 1.8 / 1.12,
// k1 = 1 / r along the meridian (the z axis there), k2 = 1 / (R + r) along the parallel.
// The operators are second-order accurate on this regular grid: halving h divides the error
// by about 4 (measured 3.6 to 4.1; at least 3 asserted). The diagonals of the grid tilt the
// fitted directions by O(h^2) too (1.5e-3 rad at 32 x 16, measured).
TEST(DiscreteCurvature, TorusConvergesToTheAnalyticCurvatures) {
    const double R = 1.0, r = 0.4;
    const double K = 1.0 / (r * (R + r)), H = (R + 2 * r) / (2 * r * (R + r));
    double last[3] = {0, 0, 0};
    for (int level = 0; level < 3; ++level) {
        const int nu = 32 << level, nv = 16 << level;
        const DiscreteCurvature c = discrete_curvature(torus(nu, nv, R, r));
        const Vec3 meridian = Vec3::UnitZ();
        const double err[3] = {std::abs(c.gaussian[0] - K), std::abs(c.mean[0] - H),
                               std::atan2(c.direction1[0].cross(meridian).norm(), std::abs(c.direction1[0].dot(meridian)))};
        EXPECT_NEAR(c.k1[0], 1 / r, 0.03);
        EXPECT_NEAR(c.k2[0], 1 / (R + r), 0.02);
        EXPECT_NEAR(c.direction2[0].dot(c.direction1[0]), 0.0, 4 * kEps);
        EXPECT_LT(err[2], 2e-3);
        for (int k = 0; k < 3 && level > 0; ++k) EXPECT_LT(err[k], last[k] / 3) << level << " " << k;
        std::copy(err, err + 3, last);
    }
}

// Curvature scales as 1 / size and Gaussian curvature as 1 / size^2: the octahedron scaled by
// 1e153 and 1e-153 gives the unit octahedron's values scaled, to the same ulps. Scaled by 1e200
// its areas (1e400) and by 1e-300 its K (1e600) are out of range: refused, not returned as inf or 0.
TEST(DiscreteCurvature, HugeAndTinyMeshesScaleOrAreRefused) {
    for (double s : {1e153, 1e-153}) {
        TriMesh m = octahedron();
        for (Vec3& p : m.positions) p *= s;
        const DiscreteCurvature c = discrete_curvature(m);
        ASSERT_EQ(c.num_estimated(), 6) << s;
        EXPECT_NEAR(c.mean[0] * s, 1.0, 16 * kEps) << s;
        EXPECT_NEAR(c.gaussian[0] * s * s, kPi / std::sqrt(3.0), 32 * kEps) << s;
        EXPECT_NEAR(c.mixed_area[0] / s / s, 2 * std::sqrt(3.0) / 3, 16 * kEps) << s;
    }
    for (double s : {1e200, 1e-300}) {
        TriMesh m = octahedron();
        for (Vec3& p : m.positions) p *= s;
        try {
            discrete_curvature(m);
            FAIL() << s;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("vertex 0: its curvature or area is out of the range of double"),
                      std::string::npos) << e.what();
        }
    }
}

TEST(DiscreteCurvature, RefusesNonManifoldAndNonFiniteInput) {
    TriMesh m = octahedron();
    m.positions[3] = Vec3(0, std::nan(""), 0);
    try {
        discrete_curvature(m);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 3"), std::string::npos) << e.what();
    }
    TriMesh fin = octahedron();
    fin.triangles.push_back({0, 2, 3});  // edge 0-2 in a third triangle
    EXPECT_THROW(discrete_curvature(fin), InputError);
}
