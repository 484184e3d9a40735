// Curves: hand-computed values on tiny inputs, then properties that must hold exactly or to
// rounding. The cross-checks against Eigen and the analytic frames are in adapters/eigen and
// verification/.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/cubic_spline.h"
#include "crossdiv/curves/curve_record.h"
#include "crossdiv/curves/frames.h"
#include "crossdiv/curves/primitive_tessellation.h"
#include "crossdiv/curves/primitives.h"
#include "crossdiv/curves/tessellation.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "parse_errors.h"
#include "test_points.h"

using namespace crossdiv;

namespace {

using crossdiv::test::v;
// A cubic whose de Casteljau levels at t = 1/2 are exact binary fractions.
const std::vector<Vec3> kCubic{v(0, 0), v(1, 2), v(3, 2), v(4, 0)};

void expect_points(const std::vector<Vec3>& got, const std::vector<Vec3>& want, double tol = 0) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_LE((got[i] - want[i]).norm(), tol) << "point " << i << ": " << got[i].transpose();
}

}  // namespace

TEST(Bezier, CasteljauStepIsTheSeedsEvaluateStep) {
    expect_points(casteljau_step(std::vector<Vec3>{v(0, 0), v(1, 0), v(1, 1)}, 0.5), {v(0.5, 0), v(1, 0.5)});
    EXPECT_TRUE(casteljau_step(std::vector<Vec3>{v(1, 1)}, 0.3).empty());
}

TEST(Bezier, PointsThatOverflowAreRefusedNamingTheLevelAndPoint) {
    // (1 - t) a + t b with a = -M, b = M at t = 2 is 3M: not a double. At t = 1/2 it is 0.
    const double M = std::numeric_limits<double>::max();
    const std::vector<Vec3> c{Vec3(-M, 0, 0), Vec3(M, 0, 0)};
    try {
        casteljau_levels(c, 2.0);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("de Casteljau level 1, point 0 is not finite"), std::string::npos) << e.what();
    }
    EXPECT_EQ(casteljau_levels(c, 0.5).back()[0], Vec3(0, 0, 0));
    // The B-spline basis change sums 1/6, 4/6, 1/6 of neighbours: at 1e308 that overflows.
    const std::vector<Vec3> bsp{Vec3(1e308, 0, 0), Vec3(1.5e308, 0, 0), Vec3(1.7e308, 0, 0), Vec3(1.7e308, 1, 0)};
    EXPECT_THROW(bspline_chain(bsp), InputError);
    EXPECT_NO_THROW(bspline_chain(std::vector<Vec3>{bsp[0] * 1e-2, bsp[1] * 1e-2, bsp[2] * 1e-2, bsp[3] * 1e-2}));
}

TEST(Bezier, EveryLevelOfACubicAtOneHalf) {
    const auto levels = casteljau_levels(kCubic, 0.5);
    ASSERT_EQ(levels.size(), 4u);
    expect_points(levels[0], kCubic);
    expect_points(levels[1], {v(0.5, 1), v(2, 2), v(3.5, 1)});
    expect_points(levels[2], {v(1.25, 1.5), v(2.75, 1.5)});
    expect_points(levels[3], {v(2, 1.5)});
    EXPECT_THROW(casteljau_levels(std::vector<Vec3>{}, 0.5), InputError);
}

TEST(Bezier, JetOfACubic) {
    // y(t) = 6 t (1 - t): y(1/2) = 1.5, y' = 0, y'' = -12; x' = 3 (2.75 - 1.25) = 4.5.
    const BezierJet j = bezier_jet(kCubic, 0.5);
    EXPECT_EQ(j.position, v(2, 1.5));
    EXPECT_EQ(j.d1, v(4.5, 0));
    EXPECT_EQ(j.d2, v(0, -12));
    // At t = 0: d1 = 3 (p1 - p0), d2 = 6 (p2 - 2 p1 + p0).
    const BezierJet j0 = bezier_jet(kCubic, 0.0);
    EXPECT_EQ(j0.d1, v(3, 6));
    EXPECT_EQ(j0.d2, v(6, -12));
    // A line has no second derivative; a point has neither.
    EXPECT_EQ(bezier_jet(std::vector<Vec3>{v(0, 0), v(2, 0)}, 0.25).d1, v(2, 0));
    EXPECT_EQ(bezier_jet(std::vector<Vec3>{v(5, 5)}, 0.25).d1, v(0, 0));
}

TEST(Bezier, SplitAtOneHalf) {
    const BezierSplit s = bezier_split(kCubic, 0.5);
    expect_points(s.left, {v(0, 0), v(0.5, 1), v(1.25, 1.5), v(2, 1.5)});
    expect_points(s.right, {v(2, 1.5), v(2.75, 1.5), v(3.5, 1), v(4, 0)});
}

