// The Eigen Splines adapter on values computed by hand: the knot-vector set-up and parameter
// shift are what can go wrong here, and hand values catch both.

#include <gtest/gtest.h>

#include "crossdiv/adapters/eigen_splines.h"
#include "crossdiv/error.h"

using namespace crossdiv;
namespace es = crossdiv::adapters::eigen_splines;

TEST(EigenSplines, UniformBSplineAtItsKnots) {
    // At a knot the uniform cubic B-spline is (p_k + 4 p_{k+1} + p_{k+2}) / 6, its derivative
    // (p_{k+2} - p_k) / 2 and its second derivative p_k - 2 p_{k+1} + p_{k+2}.
    const std::vector<Vec3> p{{0, 0, 0}, {6, 0, 0}, {6, 6, 0}, {0, 6, 0}, {0, 12, 6}};
    const std::vector<double> u{0.0, 1.0, 2.0};
    const es::SplineSamples s = es::uniform_cubic_bspline(p, u);
    EXPECT_LE((s.position[0] - Vec3(5, 1, 0)).norm(), 1e-14);
    EXPECT_LE((s.d1[0] - Vec3(3, 3, 0)).norm(), 1e-14);
    EXPECT_LE((s.d2[0] - Vec3(-6, 6, 0)).norm(), 1e-14);
    EXPECT_LE((s.position[1] - Vec3(5, 5, 0)).norm(), 1e-14);
    EXPECT_LE((s.position[2] - (p[2] + 4.0 * p[3] + p[4]) / 6.0).norm(), 1e-14);
    EXPECT_THROW(es::uniform_cubic_bspline(std::vector<Vec3>(3, Vec3::Zero()), u), InputError);
}

TEST(EigenSplines, ClampedBezierAtOneHalf) {
    // The cubic (0,0), (1,2), (3,2), (4,0): (2, 1.5), derivative (4.5, 0), second (0, -12).
    const std::vector<Vec3> p{{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};
    const es::SplineSamples s = es::clamped_bezier(p, std::vector<double>{0.5, 1.0});
    EXPECT_LE((s.position[0] - Vec3(2, 1.5, 0)).norm(), 1e-14);
    EXPECT_LE((s.d1[0] - Vec3(4.5, 0, 0)).norm(), 1e-14);
    EXPECT_LE((s.d2[0] - Vec3(0, -12, 0)).norm(), 1e-14);
    EXPECT_LE((s.position[1] - p[3]).norm(), 1e-14);
    // Degree 1: a line; its second derivative is zero (Eigen has no order above the degree).
    const es::SplineSamples line = es::clamped_bezier(std::vector<Vec3>{{0, 0, 0}, {2, 4, 0}}, std::vector<double>{0.25});
    EXPECT_LE((line.position[0] - Vec3(0.5, 1, 0)).norm(), 1e-15);
    EXPECT_LE((line.d1[0] - Vec3(2, 4, 0)).norm(), 1e-15);
    EXPECT_EQ(line.d2[0], Vec3::Zero());
}

TEST(EigenSplines, Version) { EXPECT_EQ(es::version().rfind("Eigen 3.", 0), 0u); }
