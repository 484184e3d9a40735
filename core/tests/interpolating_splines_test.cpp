// Kochanek-Bartels (TCB) and Bessel-Overhauser splines: hand-computed tangents and control
// points on tiny inputs, their reduction to Catmull-Rom, interpolation, the continuity the
// formulas give, and the SWP records that define them.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "crossdiv/curves/bessel_overhauser.h"
#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/kochanek_bartels.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"

#include "parse_errors.h"
#include "test_points.h"

using namespace crossdiv;

namespace {

using crossdiv::test::v;

using crossdiv::test::expect_near;

std::vector<Vec3> random_points(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coord(-3, 3);
    std::vector<Vec3> p(n);
    for (Vec3& x : p) x = v(coord(rng), coord(rng), coord(rng));
    return p;
}

// The first derivative leaving segment k's start and arriving at its end, from the control
// points (3 (b1 - b0), 3 (b3 - b2)).
Vec3 leaving(const BezierChain& c, int k) { return 3.0 * (c.segment(k)[1] - c.segment(k)[0]); }
Vec3 arriving(const BezierChain& c, int k) { return 3.0 * (c.segment(k)[3] - c.segment(k)[2]); }

CurveFile swp(const std::string& text) {
    std::istringstream in(text);
    return read_swp(in, "test.swp");
}

}  // namespace

// Keys (0,0), (1,0), (1,1) around the corner at (1,0): the chords are (1,0) in and (0,1) out.
TEST(KochanekBartels, TangentsByHand) {
    const Vec3 a = v(0, 0), k = v(1, 0), b = v(1, 1);
    // t = c = b = 0: Catmull-Rom's (b - a) / 2 both ways.
    KeyTangents t = kochanek_bartels_tangents(a, k, b, {});
    EXPECT_EQ(t.arriving, v(0.5, 0.5));
    EXPECT_EQ(t.leaving, v(0.5, 0.5));
    // Tension 1/2 halves it: (1 - 1/2)/2 (b - a).
    t = kochanek_bartels_tangents(a, k, b, {0.5, 0, 0});
    EXPECT_EQ(t.leaving, v(0.25, 0.25));
    // Continuity 1/2: arriving 1/4 (1,0) + 3/4 (0,1), leaving 3/4 (1,0) + 1/4 (0,1).
    t = kochanek_bartels_tangents(a, k, b, {0, 0.5, 0});
    EXPECT_EQ(t.arriving, v(0.25, 0.75));
    EXPECT_EQ(t.leaving, v(0.75, 0.25));
    EXPECT_EQ(kochanek_bartels_jump(a, k, b, {0, 0.5, 0}), v(0.5, -0.5));
    // Bias 1/2 leans both towards the incoming chord: 3/4 (1,0) + 1/4 (0,1); C1 (c = 0).
    t = kochanek_bartels_tangents(a, k, b, {0, 0, 0.5});
    EXPECT_EQ(t.arriving, v(0.75, 0.25));
    EXPECT_EQ(t.leaving, v(0.75, 0.25));
    // Tension 1 stops the curve at the key.
    t = kochanek_bartels_tangents(a, k, b, {1, 0.3, -0.2});
    EXPECT_EQ(t.arriving, v(0, 0));
    EXPECT_EQ(t.leaving, v(0, 0));
}

TEST(KochanekBartels, WithZeroParametersIsCatmullRomBitForBit) {
    for (unsigned seed = 1; seed <= 20; ++seed)
        for (bool closed : {false, true}) {
            const std::vector<Vec3> keys = random_points(3 + static_cast<int>(seed % 7) + (closed ? 0 : 1), seed);
            const std::vector<TcbParameters> zeros(keys.size());
            EXPECT_EQ(kochanek_bartels_chain(keys, {}, closed).points, catmull_rom_chain(keys, closed).points)
                << "seed " << seed;
            EXPECT_EQ(kochanek_bartels_chain(keys, zeros, closed).points, catmull_rom_chain(keys, closed).points);
        }
}

TEST(KochanekBartels, ControlPointsByHand) {
    // Open: 4 keys, one segment from (1,0) to (1,1), tension 1/2 at (1,0), continuity 1/2 at (1,1).
    const std::vector<Vec3> keys{v(0, 0), v(1, 0), v(1, 1), v(2, 1)};
    const std::vector<TcbParameters> p{{}, {0.5, 0, 0}, {0, 0.5, 0}, {}};
    const BezierChain c = kochanek_bartels_chain(keys, p, false);
    ASSERT_EQ(c.num_segments(), 1);
    // Leaving (1,0): 1/4 ((1,1) - (0,0)) = (1/4, 1/4). Arriving at (1,1), chords (0,1) in,
    // (1,0) out: 1/4 (0,1) + 3/4 (1,0).
    expect_near(c.segment(0)[1], v(1 + 0.25 / 3, 0.25 / 3));
    expect_near(c.segment(0)[2], v(1 - 0.75 / 3, 1 - 0.25 / 3));
    EXPECT_EQ(c.segment(0)[0], keys[1]);
    EXPECT_EQ(c.segment(0)[3], keys[2]);
}