TEST(Bezier, SplitHalvesReproduceTheCurve) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1, 1);
    for (int degree = 1; degree <= 12; ++degree) {
        std::vector<Vec3> c(degree + 1);
        for (Vec3& p : c) p = v(coord(rng), coord(rng), coord(rng));
        const double at = 0.3;
        const BezierSplit s = bezier_split(c, at);
        EXPECT_EQ(s.left.back(), s.right.front());
        for (int i = 0; i <= 20; ++i) {
            const double t = i / 20.0;
            // Rounding: each de Casteljau level adds ~1 ulp per coordinate (|p| <= sqrt 3).
            const Vec3 want = bezier_point(c, t);
            const Vec3 got = t <= at ? bezier_point(s.left, t / at) : bezier_point(s.right, (t - at) / (1 - at));
            EXPECT_LE((got - want).norm(), 64 * degree * 1e-16) << "degree " << degree << " t " << t;
        }
    }
}

TEST(Bezier, DegreeElevationOfAParabola) {
    expect_points(bezier_elevate(std::vector<Vec3>{v(0, 0), v(1, 2), v(2, 0)}),
                  {v(0, 0), v(2.0 / 3, 4.0 / 3), v(4.0 / 3, 4.0 / 3), v(2, 0)}, 1e-15);
    for (int i = 0; i <= 10; ++i)
        EXPECT_LE((bezier_point(bezier_elevate(kCubic), i / 10.0) - bezier_point(kCubic, i / 10.0)).norm(), 1e-14);
}

TEST(Bezier, TangentWhereTheDerivativeVanishes) {
    // p0 = p1: the curve leaves along p2 - p0; p2 = p3: it arrives along p3 - p1.
    const std::vector<Vec3> c{v(0, 0), v(0, 0), v(1, 1), v(2, 1)};
    EXPECT_LE((bezier_unit_tangent(c, 0.0) - v(1, 1).normalized()).norm(), 1e-15);
    const std::vector<Vec3> e{v(0, 0), v(1, 0), v(2, 2), v(2, 2)};
    EXPECT_LE((bezier_unit_tangent(e, 1.0) - v(1, 2).normalized()).norm(), 1e-15);
    EXPECT_LE((bezier_point_tangent(e, 1.0).tangent - v(1, 2).normalized()).norm(), 1e-15);
    EXPECT_EQ(bezier_unit_tangent(std::vector<Vec3>{v(1, 1), v(1, 1)}, 0.5), v(0, 0));
}

TEST(CubicSpline, SegmentTessellationFollowsTheSeedsRule) {
    std::vector<Vec3> pts;
    const Eigen::Matrix4d bez = basis_matrix(CubicBasis::Bezier);
    tessellate_cubic_spline_segment(kCubic[0], kCubic[1], kCubic[2], kCubic[3], bez, 1, true, pts);
    expect_points(pts, {v(0, 0), v(4, 0)});
    pts.clear();
    tessellate_cubic_spline_segment(kCubic[0], kCubic[1], kCubic[2], kCubic[3], bez, 1, false, pts);
    expect_points(pts, {v(0, 0)});
    pts.clear();
    // num_intervals = 5: t = 0, .2, ..., 1 (the rule; not the seed's example). At t = .2:
    // x = 3(.2)(.64) + 9(.04)(.8) + 4(.008) = .704, y = 6(.2)(.8) = .96.
    tessellate_cubic_spline_segment(kCubic[0], kCubic[1], kCubic[2], kCubic[3], bez, 5, true, pts);
    ASSERT_EQ(pts.size(), 6u);
    EXPECT_LE((pts[1] - v(0.704, 0.96)).norm(), 1e-15);
    EXPECT_THROW(tessellate_cubic_spline_segment(kCubic[0], kCubic[1], kCubic[2], kCubic[3], bez, 0, true, pts), InputError);
}

TEST(CubicSpline, BasisConversionsByHand) {
    const std::array<Vec3, 4> square{v(0, 0), v(6, 0), v(6, 6), v(0, 6)};
    const auto bs = bspline_to_bezier(square);
    expect_points({bs.begin(), bs.end()}, {v(5, 1), v(6, 2), v(6, 4), v(5, 5)});
    const std::array<Vec3, 4> cr{v(0, 0), v(1, 0), v(2, 1), v(3, 3)};
    const auto b = catmull_rom_to_bezier(cr);
    expect_points({b.begin(), b.end()}, {v(1, 0), v(4.0 / 3, 1.0 / 6), v(5.0 / 3, 0.5), v(2, 1)}, 1e-15);
}

