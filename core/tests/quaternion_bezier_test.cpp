// Quaternion Bezier curves: slerp against Eigen's, the properties de Casteljau with slerp must
// have (unit norm, end interpolation, constant angular velocity for two points, the planar
// de Casteljau of the angles on a great circle), the rotation matrix, and the cam3 record.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/quaternion_bezier.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"

#include "parse_errors.h"
#include "test_points.h"

using namespace crossdiv;

namespace {

using crossdiv::test::kEps;

Quat random_unit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    Quat q(g(rng), g(rng), g(rng), g(rng));
    return q.normalized();
}

/// The rotation by `angle` about the unit `axis`.
Quat about(const Vec3& axis, double angle) {
    return Quat(std::cos(angle / 2), std::sin(angle / 2) * axis.x(), std::sin(angle / 2) * axis.y(),
                std::sin(angle / 2) * axis.z());
}

double distance(const Quat& a, const Quat& b) { return (a.coeffs() - b.coeffs()).norm(); }

}  // namespace

// Eigen's slerp (acos of the dot product, the shorter arc) and ours (the half-angle atan2)
// agree to 1e-15 on random pairs, on nearby pairs and on pairs with a negative dot product.
TEST(Slerp, AgreesWithEigen) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> unit(0, 1);
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        const Quat a = random_unit(rng);
        Quat b = random_unit(rng);
        if (i % 3 == 1) b = (a.coeffs() + 1e-3 * b.coeffs()).normalized();  // nearby
        if (i % 3 == 2) b.coeffs() = -b.coeffs();                               // the other sign
        const double t = unit(rng);
        worst = std::max(worst, distance(slerp(a, b, t), a.slerp(t, b)));
    }
    EXPECT_LE(worst, 1e-15);
}

TEST(Slerp, ByHand) {
    const Vec3 z(0, 0, 1);
    // Half-way between the identity and a quarter turn about z is the eighth turn.
    const Quat q = slerp(Quat::Identity(), about(z, M_PI / 2), 0.5);
    EXPECT_LE(distance(q, about(z, M_PI / 4)), 2 * kEps);
    // -q is q's rotation: slerp goes the short way and ends at -b.
    const Quat minus_b(-about(z, M_PI / 2).coeffs());
    EXPECT_LE(distance(slerp(Quat::Identity(), minus_b, 0.5), about(z, M_PI / 4)), 2 * kEps);
    EXPECT_EQ(slerp(Quat::Identity(), minus_b, 1.0).coeffs(), about(z, M_PI / 2).coeffs());
}

TEST(QuaternionBezier, StaysUnitAndInterpolatesItsEnds) {
    std::mt19937 rng(5);
    for (int d = 1; d <= 8; ++d) {
        std::vector<Quat> c(d + 1);
        for (Quat& q : c) q = random_unit(rng);
        double norm_error = 0;
        for (int i = 0; i <= 64; ++i) norm_error = std::max(norm_error, std::abs(quaternion_bezier_point(c, i / 64.0).norm() - 1));
        EXPECT_LE(norm_error, 4 * d * kEps) << "degree " << d;
        // t = 0: every slerp weight is sin(theta)/sin(theta) = 1 and sin(0) = 0, exactly.
        EXPECT_EQ(quaternion_bezier_point(c, 0.0).coeffs(), c[0].coeffs());
        // t = 1: the last quaternion, or its negative where a slerp took the shorter arc.
        const Quat end = quaternion_bezier_point(c, 1.0);
        EXPECT_TRUE(end.coeffs() == c[d].coeffs() || end.coeffs() == -c[d].coeffs()) << "degree " << d;
    }
}

TEST(QuaternionBezier, TwoControlPointsTurnAtConstantAngularVelocity) {
    std::mt19937 rng(8);
    for (int i = 0; i < 50; ++i) {
        const std::vector<Quat> c{random_unit(rng), random_unit(rng)};
        const double total = rotation_angle_between(c[0], c[1]);
        for (int k = 0; k <= 10; ++k) {
            const double t = k / 10.0;
            EXPECT_NEAR(rotation_angle_between(c[0], quaternion_bezier_point(c, t)), t * total, 1e-14);
        }
    }
}

