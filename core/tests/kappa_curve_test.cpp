// kappa-curves: the cubic for t_i and the joint weights l_i on hand-computed pieces, the
// closed regular polygons whose converged curves are known in closed form, the properties
// the iteration converges to on irregular points, and the SWP record.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/kappa_curve.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/mesh/tri_mesh.h"

#include "parse_errors.h"
#include "test_points.h"

using namespace crossdiv;

namespace {

using crossdiv::test::v;

using crossdiv::test::kEps;

/// The regular n-gon of circumradius 1, counterclockwise from (1, 0).
std::vector<Vec3> regular_polygon(int n) {
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i) p.push_back(v(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n)));
    return p;
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

// The quadratic (0,0), (x,y), (4,0) has c'(t)/2 = (x, y) + t (4 - 2x, -2y) and c''/2 =
// (4 - 2x, -2y); at t = 1/4 their dot product is (1 + x/2)(4 - 2x) - y^2 = 4 - x^2 - y^2, so
// with the middle point (0, 2) on the circle of radius 2 the speed is smallest (|curvature|
// largest) at t = 1/4, where the curve passes through (1/4, 3/4).
TEST(KappaCurve, ParameterOfTheCurvatureMaximumByHand) {
    EXPECT_EQ(kappa_parameter(v(-1, 0), v(0, 1), v(1, 0)), 0.5);  // 4t^3 - 6t^2 + 6t - 2 = 0
    EXPECT_NEAR(kappa_parameter(v(0, 0), v(0.25, 0.75), v(4, 0)), 0.25, 2 * kEps);
    const Vec3 piece[3] = {v(0, 0), v(0, 2), v(4, 0)};
    EXPECT_EQ(quadratic_max_curvature_param(piece), 0.25);  // -(0,2).(4,-4) / 32
    EXPECT_EQ(bezier_point(piece, 0.25), v(0.25, 0.75));
    // The point at a joint: the cubic's root is the end itself.
    EXPECT_EQ(kappa_parameter(v(0, 0), v(0, 0), v(4, 0)), 0.0);
    EXPECT_EQ(kappa_parameter(v(0, 0), v(4, 0), v(4, 0)), 1.0);
    // A straight uniform piece has no curvature maximum; the middle is reported.
    const Vec3 straight[3] = {v(0, 0), v(1, 0), v(2, 0)};
    EXPECT_EQ(quadratic_max_curvature_param(straight), 0.5);
}

// Triangle (0,0), (1,0), (1,1) has area 1/2, triangle (1,0), (1,1), (-3,1) area 2: l =
// sqrt(1/2) / (sqrt(1/2) + sqrt(2)) = 1/3.
TEST(KappaCurve, JointWeightByHand) {
    EXPECT_NEAR(kappa_lambda(v(0, 0), v(1, 0), v(1, 1), v(-3, 1)), 1.0 / 3.0, kEps);
    EXPECT_EQ(kappa_lambda(v(0, 0), v(1, 0), v(2, 0), v(3, 0)), 0.5);  // both triangles flat
    EXPECT_EQ(kappa_lambda(v(0, 0), v(1, 0), v(1, 1), v(1, 2)), 1.0);   // only the second flat
}

// By symmetry every t_i and l_i of a regular n-gon is 1/2, so the middle points are the
// corners scaled by s: (1/4)(s p_{i-1} + s p_i)/2 + (1/2) s p_i + (1/4)(s p_i + s p_{i+1})/2 = p_i,
// with p_{i-1} + p_{i+1} = 2 cos(2 pi / n) p_i, gives s = 8 / (6 + 2 cos(2 pi / n)): 4/3 for
// the square, 8/5 for the triangle. The joints are the midpoints of the scaled edges.
TEST(KappaCurve, RegularPolygonsConvergeToTheClosedForm) {
    for (int n : {3, 4, 5, 8}) {
        const std::vector<Vec3> p = regular_polygon(n);
        const KappaCurve k = kappa_curve(p);
        ASSERT_TRUE(k.converged) << n;
        EXPECT_LE(k.iterations(), 3) << n;  // the first solve lands on the fixed point
        const double s = 8.0 / (6.0 + 2.0 * std::cos(2 * M_PI / n));
        for (int i = 0; i < n; ++i) {
            const auto piece = k.chain.segment(i);
            EXPECT_LE((piece[1] - s * p[i]).norm(), 8 * kEps) << n << " middle " << i;
            EXPECT_LE((piece[2] - 0.5 * s * (p[i] + p[(i + 1) % n])).norm(), 8 * kEps) << n << " joint " << i;
            EXPECT_NEAR(k.params[i], 0.5, 4 * kEps);
            EXPECT_NEAR(k.lambdas[i], 0.5, 4 * kEps);
        }
    }
    const KappaCurve square = kappa_curve(std::vector<Vec3>{v(1, 1), v(-1, 1), v(-1, -1), v(1, -1)});
    EXPECT_LE((square.chain.segment(0)[1] - v(4.0 / 3, 4.0 / 3)).norm(), 4 * kEps);
    EXPECT_LE((square.chain.segment(0)[2] - v(0, 4.0 / 3)).norm(), 4 * kEps);
}