TEST(CubicSpline, ConversionsReproduceTheMatrixForm) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coord(-2, 2);
    for (CubicBasis basis : {CubicBasis::Bezier, CubicBasis::BSpline, CubicBasis::CatmullRom}) {
        std::array<Vec3, 4> g;
        for (Vec3& p : g) p = v(coord(rng), coord(rng), coord(rng));
        std::vector<Vec3> matrix_form;
        tessellate_cubic_spline_segment(g[0], g[1], g[2], g[3], basis_matrix(basis), 8, true, matrix_form);
        const auto b = to_bezier(basis, g);
        for (int i = 0; i <= 8; ++i)
            EXPECT_LE((bezier_point(b, i / 8.0) - matrix_form[i]).norm(), 1e-14) << to_string(basis) << " i " << i;
    }
}

TEST(CubicSpline, ChainsCheckTheirPointCounts) {
    const std::vector<Vec3> five(5, v(0, 0));
    EXPECT_THROW(bezier_chain(five), InputError);
    EXPECT_THROW(bspline_chain(std::vector<Vec3>(3, v(0, 0))), InputError);
    EXPECT_THROW(catmull_rom_chain(std::vector<Vec3>(3, v(0, 0)), false), InputError);
    EXPECT_NO_THROW(catmull_rom_chain(std::vector<Vec3>(3, v(0, 0)), true));
    EXPECT_EQ(bezier_chain(std::vector<Vec3>(7, v(0, 0))).num_segments(), 2);
    EXPECT_EQ(bspline_chain(five).num_segments(), 2);
    EXPECT_EQ(catmull_rom_chain(five, true).num_segments(), 5);
}

TEST(CubicSpline, CatmullRomPassesThroughItsPoints) {
    const std::vector<Vec3> p{v(0, 0), v(1, 0), v(2, 1), v(3, 3), v(5, 2)};
    const BezierChain open = catmull_rom_chain(p, false);
    for (int k = 0; k <= 2; ++k) EXPECT_EQ(chain_jet(open, k).position, p[k + 1]) << k;
    const BezierChain closed = catmull_rom_chain(p, true);
    for (int k = 0; k < 5; ++k) EXPECT_EQ(chain_jet(closed, k).position, p[(k + 1) % 5]) << k;
    EXPECT_EQ(chain_jet(closed, 5).position, p[1]);  // closes where it started
}

TEST(Tessellation, UniformParametersAndEnds) {
    const BezierChain c = bezier_chain(std::vector<Vec3>{v(0, 0), v(1, 2), v(3, 2), v(4, 0), v(5, -2), v(7, -2), v(8, 0)});
    const Polyline p = tessellate_uniform(c, 4);
    ASSERT_EQ(p.size(), 9);
    for (int i = 0; i <= 8; ++i) EXPECT_DOUBLE_EQ(p.params[i], i * 0.25);
    EXPECT_EQ(p.positions[2], v(2, 1.5));
    EXPECT_EQ(p.positions[8], v(8, 0));
    // Planar curve: N = +z x T, to the left; at the top of the first arch T = +x, N = +y.
    EXPECT_LE((p.tangents[2] - v(1, 0)).norm(), 1e-15);
    EXPECT_LE((p.normals[2] - v(0, 1)).norm(), 1e-15);
}

TEST(Tessellation, AngleModeByHand) {
    // Turns of 45 degrees at p1 and p2: one edge when half the tolerance is >= 45 degrees.
    const BezierChain c = single_bezier(std::vector<Vec3>{v(0, 0), v(1, 0), v(2, 1), v(2, 2)});
    EXPECT_EQ(tessellate_angle(c, 100 * M_PI / 180).size(), 2);
    const Polyline finer = tessellate_angle(c, 80 * M_PI / 180);
    EXPECT_GT(finer.size(), 2);
    for (int i = 0; i < finer.size(); ++i)
        EXPECT_LE((finer.positions[i] - bezier_point(c.segment(0), finer.params[i])).norm(), 4e-16) << i;
    // A straight cubic never splits, even when its control points double back on the line.
    EXPECT_EQ(tessellate_angle(single_bezier(std::vector<Vec3>{v(0, 0), v(1, 0), v(2, 0), v(3, 0)}), 0.01).size(), 2);
    // The level cap: a 1e-6 rad tolerance on a curve turning ~127 degrees would need ~4e6
    // edges; every piece stops at depth 10, 2^10 edges.
    EXPECT_EQ(tessellate_angle(single_bezier(kCubic), 1e-6).size(), 1025);
    EXPECT_THROW(tessellate_angle(c, 0.0), InputError);
}

TEST(Tessellation, WangBoundByHand) {
    // Second differences (1, -2) and (-1, -2): M = sqrt 5; n = ceil(sqrt(6 M / (8 tol))).
    const BezierChain c = single_bezier(kCubic);
    EXPECT_EQ(wang_intervals(c, 0.01), std::vector<int>{13});
    EXPECT_EQ(wang_intervals(c, 10.0), std::vector<int>{1});
}