TEST(KochanekBartels, InterpolatesEveryKeyAndJumpsByTheFormula) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> param(-1, 1);
    for (bool closed : {false, true}) {
        const std::vector<Vec3> keys = random_points(9, closed ? 11 : 12);
        std::vector<TcbParameters> p(keys.size());
        for (size_t i = 0; i < p.size(); ++i) p[i] = {param(rng), i % 3 == 0 ? 0.0 : param(rng), param(rng)};
        const BezierChain c = kochanek_bartels_chain(keys, p, closed);
        const int n = c.num_segments();
        const size_t m = keys.size();
        for (int k = 0; k < n; ++k) {
            EXPECT_EQ(c.segment(k)[0], keys[(k + 1) % m]);  // exact: the key itself
            EXPECT_EQ(c.segment(k)[3], keys[(k + 2) % m]);
        }
        // At the joint of segments k and k + 1 (key k + 2): the derivative jump is the formula's,
        // 0 where continuity is 0. Tolerance: the tangents are sums of two scaled chords of
        // points within 3 of the origin, read back through b1 - b0 (a few ulps of 10).
        for (int k = 0; k + 1 < n + (closed ? 1 : 0); ++k) {
            const size_t i = (k + 2) % m;
            const Vec3 jump = leaving(c, (k + 1) % n) - arriving(c, k);
            const Vec3 want = kochanek_bartels_jump(keys[(i + m - 1) % m], keys[i], keys[(i + 1) % m], p[i]);
            expect_near(jump, want, 64 * std::numeric_limits<double>::epsilon() * 10);
            if (p[i].continuity == 0) {
                EXPECT_LE(jump.norm(), 64 * std::numeric_limits<double>::epsilon() * 10);
            }
        }
    }
}

TEST(KochanekBartels, RefusesWrongCountsAndParameters) {
    const std::vector<Vec3> keys{v(0, 0), v(1, 0), v(1, 1), v(2, 1)};
    EXPECT_THROW(kochanek_bartels_chain(std::span(keys).first(3), {}, false), InputError);
    EXPECT_NO_THROW(kochanek_bartels_chain(std::span(keys).first(3), {}, true));
    const std::vector<TcbParameters> three(3);
    try {
        kochanek_bartels_chain(keys, three, false);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "a TCB spline needs one parameter set per key: 4 keys, 3 parameter sets");
    }
    for (double bad : {1.5, -1.01, std::numeric_limits<double>::quiet_NaN()}) {
        std::vector<TcbParameters> p(4);
        p[2].bias = bad;
        EXPECT_THROW(kochanek_bartels_chain(keys, p, false), InputError) << bad;
    }
}

// Collinear points 1, 2, 3 apart: chord-length knots make the curve the line at constant
// speed, so the inner control points sit at thirds of the segment.
TEST(BesselOverhauser, ControlPointsByHand) {
    BezierChain c = bessel_overhauser_chain(std::vector<Vec3>{v(0, 0), v(1, 0), v(3, 0), v(6, 0)}, false);
    ASSERT_EQ(c.num_segments(), 1);
    expect_near(c.segment(0)[1], v(5.0 / 3, 0));
    expect_near(c.segment(0)[2], v(7.0 / 3, 0));
    // Chords 1, 2, 1 around a U: at (1,0) v = (2 (1,0) + 1 (0,1)) / 3, at (1,2)
    // v = (1 (0,1) + 2 (-1,0)) / 3; the segment spans h = 2.
    c = bessel_overhauser_chain(std::vector<Vec3>{v(0, 0), v(1, 0), v(1, 2), v(0, 2)}, false);
    expect_near(c.segment(0)[1], v(1 + 4.0 / 9, 2.0 / 9));
    expect_near(c.segment(0)[2], v(1 + 4.0 / 9, 2 - 2.0 / 9));
    EXPECT_EQ(bessel_overhauser_chords(std::vector<Vec3>{v(0, 0), v(1, 0), v(1, 2), v(0, 2)}, false),
              std::vector<double>{2.0});
}

// Equal chords (unit steps along the axes) give Catmull-Rom, to rounding: Bessel's tangent is
// (m_{i-1} + m_i) / 2 there, Catmull-Rom's (p_{i+1} - p_{i-1}) / 2, the same sum in another order.
TEST(BesselOverhauser, WithEqualChordsIsCatmullRom) {
    const std::vector<Vec3> walk{v(0, 0), v(1, 0), v(1, 1), v(2, 1), v(2, 1, 1), v(2, 2, 1), v(1, 2, 1), v(1, 2, 0)};
    for (bool closed : {false, true}) {
        std::vector<Vec3> p = walk;
        if (closed) p = {v(0, 0), v(1, 0), v(1, 1), v(0, 1)};  // a unit square
        const BezierChain bo = bessel_overhauser_chain(p, closed), cr = catmull_rom_chain(p, closed);
        ASSERT_EQ(bo.points.size(), cr.points.size());
        for (size_t i = 0; i < bo.points.size(); ++i) expect_near(bo.points[i], cr.points[i], 4e-16);
    }
}