// On irregular points (the example of Yan's reference code, and a blob with inflections) the
// converged curve has every property the construction promises, each measured independently
// of the iteration: p_i on piece i at t_i, the speed minimum (|curvature| maximum) of piece i
// at p_i, shared joints with parallel tangents, and equal |curvature| on both sides.
TEST(KappaCurve, ConvergedCurvesHaveTheirProperties) {
    std::vector<Vec3> blob;
    for (int i = 0; i < 12; ++i) {
        const double a = 2 * M_PI * i / 12, r = 1 + 0.3 * std::sin(3 * a);
        blob.push_back(v(r * std::cos(a), r * std::sin(a)));
    }
    int inflections = 0;
    for (const std::vector<Vec3>& p : {std::vector<Vec3>{v(0, 0), v(0, 1), v(2, 2), v(1, 0)}, blob}) {
        const KappaCurve k = kappa_curve(p);
        ASSERT_TRUE(k.converged);
        EXPECT_LE(k.residual(), kKappaConvergence);
        const double diagonal = bounding_box_diagonal(p);
        const size_t n = p.size();
        for (size_t i = 0; i < n; ++i) {
            const auto piece = k.chain.segment(static_cast<int>(i)), after = k.chain.segment(static_cast<int>((i + 1) % n));
            EXPECT_LE((bezier_point(piece, k.params[i]) - p[i]).norm() / diagonal, 1e-14) << i;
            EXPECT_LE((bezier_point(piece, quadratic_max_curvature_param(piece)) - p[i]).norm() / diagonal, 1e-9) << i;
            EXPECT_EQ(piece[2], after[0]);
            const Vec3 in = piece[2] - piece[1], out = after[1] - after[0];
            EXPECT_LE(in.normalized().cross(out.normalized()).norm(), 4 * kEps) << i;
            EXPECT_GT(in.dot(out), 0.0);
            const double left = quadratic_signed_curvature(piece, 1.0), right = quadratic_signed_curvature(after, 0.0);
            EXPECT_NEAR(std::abs(left), std::abs(right), 1e-9 * std::max(std::abs(left), std::abs(right))) << i;
            if (left * right < 0) ++inflections;
        }
        // The residuals fall: no step of a converging iteration moves the points more than
        // the first.
        for (double r : k.residuals) EXPECT_LE(r, k.residuals.front());
    }
    EXPECT_EQ(inflections, 6);  // the blob's three dents each have an inflection on both sides
}

TEST(KappaCurve, IsTheSameCurveAtEveryScaleToTheLastBit) {
    // Scaling by a power of two is exact, and the construction commutes with scaling: at
    // 2^-1000 (about 1e-301, where the triangle areas underflow to 0 and the system was
    // singular) and at 2^1000 (where they overflow) the curve is the unit-scale curve times
    // the scale, bit for bit.
    const std::vector<Vec3> p = {v(1, 0), v(0, 1), v(-1, 0), v(0, -1.5)};
    const KappaCurve unit = kappa_curve(p);
    ASSERT_TRUE(unit.converged);
    for (int exponent : {-1000, -1, 7, 1000}) {
        std::vector<Vec3> scaled;
        for (const Vec3& q : p) scaled.push_back(std::ldexp(1.0, exponent) * q);
        const KappaCurve k = kappa_curve(scaled);
        ASSERT_TRUE(k.converged) << exponent;
        EXPECT_EQ(k.iterations(), unit.iterations()) << exponent;
        ASSERT_EQ(k.chain.points.size(), unit.chain.points.size());
        for (size_t i = 0; i < k.chain.points.size(); ++i)
            EXPECT_EQ(k.chain.points[i], std::ldexp(1.0, exponent) * unit.chain.points[i]) << exponent << " point " << i;
    }
}