TEST(Tessellation, DistanceModeMeetsItsToleranceWithFewerPointsThanWang) {
    const BezierChain c = bspline_chain(std::vector<Vec3>{v(0, 0), v(1, 3), v(2, -1), v(3, 0), v(4, 4), v(6, 0), v(7, 1)});
    for (double tol : {1e-1, 1e-2, 1e-3, 1e-4, 1e-6}) {
        const Polyline d = tessellate_distance(c, tol);
        EXPECT_LE(chordal_deviation(c, d).max, tol) << tol;
        const std::vector<int> wang = wang_intervals(c, tol);
        const Polyline w = tessellate_uniform(c, wang);
        EXPECT_LE(chordal_deviation(c, w).max, tol) << tol;
        EXPECT_LE(d.size(), w.size()) << tol;
    }
    EXPECT_EQ(tessellate_distance(single_bezier(std::vector<Vec3>{v(0, 0), v(1, 0), v(2, 0)}), 1e-9).size(), 2);
    EXPECT_THROW(tessellate_distance(c, 1e-15), InputError);
    EXPECT_THROW(tessellate_distance(c, std::nan("")), InputError);
}

TEST(Tessellation, FlatteningEstimateOfAParabolaByHand) {
    // y = x^2 on [-1, 1]: kappa = 2 / (1 + 4x^2)^(3/2), ds = (1 + 4x^2)^(1/2) dx, so
    // sqrt(kappa) ds = sqrt(2) (1 + 4x^2)^(-1/4) dx; its integral by Simpson's rule on 10^5
    // intervals is exact to far below the estimate's 128 trapezoids (error ~1e-5 relative).
    const BezierChain c = single_bezier(std::vector<Vec3>{v(-1, 1), v(0, -1), v(1, 1)});
    const int n = 100000;
    double integral = 0;
    for (int i = 0; i <= n; ++i) {
        const double x = -1.0 + 2.0 * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        integral += w * std::sqrt(2.0) * std::pow(1 + 4 * x * x, -0.25);
    }
    integral *= (2.0 / n) / 3;
    const double tol = 1e-4;
    EXPECT_NEAR(flattening_estimate(c, tol), integral / std::sqrt(8 * tol), 1e-4 * integral / std::sqrt(8 * tol));
    // The distance mode cuts where the integral says: within tol, with about N* edges (the
    // parabola's sag over a piece is kappa h^2 / 8 to within its curvature's variation).
    const Polyline d = tessellate_distance(c, tol);
    EXPECT_LE(chordal_deviation(c, d).max, tol);
    EXPECT_LE(d.size() - 1, std::ceil(1.15 * flattening_estimate(c, tol)));
    EXPECT_THROW(flattening_estimate(c, 0.0), InputError);
}

TEST(Tessellation, APrimitiveByDistanceIsWithinTolWithNearlyTheFewestEdges) {
    // A circle of radius 2 at tol 1e-4: N* = sqrt(1 / r) 2 pi r / sqrt(8 tol) = 2 pi sqrt(2 / 8e-4)
    // = 100 pi. The fewest edges of any inscribed polygon within tol: a chord of angle t sags
    // r (1 - cos(t / 2)), so t <= 2 acos(1 - tol / r) and 2 pi / t = 314.16...: 315 edges. The
    // bound (h^2 / 8 r, widened by h / 32 of it between samples) gives edges of 0.019994
    // radians: 315 too.
    Primitive circle;
    circle.radius = 2;
    EXPECT_NEAR(primitive_flattening_estimate(circle, 1e-4), 100 * M_PI, 1e-9 * 100 * M_PI);
    const Polyline c = tessellate_primitive_distance(circle, 1e-4);
    EXPECT_EQ(std::ceil(2 * M_PI / (2 * std::acos(1 - 1e-4 / 2))), 315);
    EXPECT_EQ(c.size() - 1, 315);
    EXPECT_LE(primitive_deviation(circle, c).max, 1e-4);
    EXPECT_EQ(c.positions.back(), c.positions.front());  // closed, bitwise
    // The helix and the trefoil at 1e-3 and 1e-4 of their size: within tol, and within 1.15 N*
    // (doubling uniform steps took the trefoil 1.92 N* at 1e-4).
    Primitive helix;
    helix.kind = PrimitiveKind::Helix;
    helix.radius = 1.5;
    helix.pitch = 2;
    helix.turns = 3;
    Primitive trefoil;
    trefoil.kind = PrimitiveKind::Trefoil;
    for (const Primitive& p : {helix, trefoil})
        for (double rel : {1e-3, 1e-4}) {
            const double tol = rel * bounding_box_diagonal(sample_primitive(p, 256).positions);
            const Polyline d = tessellate_primitive_distance(p, tol);
            const std::string what = std::string(to_string(p.kind)) + " at " + std::to_string(rel);
            EXPECT_LE(primitive_deviation(p, d).max, tol) << what;
            EXPECT_LE(d.size() - 1, 1.15 * primitive_flattening_estimate(p, tol)) << what;
            EXPECT_GE(d.size() - 1, primitive_flattening_estimate(p, tol) * 0.95) << what;
        }
    EXPECT_NE(tessellate_primitive_distance(helix, 1e-3).positions.back(),
              tessellate_primitive_distance(helix, 1e-3).positions.front());  // open
    EXPECT_THROW(tessellate_primitive_distance(circle, 0.0), InputError);
    EXPECT_THROW(tessellate_primitive_distance(circle, 1e-300), InputError);
    EXPECT_THROW(primitive_flattening_estimate(circle, -1.0), InputError);
}