// Rotations about one axis lie on a great circle of the unit quaternions; slerp between two of
// them is the rotation by the blended angle, so the curve is the rotation by the planar de
// Casteljau of the angles (consecutive angles less than pi apart: the shorter arcs).
TEST(QuaternionBezier, OnAGreatCircleIsTheDeCasteljauOfTheAngles) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> step(-2.5, 2.5);
    const Vec3 axis = Vec3(1, -2, 0.5).normalized();
    for (int d = 1; d <= 10; ++d) {
        std::vector<double> angle{0.3};
        for (int i = 0; i < d; ++i) angle.push_back(angle.back() + step(rng));
        std::vector<Quat> c;
        std::vector<Vec3> planar;
        for (double a : angle) {
            c.push_back(about(axis, a));
            planar.emplace_back(a, 0, 0);
        }
        for (int k = 0; k <= 32; ++k) {
            const double t = (k + 0.1) / 33.0;
            const Quat q = quaternion_bezier_point(c, t);
            const Quat want = about(axis, bezier_point(planar, t).x());
            const double err = std::min(distance(q, want), distance(Quat(-q.coeffs()), want));
            EXPECT_LE(err, 8 * d * kEps) << "degree " << d << " t " << t;
        }
    }
}

TEST(RotationMatrix, MatchesEigenAndIsOrthonormal) {
    std::mt19937 rng(21);
    for (int i = 0; i < 500; ++i) {
        const Quat q = random_unit(rng);
        const Eigen::Matrix3d r = rotation_matrix(q);
        EXPECT_LE((r - q.toRotationMatrix()).cwiseAbs().maxCoeff(), 4 * kEps);
        // Each entry of r carries a few ulps (two products and a sum, and |q| = 1 to an ulp);
        // r^T r sums three products of them.
        EXPECT_LE((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 16 * kEps);
        EXPECT_NEAR(r.determinant(), 1.0, 8 * kEps);
    }
    // A quarter turn about z takes x to y.
    const Eigen::Matrix3d r = rotation_matrix(about(Vec3(0, 0, 1), M_PI / 2));
    EXPECT_LE((r * Vec3(1, 0, 0) - Vec3(0, 1, 0)).norm(), 2 * kEps);
}

TEST(QuaternionChain, CountsAndZeroQuaternions) {
    const std::vector<Quat> four(4, Quat::Identity());
    EXPECT_EQ(quaternion_chain(four).num_segments(), 1);
    EXPECT_THROW(quaternion_chain(std::span(four).first(3)), InputError);
    std::vector<Quat> zero = four;
    zero[2].coeffs().setZero();
    try {
        quaternion_chain(zero);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "quaternion 3 of 4 is zero: it names no rotation");
    }
    // Normalized on the way in.
    std::vector<Quat> scaled = four;
    scaled[1].coeffs() *= 2;
    EXPECT_EQ(quaternion_chain(scaled).control[1].coeffs(), Quat::Identity().coeffs());
}

TEST(SwpCameraPath, PositionsAndQuaternions) {
    std::istringstream in("cam3 fly 8 4 [0 0 0 1 0 0 0] [1 0 0 1 0 0 0] [2 1 0 2 0 0 0] [3 1 1 0 0 0 1]\n");
    const CurveFile f = read_swp(in, "cam.swp");
    ASSERT_EQ(f.curves.size(), 1u);
    const CurveRecord& r = f.curves[0];
    EXPECT_EQ(r.type, CurveType::CameraPath);
    EXPECT_EQ(r.chain().num_segments(), 1);
    ASSERT_EQ(r.orientations.size(), 4u);
    EXPECT_EQ(r.orientations[2].coeffs(), Quat::Identity().coeffs());  // (2 0 0 0) normalized
    EXPECT_EQ(r.orientations[3].coeffs(), Quat(0, 0, 0, 1).coeffs());
    const auto error = [](const std::string& text) { return test::swp_error(text, "cam.swp"); };
    EXPECT_EQ(error("cam3 fly 8 4\n[0 0 0 1 0 0 0] [1 0 0]\n"), "cam.swp:2: point 2 of 4 has 3 numbers, expected 7 (x y z w qx qy qz)");
    EXPECT_EQ(error("cam3 fly 8 4 [0 0 0 1 0 0 0] [1 0 0 0 0 0 0] [2 1 0 1 0 0 0] [3 1 1 1 0 0 0]\n"),
              "cam.swp:1: cam3 'fly': quaternion 2 of 4 is zero: it names no rotation");
    EXPECT_EQ(error("cam3 fly 8 3 [0 0 0 1 0 0 0] [1 0 0 1 0 0 0] [2 1 0 1 0 0 0]\n"),
              "cam.swp:1: cam3 'fly': a piecewise cubic Bezier curve needs 3n + 1 control points (4, 7, 10, ...), got 3");
}