// C1 in the chord-length parameter: the chain's derivatives divided by each segment's chord.
TEST(BesselOverhauser, IsC1InTheChordLengthParameter) {
    for (bool closed : {false, true}) {
        const std::vector<Vec3> p = random_points(10, closed ? 3 : 4);
        const BezierChain c = bessel_overhauser_chain(p, closed);
        const std::vector<double> h = bessel_overhauser_chords(p, closed);
        const int n = c.num_segments();
        ASSERT_EQ(h.size(), static_cast<size_t>(n));
        for (int k = 0; k + 1 < n + (closed ? 1 : 0); ++k) {
            const Vec3 jump = leaving(c, (k + 1) % n) / h[(k + 1) % n] - arriving(c, k) / h[k];
            EXPECT_LE(jump.norm(), 1e-14) << "joint " << k;
            EXPECT_EQ(c.segment((k + 1) % n)[0], c.segment(k)[3]);
        }
    }
}

TEST(BesselOverhauser, RefusesCoincidentPoints) {
    try {
        bessel_overhauser_chain(std::vector<Vec3>{v(0, 0), v(1, 0), v(1, 0), v(2, 0)}, false);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "points 2 and 3 of 4 coincide: a chord of length 0 has no knot interval");
    }
    // Closed, the wrap-around chord counts too.
    EXPECT_THROW(bessel_overhauser_chain(std::vector<Vec3>{v(0, 0), v(1, 0), v(1, 1), v(0, 0)}, true), InputError);
}

TEST(SwpInterpolatingSplines, KeysWithAndWithoutParameters) {
    const CurveFile f = swp("tcb2 a 8 4 [0 0] [1 0 0.5 -0.25 1] [1 1] [2 1]\n"
                            "tcc3 b 4 3 [0 0 0] [1 0 0] [0 1 0]\n"
                            "ovh2 c 4 4 [0 0] [1 0] [3 0] [6 0]\n"
                            "ovc3 d 4 3 [0 0 0] [1 0 0] [0 1 1]\n");
    ASSERT_EQ(f.curves.size(), 4u);
    EXPECT_EQ(f.curves[0].type, CurveType::Tcb);
    ASSERT_EQ(f.curves[0].tcb.size(), 4u);
    EXPECT_EQ(f.curves[0].tcb[1], (TcbParameters{0.5, -0.25, 1}));
    EXPECT_EQ(f.curves[0].tcb[0], TcbParameters{});
    EXPECT_EQ(f.curves[1].type, CurveType::TcbClosed);
    EXPECT_TRUE(f.curves[1].tcb.empty());  // no key gives parameters: all 0
    EXPECT_TRUE(f.curves[1].closed());
    EXPECT_EQ(f.curves[1].chain().num_segments(), 3);
    EXPECT_EQ(f.curves[2].type, CurveType::BesselOverhauser);
    EXPECT_EQ(f.curves[2].chain().segment(0)[1], bessel_overhauser_chain(f.curves[2].control, false).segment(0)[1]);
    EXPECT_EQ(f.curves[3].type, CurveType::BesselOverhauserClosed);
    EXPECT_TRUE(f.curves[3].closed());
}

TEST(SwpInterpolatingSplines, ErrorsNameTheLineAndKey) {
    const auto message = [](const std::string& text) { return test::swp_error(text, "test.swp"); };
    EXPECT_EQ(message("tcb2 a 8 4\n[0 0] [1 0]\n[1 1 2 0 0] [2 1]\n"),
              "test.swp:3: key 3 of 4: tension 2.000000 is outside [-1, 1]");
    EXPECT_EQ(message("tcb2 a 8 4 [0 0] [1 0 1 1] [1 1] [2 1]\n"), "test.swp:1: point 2 of 4 has 4 numbers, expected 2 or 5");
    EXPECT_EQ(message("tcb2 a 8 4 [0 0] [1 0 0 0 0 0] [1 1] [2 1]\n"),
              "test.swp:1: point 2 of 4 has more than 5 numbers (or an unclosed '[')");
    EXPECT_EQ(message("tcb2 a 8 3 [0 0] [1 0] [1 1]\n"),
              "test.swp:1: tcb2 'a': an open TCB spline needs at least 4 keys, got 3");
    EXPECT_EQ(message("ovh2 a 8 4 [0 0] [1 0] [1 0] [2 1]\n"),
              "test.swp:1: ovh2 'a': points 2 and 3 of 4 coincide: a chord of length 0 has no knot interval");
    // Other records take no parameters.
    EXPECT_EQ(message("crm2 a 8 4 [0 0] [1 0 0 0 0] [1 1] [2 1]\n"),
              "test.swp:1: point 2 of 4 has more than 2 coordinates (or an unclosed '[')");
}