TEST(Tessellation, ChordalDeviationOfAParabolaByHand) {
    // y = x^2 on [-1, 1] (control (-1,1), (0,-1), (1,1)); its chord is y = 1, 1 away at x = 0.
    const BezierChain c = single_bezier(std::vector<Vec3>{v(-1, 1), v(0, -1), v(1, 1)});
    const Deviation d = chordal_deviation(c, tessellate_uniform(c, 1));
    EXPECT_NEAR(d.max, 1.0, 1e-12);
    EXPECT_NEAR(d.at_param, 0.5, 1e-6);
}

TEST(Frames, ACurveAtTheScaleOf1eMinus300HasTheUnitCurvesTangentsDeviationAndFrames) {
    // A space B-spline and the same control points times 2^-1000 (about 1e-301): the squares
    // of its derivatives and steps underflow, which made the tangents 0 and the frames NaN.
    // Scaled by a power of two the curve is the same curve: its unit tangents, frames and
    // (scaled) deviation are the unit curve's to rounding.
    const std::vector<Vec3> control = {v(0, 0, 0), v(1, 3, 1), v(2, -1, 2), v(3, 0, -1), v(4, 4, 0)};
    const double tiny = std::ldexp(1.0, -1000);
    std::vector<Vec3> small;
    for (const Vec3& c : control) small.push_back(tiny * c);
    const Polyline unit = tessellate_uniform(bspline_chain(control), 16);
    const Polyline scaled = tessellate_uniform(bspline_chain(small), 16);
    ASSERT_EQ(unit.size(), scaled.size());
    EXPECT_NEAR(chordal_deviation(bspline_chain(small), scaled).max / tiny, chordal_deviation(bspline_chain(control), unit).max, 1e-15);
    for (FrameMethod m : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        const auto f = curve_frames(unit.positions, unit.tangents, m), g = curve_frames(scaled.positions, scaled.tangents, m);
        for (int i = 0; i < unit.size(); ++i) {
            EXPECT_LE((scaled.tangents[i] - unit.tangents[i]).norm(), 1e-15) << i;
            EXPECT_LE((g[i].N - f[i].N).norm(), 1e-14) << to_string(m) << " " << i;
            EXPECT_LE((g[i].B - f[i].B).norm(), 1e-14) << to_string(m) << " " << i;
        }
    }
}

TEST(Frames, PlanarFramesAreTheSeedsCircle) {
    Primitive circle;
    circle.radius = 2;
    const Polyline p = sample_primitive(circle, 8);
    ASSERT_EQ(p.size(), 9);
    EXPECT_EQ(p.positions[8], p.positions[0]);
    for (int i = 0; i < 8; ++i) {
        const double s = 2 * M_PI * i / 8;
        EXPECT_LE((p.normals[i] - v(-std::cos(s), -std::sin(s))).norm(), 1e-15) << i;
    }
    const auto right = curve_frames(p.positions, p.tangents, FrameMethod::Planar, NormalSide::Right);
    EXPECT_LE((right[0].N - v(1, 0)).norm(), 1e-15);  // CS4620: outward on a CCW loop
    EXPECT_LE(max_orthonormality_error(right), 1e-15);
}

TEST(Frames, SpaceMethodsReduceToThePlanarFrameInThePlane) {
    const BezierChain c = bspline_chain(std::vector<Vec3>{v(0, 0), v(1, 3), v(2, -1), v(3, 0), v(4, 4)});
    const Polyline p = tessellate_uniform(c, 16);
    const auto planar = curve_frames(p.positions, p.tangents, FrameMethod::Planar);
    for (FrameMethod m : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        const auto f = curve_frames(p.positions, p.tangents, m);
        for (int i = 0; i < p.size(); ++i) EXPECT_LE((f[i].N - planar[i].N).norm(), 1e-14) << to_string(m) << " " << i;
    }
}