TEST(KappaCurve, ReportsAnIterationStoppedShortAsNotConverged) {
    const std::vector<Vec3> p{v(0, 0), v(0, 1), v(2, 2), v(1, 0)};
    const KappaCurve k = kappa_curve(p, {kKappaConvergence, 3});
    EXPECT_FALSE(k.converged);
    EXPECT_EQ(k.iterations(), 3);
    EXPECT_GT(k.residual(), 1e-4);
    // A spike of 0.6 degrees with a point close behind it converges too slowly for the cap.
    const std::vector<Vec3> spike{v(0, 0), v(10, 0.05), v(0, 0.1), v(-2, 0.05)};
    const std::string e = error_of([&] { converged_kappa_curve(spike); });
    EXPECT_EQ(e.rfind("the kappa-curve iteration did not converge: after 5000 iterations the middle points still move by ", 0),
              0u)
        << e;
}

TEST(KappaCurve, RefusesPointsItCannotUse) {
    EXPECT_EQ(error_of([] { kappa_curve(std::vector<Vec3>{v(0, 0), v(1, 0)}); }),
              "a closed kappa-curve needs at least 3 points, got 2");
    EXPECT_EQ(error_of([] { kappa_curve(std::vector<Vec3>{v(0, 0), v(1, 0), v(1, 0), v(0, 1)}); }),
              "points 2 and 3 of 4 coincide: a piece cannot have its curvature maximum at both");
    EXPECT_EQ(error_of([] { kappa_curve(std::vector<Vec3>{v(0, 0), v(1, 0), v(0, 1), v(0, 0)}); }),
              "points 4 and 1 of 4 coincide: a piece cannot have its curvature maximum at both");
    EXPECT_EQ(error_of([] { kappa_curve(std::vector<Vec3>{v(0, 0), v(1, 0), Vec3(0, 1, 1)}); }),
              "point 3 of 3 is off the xy-plane: a kappa-curve is planar");
    EXPECT_EQ(error_of([] { kappa_curve(std::vector<Vec3>{v(0, 0), v(NAN, 0), v(0, 1)}); }), "point 2 of 3 is not finite");
    EXPECT_EQ(error_of([] { kappa_curve(regular_polygon(10'001)); }),
              "a kappa-curve of 10001 points: each of up to 5000 iterations solves a system of that size; at most "
              "10000 points");
}

TEST(KappaCurve, SwpRecord) {
    std::istringstream in("# a kappa-curve\nkpc2 k 8 4 [0 0] [0 1] [2 2] [1 0]\n");
    const CurveFile f = read_swp(in, "k.swp");
    ASSERT_EQ(f.curves.size(), 1u);
    const CurveRecord& r = f.curves[0];
    EXPECT_EQ(r.type, CurveType::KappaClosed);
    EXPECT_TRUE(r.wraps());
    EXPECT_TRUE(r.closed());
    // The reader solves the iteration once and keeps it; chain() reads it.
    ASSERT_TRUE(r.kappa);
    EXPECT_TRUE(r.kappa->converged);
    const BezierChain c = r.chain();
    EXPECT_EQ(c.points, r.kappa->chain.points);
    EXPECT_EQ(c.degree, 2);
    EXPECT_EQ(c.num_segments(), 4);
    const Polyline line = tessellate_record(r, {});
    EXPECT_EQ(line.size(), 4 * 8 + 1);
    EXPECT_EQ(line.positions.front(), line.positions.back());

    using test::swp_error;
    EXPECT_EQ(swp_error("\nkpc2 k 8 2 [0 0] [1 0]\n"), "bad.swp:2: kpc2 'k': a closed kappa-curve needs at least 3 points, got 2");
    EXPECT_EQ(swp_error("kpc2 k 8 4 [0 0] [10 0.05] [0 0.1] [-2 0.05]\n").rfind("bad.swp:1: kpc2 'k': the kappa-curve iteration did "
                                                                              "not converge: after 5000 iterations",
                                                                              0),
              0u);
}