TEST(Frames, ClosureMismatchIsMeasuredAndDistributed) {
    Primitive trefoil;
    trefoil.kind = PrimitiveKind::Trefoil;
    const Polyline p = sample_primitive(trefoil, 400);
    auto f = curve_frames(p.positions, p.tangents, FrameMethod::DoubleReflection);
    const double mismatch = closure_angle(f);
    EXPECT_GT(std::abs(mismatch), 1e-3);  // a trefoil's rotation-minimizing frame does not close
    distribute_closure(p.positions, f, mismatch);
    EXPECT_LE(std::abs(closure_angle(f)), 1e-12);
    EXPECT_LE(max_orthonormality_error(f), 1e-14);
}

TEST(CurveIo, ReadsCoreSwp) {
    std::istringstream in(
        "bez2 . 20 4\n  [3 0]\n  [3 1]\n [1 1]\n [1 0]\n\n"
        "bsp3 spine 20 4 [-2 0 1] [0 2 1]\n[0 3 -1] [ 2 0 -1 ]\n"
        "circ ring 30 1.5\ncrc2 loop 8 3 [0 0] [1 0] [0 1]\nsrev vase 90 spine\ngcyl tube ring spine\n");
    const CurveFile f = read_swp(in, "core.swp");
    ASSERT_EQ(f.curves.size(), 4u);
    EXPECT_EQ(f.curves[0].type, CurveType::BezierChain);
    EXPECT_EQ(f.curves[0].name, "");
    EXPECT_EQ(f.curves[0].steps, 20);
    EXPECT_EQ(f.curves[0].control[1], v(3, 1));
    EXPECT_EQ(f.curves[1].name, "spine");
    EXPECT_EQ(f.curves[1].dim, 3);
    EXPECT_EQ(f.curves[1].control[3], v(2, 0, -1));
    EXPECT_EQ(f.curves[1].line, 7);
    EXPECT_EQ(f.curves[2].primitive.radius, 1.5);
    EXPECT_TRUE(f.curves[3].closed());
    ASSERT_EQ(f.sweeps.size(), 2u);
    EXPECT_EQ(f.sweeps[0].profile_index, 1);
    EXPECT_EQ(f.sweeps[1].sweep_index, 1);
    EXPECT_EQ(f.sweeps[1].profile_index, 2);
}

namespace {
using test::parse_error;
using test::swp_error;
std::string bzc_error(const std::string& text) {
    return parse_error([](std::istream& in, const std::string& n) { return read_bzc(in, n); }, text, "bad.bzc");
}
}  // namespace

TEST(CurveIo, SwpErrorsNameFileAndLine) {
    EXPECT_EQ(swp_error("bez2 . 20 5\n[0 0] [1 0] [1 1] [0 1] [2 2]\n"),
              "bad.swp:1: bez2 '.': a piecewise cubic Bezier curve needs 3n + 1 control points (4, 7, 10, ...), got 5");
    EXPECT_EQ(swp_error("\nbsp2 . 20 3\n[0 0] [1 0] [1 1]\n"),
              "bad.swp:2: bsp2 '.': a cubic B-spline needs at least 4 control points, got 3");
    EXPECT_EQ(swp_error("circ . 10 1\nspline . 4\n"),
              "bad.swp:2: unknown record 'spline' (known: bez2, bez3, bsp2, bsp3, crm2, crm3, crc2, crc3, tcb2, tcb3, tcc2, tcc3, "
              "ovh2, ovh3, ovc2, ovc3, kpc2, cam3, circ, helx, trfl, srev, gcyl)");
    EXPECT_EQ(swp_error("bez2 . 20 4\n[0 0] [1 0\n[1 1] [0 1]\n"), "bad.swp:3: unbalanced bracket: '[' inside point 2 of 4");
    EXPECT_EQ(swp_error("bez2 . 20 4\n[0 0] [1 0] [1 1] [0 1]]\n"),
              "bad.swp:2: unbalanced bracket: ']' outside a point list (too many points?)");
    EXPECT_EQ(swp_error("bez2 . 20 4\n[0 0] [1 0] [1 1]\ncirc . 3 1\n"),
              "bad.swp:3: expected '[' opening point 4 of 4, got 'circ' (too few points?)");
    EXPECT_EQ(swp_error("bez2 . 20 4\n[0 0] [1 nan] [1 1] [0 1]\n"), "bad.swp:2: a coordinate is nan; numbers must be finite");
    EXPECT_EQ(swp_error("bez2 . 20 4\n[0 0] [1 0 2] [1 1] [0 1]\n"),
              "bad.swp:2: point 2 of 4 has more than 2 coordinates (or an unclosed '[')");
    EXPECT_EQ(swp_error("circ a 10 1\n\nsrev s 10 b\n"), "bad.swp:3: undefined curve 'b' (curves must be defined before use)");
    EXPECT_EQ(swp_error("circ a 10 1\ncirc a 10 2\n"), "bad.swp:2: curve 'a' is already defined on line 1");
    EXPECT_EQ(swp_error("circ a 0 1\n"), "bad.swp:1: STEPS must be at least 1, got 0");
    // STEPS beyond the documented limit, or beyond 32 and 64 bits, with the file's text (an
    // int cast made 4294967296 into 0 and 2147483680 into a negative count).
    EXPECT_EQ(swp_error("circ a 4294967296 1\n"), "bad.swp:1: STEPS 4294967296 is out of range: at most 1000000");
    EXPECT_EQ(swp_error("\nbsp2 a 2147483680 4 [0 0] [1 0] [1 1] [0 1]\n"),
              "bad.swp:2: STEPS 2147483680 is out of range: at most 1000000");
    EXPECT_EQ(swp_error("circ a 99999999999999999999 1\n"),
              "bad.swp:1: STEPS 99999999999999999999 is out of range: at most 1000000");
    EXPECT_EQ(swp_error("circ a 1000001 1\n"), "bad.swp:1: STEPS 1000001 is out of range: at most 1000000");
    EXPECT_EQ(swp_error("bez3 . 20 4\n[0 0 0] [1 0 0] [1 1 0]\n"),
              "bad.swp:2: unexpected end of file: expected '[' opening point 4 of 4");
}

TEST(CurveIo, ReadsBzcAndNamesItsErrors) {
    std::istringstream in("4\n0.200 0.350   0.300 0.600   0.800 0.750   0.900 0.450\n");
    const CurveFile f = read_bzc(in, "curve1.bzc");
    ASSERT_EQ(f.curves.size(), 1u);
    EXPECT_EQ(f.curves[0].type, CurveType::Bezier);
    EXPECT_EQ(f.curves[0].chain().degree, 3);
    EXPECT_EQ(f.curves[0].control[2], v(0.8, 0.75));
    EXPECT_EQ(bzc_error("3\n0 0 1 1 2\n"), "bad.bzc:2: unexpected end of file: expected y of point 3 of 3");
    EXPECT_EQ(bzc_error("2\n0 0 1 1 2 2\n"), "bad.bzc:2: unexpected '2' after 2 points");
    EXPECT_EQ(bzc_error("0\n"), "bad.bzc:1: the control point count must be at least 1, got 0");
    // Degree 256 is the most (kMaxBezierDegree: the adaptive tessellations grow as its square).
    EXPECT_EQ(bzc_error("258\n0 0\n"), "bad.bzc:1: the control point count 258 is out of range: at most 257");
    EXPECT_EQ(bzc_error("2\n0 0\n1 inf\n"), "bad.bzc:3: y of point 2 of 2 is inf; numbers must be finite");
}

namespace {

/// The records of `text`, written by write_swp and read again.
crossdiv::CurveFile swp_round_trip(const std::string& text, std::string* written = nullptr) {
    std::istringstream in(text);
    const crossdiv::CurveFile first = crossdiv::read_swp(in, "first.swp");
    std::ostringstream out;
    crossdiv::write_swp(out, first);
    if (written) *written = out.str();
    std::istringstream again(out.str());
    return crossdiv::read_swp(again, "written.swp");
}

}  // namespace

TEST(SwpWriter, WritesTheReadersLayoutByHand) {
    std::string written;
    swp_round_trip("bez2 arc 8 4 [0 0] [0.5 1] [1.5 1] [2 0]\nbsp3 . 4 4 [0 0 0] [1 0 1] [1 1 2] [0 1 3]\n", &written);
    EXPECT_EQ(written,
              "bez2 arc 8 4\n[ 0 0 ]\n[ 0.5 1 ]\n[ 1.5 1 ]\n[ 2 0 ]\n"
              "bsp3 . 4 4\n[ 0 0 0 ]\n[ 1 0 1 ]\n[ 1 1 2 ]\n[ 0 1 3 ]\n");
}

TEST(SwpWriter, EveryControlPointRecordReadsBackBitForBit) {
    const std::string text =
        "bez3 a 5 4 [0.1 0.2 0.3] [0.30000000000000004 1e-300 -7] [1 2 3] [4 5 6]\n"
        "crm2 b 6 5 [0 0] [1 0.3333333333333333] [2 0] [3 1] [4 0]\n"
        "crc2 c 6 3 [0 0] [1 0] [0 1]\n"
        "tcb2 d 6 4 [0 0 0.5 -0.25 1] [1 1] [2 0 -1 0 0] [3 1]\n"
        "tcc3 e 3 3 [0 0 0] [1 0 0] [0 1 0]\n"
        "ovh2 f 4 4 [0 0] [1 1] [3 1] [4 0]\n"
        "ovc2 g 4 3 [0 0] [2 0] [1 1]\n"
        "kpc2 h 4 4 [0 0] [2 0] [2 1] [0 1.5]\n";
    std::istringstream in(text);
    const crossdiv::CurveFile first = crossdiv::read_swp(in, "first.swp");
    const crossdiv::CurveFile again = swp_round_trip(text);
    ASSERT_EQ(again.curves.size(), first.curves.size());
    for (size_t i = 0; i < first.curves.size(); ++i) {
        const auto &a = first.curves[i], &b = again.curves[i];
        EXPECT_EQ(b.name, a.name);
        EXPECT_EQ(b.keyword, a.keyword);
        EXPECT_EQ(b.type, a.type);
        EXPECT_EQ(b.dim, a.dim);
        EXPECT_EQ(b.steps, a.steps);
        EXPECT_EQ(b.control, a.control) << a.name;  // bit for bit
        EXPECT_EQ(b.tcb, a.tcb) << a.name;
    }
    EXPECT_EQ(again.curves[3].tcb[0], (crossdiv::TcbParameters{0.5, -0.25, 1}));
}

TEST(SwpWriter, RecordsSwpCannotHoldAsPointsAreRefusedByName) {
    std::istringstream in("circ ring 16 2\nbez2 ok 4 4 [0 0] [1 1] [2 1] [3 0]\n");
    const crossdiv::CurveFile file = crossdiv::read_swp(in, "prim.swp");
    std::ostringstream out;
    try {
        crossdiv::write_swp(out, file);
        FAIL() << "a circle was written";
    } catch (const crossdiv::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("curve 0 'ring' (circ)"), std::string::npos) << e.what();
    }
    crossdiv::CurveFile bad;
    bad.curves.push_back(file.curves[1]);
    bad.curves[0].control[2].x() = NAN;
    EXPECT_THROW(crossdiv::write_swp(out, bad), crossdiv::InputError);
    // A keyword that does not name the record's type: bez2 on a B-spline would read back as
    // another curve.
    crossdiv::CurveFile renamed;
    renamed.curves.push_back(file.curves[1]);
    renamed.curves[0].type = crossdiv::CurveType::BSpline;
    try {
        crossdiv::write_swp(out, renamed);
        FAIL() << "a B-spline was written as bez2";
    } catch (const crossdiv::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("which its keyword does not name"), std::string::npos) << e.what();
    }
}

TEST(Tessellation, ARadialBudgetSpendsLessFarFromTheAxis) {
    // A quarter circle of radius 1 about (0, 0) in the xy-plane, from (1, 0) to (0, 1) (a
    // cubic's usual approximation): under {tol, radial} an edge whose arc reaches |x| = r may
    // deviate by tol - radial r, so edges are longer near x = 0 than near x = 1.
    const double k = 0.5522847498;
    const BezierChain c = single_bezier(std::vector<Vec3>{v(1, 0), v(1, k), v(k, 1), v(0, 1)});
    const double tol = 1e-4, radial = 0.5e-4;
    const Polyline p = tessellate_distance(c, DistanceBudget{tol, radial});
    const Polyline plain = tessellate_distance(c, tol);
    EXPECT_GT(p.size(), plain.size());  // less tolerance near the rim: more edges
    double first = 0, last = 0;
    for (int i = 0; i + 1 < p.size(); ++i) {
        // Each edge within what the budget leaves at the farthest |x| its arc reaches.
        double farthest = 0, deviation = 0;
        for (int j = 0; j <= 64; ++j) {
            const double u = p.params[i] + (p.params[i + 1] - p.params[i]) * j / 64;
            const Vec3 q = bezier_point(c.segment(0), u);
            farthest = std::max(farthest, std::abs(q.x()));
            deviation = std::max(deviation, point_segment_distance(q, p.positions[i], p.positions[i + 1]));
        }
        EXPECT_LE(deviation, tol - radial * farthest) << "edge " << i;
        const double length = (p.positions[i + 1] - p.positions[i]).norm();
        if (i == 0) first = length;
        if (i + 3 == p.size()) last = length;  // the last full edge (the final one takes what is left)
    }
    // Near the axis an edge may sag twice as far as at the rim: about sqrt(2) times as long.
    EXPECT_GT(last, 1.3 * first);
    EXPECT_THROW(tessellate_distance(c, DistanceBudget{tol, -1.0}), InputError);
    EXPECT_THROW(tessellate_distance(c, DistanceBudget{tol, std::nan("")}), InputError);
    EXPECT_THROW(tessellate_distance(c, DistanceBudget{tol, 2 * tol}), InputError);  // nothing left at x = 1
}
