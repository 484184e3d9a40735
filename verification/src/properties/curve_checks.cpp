#include "crossdiv/verification/properties/curve_checks.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "crossdiv/curves/bessel_overhauser.h"
#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/kochanek_bartels.h"
#include "crossdiv/curves/primitive_tessellation.h"
#include "crossdiv/curves/quaternion_bezier.h"
#include "crossdiv/datasets/bundled_curves.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/convergence_order.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "harness/check_inputs.h"
#include "kappa_checks.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
using nlohmann::json;

namespace {

using tolerances::kEps;
/// Parameters per segment at which evaluations are compared: the knots (t = 0, 1) and
/// interior points that are not binary fractions, so no algorithm is exact by accident.
constexpr int kSamplesPerSegment = 64;

double sample_t(int i) { return i == 0 ? 0.0 : i == kSamplesPerSegment ? 1.0 : (i - 0.5 * std::sqrt(0.5)) / kSamplesPerSegment; }

/// The rounding bound of kCurveRoundingUlps for degree d, derivative order `order`, scale s.
double rounding_bound(int d, int order) {
    double factor = tolerances::kCurveRoundingUlps * (d + 1) * kEps;
    if (order >= 1) factor *= std::max(d, 1);
    if (order >= 2) factor *= std::max(d - 1, 1);
    return factor;
}

double scale_of(const BezierChain& c) {
    const double s = bounding_box_diagonal(c.points);
    return s > 0 ? s : 1.0;  // a curve that is one point: absolute errors
}

std::vector<double> binomials(int d) {
    std::vector<double> b(d + 1, 1.0);
    for (int i = 1; i <= d; ++i) b[i] = b[i - 1] * (d - i + 1) / i;
    return b;
}

/// 2D convex hull (Andrew's monotone chain), counterclockwise, collinear points dropped.
std::vector<Vec3> hull_2d(std::vector<Vec3> p) {
    std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    auto cross = [](const Vec3& o, const Vec3& a, const Vec3& b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    std::vector<Vec3> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
        h[k++] = p[i];
    }
    h.resize(k - 1);
    return h;
}

/// How far x lies outside the 2D convex polygon `hull` (0 inside or on it).
double outside_2d(const std::vector<Vec3>& hull, const Vec3& x) {
    if (hull.size() == 1) return (x - hull[0]).head<2>().norm();
    if (hull.size() == 2) return point_segment_distance(Vec3(x.x(), x.y(), 0), hull[0], hull[1]);
    double out = 0;
    bool inside = true;
    for (size_t i = 0; i < hull.size(); ++i) {
        const Vec3 &a = hull[i], &b = hull[(i + 1) % hull.size()];
        const double c = (b.x() - a.x()) * (x.y() - a.y()) - (b.y() - a.y()) * (x.x() - a.x());
        if (c < 0) inside = false;
    }
    if (inside) return 0;
    out = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < hull.size(); ++i)
        out = std::min(out, point_segment_distance(Vec3(x.x(), x.y(), 0), hull[i], hull[(i + 1) % hull.size()]));
    return out;
}

class Checker {
public:
    explicit Checker(CheckReport& r) : r_(r) {}
    void add(const std::string& curve, const std::string& check, const std::string& reference, double measured,
             double tolerance, const std::string& unit, const std::string& note) {
        r_.checks.push_back({curve, check, reference, measured, tolerance, unit, note});
    }

private:
    CheckReport& r_;
};

/// de Casteljau vs the Bernstein sum on each segment; endpoints; partition of unity and the
/// convex hull (2D: distance outside the control points' hull; 3D: the point as the convex
/// combination with the Bernstein weights, which are checked nonnegative and summing to 1).
void check_bezier_properties(const BezierChain& c, const std::string& label, bool planar, Checker& out) {
    const double s = scale_of(c);
    const int d = c.degree;
    const std::vector<double> binom = binomials(d);
    double bern = 0, ends = 0, unity = 0, hull = 0, negative = 0, split = 0;
    for (int k = 0; k < c.num_segments(); ++k) {
        const auto seg = c.segment(k);
        ends = std::max({ends, (bezier_point(seg, 0.0) - seg.front()).norm(), (bezier_point(seg, 1.0) - seg.back()).norm()});
        const std::vector<Vec3> hull2 = planar ? hull_2d({seg.begin(), seg.end()}) : std::vector<Vec3>{};
        const BezierSplit halves = bezier_split(seg, 0.375);
        for (int i = 0; i <= kSamplesPerSegment; ++i) {
            const double t = sample_t(i);
            const Vec3 p = bezier_point(seg, t);
            bern = std::max(bern, (p - bernstein_point(seg, t)).norm());
            double sum = 0;
            Vec3 combo = Vec3::Zero();
            for (int j = 0; j <= d; ++j) {
                const double w = binom[j] * std::pow(t, j) * std::pow(1 - t, d - j);
                negative = std::max(negative, -w);
                sum += w;
                combo += w * seg[j];
            }
            unity = std::max(unity, std::abs(sum - 1));
            hull = std::max(hull, planar ? outside_2d(hull2, p) : (p - combo / sum).norm());
            const Vec3 q = t <= 0.375 ? bezier_point(halves.left, t / 0.375) : bezier_point(halves.right, (t - 0.375) / 0.625);
            split = std::max(split, (p - q).norm());
        }
    }
    const double tol = rounding_bound(d, 0);
    out.add(label, "bernstein-sum", "bernstein", bern / s, tol, "rel", "de Casteljau vs the Bernstein sum at 65 t per segment");
    out.add(label, "endpoint-interpolation", "analytic", ends / s, 0.0, "rel", "P(0) = p_0 and P(1) = p_d exactly");
    out.add(label, "partition-of-unity", "analytic", std::max(unity, negative), tol, "abs",
            "|sum B_i(t) - 1| and max(-B_i(t)) of the Bernstein weights");
    out.add(label, "convex-hull", "analytic", hull / s, tol, "rel",
            planar ? "distance outside the 2D convex hull of each segment's control points"
                   : "distance to the convex combination sum B_i(t) p_i with the checked weights");
    out.add(label, "split-halves", "analytic", split / s, 2 * tol, "rel",
            "the halves split at t = 3/8 reproduce the segment (two evaluations, twice the bound)");
}

/// The curves' reference (Eigen's Splines), or nullptr when this build has none.
const Implementation* spline_reference() {
    const std::vector<const Implementation*> refs = references_with(&Capabilities::spline_evaluation);
    return refs.empty() ? nullptr : refs.front();
}

/// Our de Casteljau (position, d1, d2 from one pass) against Eigen's Cox-de Boor.
void check_against_eigen(const Implementation& eigen, const CurveRecord& r, const BezierChain& c, const std::string& label,
                         Checker& out) {
    const double s = scale_of(c);
    double e[3] = {0, 0, 0};
    auto compare = [&](const adapters::SplineSamples& ref, const std::vector<ChainJet>& ours) {
        for (size_t i = 0; i < ours.size(); ++i) {
            e[0] = std::max(e[0], (ours[i].position - ref.position[i]).norm());
            e[1] = std::max(e[1], (ours[i].d1 - ref.d1[i]).norm());
            e[2] = std::max(e[2], (ours[i].d2 - ref.d2[i]).norm());
        }
    };
    std::string how;
    if (r.type == CurveType::BSpline) {
        // The whole spline at once, in the global parameter.
        std::vector<double> u;
        std::vector<ChainJet> ours;
        for (int k = 0; k < c.num_segments(); ++k)
            for (int i = 0; i <= kSamplesPerSegment; ++i) {
                u.push_back(k + sample_t(i));
                ours.push_back(chain_jet(c, k + sample_t(i)));
            }
        compare(eigen.evaluate_spline(SplineKind::UniformCubicBSpline, r.control, u), ours);
        how = "uniform cubic B-spline vs Eigen::Spline with knots 0..n+3";
    } else {
        // Segment by segment, each a clamped B-spline [0^(d+1), 1^(d+1)].
        for (int k = 0; k < c.num_segments(); ++k) {
            std::vector<double> t;
            std::vector<ChainJet> ours;
            for (int i = 0; i <= kSamplesPerSegment; ++i) {
                t.push_back(sample_t(i));
                const BezierJet j = bezier_jet(c.segment(k), sample_t(i));
                ours.push_back({j.position, j.d1, j.d2});
            }
            compare(eigen.evaluate_spline(SplineKind::ClampedBezier, c.segment(k), t), ours);
        }
        how = "each Bezier segment vs Eigen::Spline with knots [0^(d+1), 1^(d+1)]";
    }
    const char* names[3] = {"position", "d1", "d2"};
    for (int o = 0; o < 3; ++o)
        out.add(label, names[o], "eigen", e[o] / s, rounding_bound(c.degree, o), "rel", how + ", 65 samples per segment");
}

bool is_tcb(const CurveRecord& r) { return r.type == CurveType::Tcb || r.type == CurveType::TcbClosed; }
bool is_bessel(const CurveRecord& r) {
    return r.type == CurveType::BesselOverhauser || r.type == CurveType::BesselOverhauserClosed;
}

/// Continuity at each joint, measured, against what the representation dictates.
void check_continuity(const CurveRecord& r, const BezierChain& c, const std::string& label, Checker& out, json& table) {
    const int n = c.num_segments();
    const int joints = n - 1 + (r.wraps() ? 1 : 0);
    if (joints <= 0) return;
    const double s = scale_of(c);
    const bool tcb = is_tcb(r), bessel = is_bessel(r);
    const std::vector<double> chords = bessel ? bessel_overhauser_chords(r.control, r.wraps()) : std::vector<double>{};
    double gap[3] = {0, 0, 0}, predicted_error[3] = {0, 0, 0}, chord_velocity_jump = 0;
    for (int j = 0; j < joints; ++j) {
        const auto a = c.segment(j), b = c.segment((j + 1) % n);
        const BezierJet ea = bezier_jet(a, 1.0), sb = bezier_jet(b, 0.0);
        const Vec3 jump[3] = {sb.position - ea.position, sb.d1 - ea.d1, sb.d2 - ea.d2};
        for (int o = 0; o < 3; ++o) gap[o] = std::max(gap[o], jump[o].norm());
        if (tcb) {
            // The jump the key's continuity dictates; joint j is key j + 2 (segment k runs from
            // key k + 1).
            const size_t m = r.control.size(), i = (j + 2) % m;
            const TcbParameters p = r.tcb.empty() ? TcbParameters{} : r.tcb[i];
            const Vec3 want = kochanek_bartels_jump(r.control[(i + m - 1) % m], r.control[i], r.control[(i + 1) % m], p);
            predicted_error[1] = std::max(predicted_error[1], (jump[1] - want).norm());
        }
        if (bessel)  // velocities in the chord-length parameter: the chain's over each chord
            chord_velocity_jump = std::max(chord_velocity_jump, (sb.d1 / chords[(j + 1) % n] - ea.d1 / chords[j]).norm());
        if (r.type == CurveType::BezierChain) {
            // The jump the control points dictate: p = the input points around joint 3(j+1).
            const auto& p = r.control;
            const size_t m = 3 * (j + 1);
            const Vec3 want[3] = {Vec3::Zero(), 3.0 * ((p[m + 1] - p[m]) - (p[m] - p[m - 1])),
                                  6.0 * ((p[m + 2] - 2.0 * p[m + 1] + p[m]) - (p[m] - 2.0 * p[m - 1] + p[m - 2]))};
            for (int o = 0; o < 3; ++o) predicted_error[o] = std::max(predicted_error[o], (jump[o] - want[o]).norm());
        }
    }
    table.push_back({{"curve", label}, {"type", to_string(r.type)}, {"joints", joints}, {"c0_gap_rel", gap[0] / s},
                     {"c1_jump_rel", gap[1] / s}, {"c2_jump_rel", gap[2] / s}});
    if (r.type == CurveType::KappaClosed) return;  // G1 and G2, not C1: check_kappa_record
    const int d = c.degree;
    if (r.type == CurveType::BezierChain) {
        const char* names[3] = {"continuity-c0", "continuity-c1", "continuity-c2"};
        for (int o = 0; o < 3; ++o)
            out.add(label, names[o], "analytic", predicted_error[o] / s, o == 0 ? 0.0 : 4 * rounding_bound(d, o), "rel",
                    "derivative jump at each joint vs the jump its control points dictate");
        return;
    }
    if (tcb) {
        out.add(label, "continuity-c0", "analytic", gap[0] / s, 4 * rounding_bound(d, 0), "rel", "gap at each key");
        out.add(label, "continuity-c1", "analytic", predicted_error[1] / s, 4 * rounding_bound(d, 1), "rel",
                "derivative jump at each key vs (1-t) c ((1+b)(p_i - p_{i-1}) - (1-b)(p_{i+1} - p_i)), 0 where c = 0");
        return;
    }
    if (bessel) {
        out.add(label, "continuity-c0", "analytic", gap[0] / s, 4 * rounding_bound(d, 0), "rel", "gap at each point");
        // A velocity in the chord-length parameter has about unit length: its jump is absolute.
        out.add(label, "continuity-c1", "analytic", chord_velocity_jump, 4 * rounding_bound(d, 1), "abs",
                "velocity jump at each point in the chord-length parameter (Bessel-Overhauser: C1 there)");
        return;
    }
    // B-splines are C2, Catmull-Rom C1 (its C2 jump is reported in the table, not required).
    const int required = r.type == CurveType::BSpline ? 2 : 1;
    const char* names[3] = {"continuity-c0", "continuity-c1", "continuity-c2"};
    for (int o = 0; o <= required; ++o)
        out.add(label, names[o], "analytic", gap[o] / s, 4 * rounding_bound(d, o), "rel",
                std::string("jump at each joint (") + (required == 2 ? "B-spline: C2" : "Catmull-Rom: C1") + ")");
}

/// Whether the record's chain passes through its points (from p_1 open, every point closed).
bool interpolating(const CurveRecord& r) {
    switch (r.type) {
        case CurveType::CatmullRom:
        case CurveType::CatmullRomClosed:
        case CurveType::Tcb:
        case CurveType::TcbClosed:
        case CurveType::BesselOverhauser:
        case CurveType::BesselOverhauserClosed: return true;
        default: return false;
    }
}

/// An interpolating spline passes exactly through its points: segment k starts at p_{k+1} and
/// ends at p_{k+2} (mod n when closed), the points themselves.
void check_interpolation(const CurveRecord& r, const BezierChain& c, const std::string& label, Checker& out) {
    const size_t n = r.control.size();
    double through = 0;
    for (int k = 0; k < c.num_segments(); ++k) {
        through = std::max(through, (bezier_point(c.segment(k), 0.0) - r.control[(k + 1) % n]).norm());
        through = std::max(through, (bezier_point(c.segment(k), 1.0) - r.control[(k + 2) % n]).norm());
    }
    out.add(label, "interpolation", "analytic", through / scale_of(c), 0.0, "rel",
            std::string(to_string(r.type)) + " passes exactly through p_1 .. p_{n-2} (closed: every point)");
}

/// A TCB record whose parameters are all 0 is Catmull-Rom's chain, bit for bit.
void check_tcb_reduction(const CurveRecord& r, const BezierChain& c, const std::string& label, Checker& out) {
    for (const TcbParameters& p : r.tcb)
        if (!(p == TcbParameters{})) return;
    const BezierChain cr = catmull_rom_chain(r.control, r.wraps());
    double e = 0;
    for (size_t i = 0; i < c.points.size(); ++i) e = std::max(e, (c.points[i] - cr.points[i]).norm());
    out.add(label, "tcb-zero-is-catmull-rom", "analytic", e / scale_of(c), 0.0, "rel",
            "tension, continuity and bias 0: every Bezier control point equals Catmull-Rom's bit for bit");
}

/// Overhauser's own construction of a Bessel-Overhauser segment, without tangents or Bezier
/// points: on the chord from p_i to p_{i+1} (chord-length knots), the linear blend of the
/// parabola through p_{i-1}, p_i, p_{i+1} and the one through p_i, p_{i+1}, p_{i+2}, each in
/// Lagrange form on its three knots. The blend is a cubic with the Hermite segment's end points
/// and end velocities (the first parabola's derivative at u_i is Bessel's tangent), so it is the
/// same curve; a tangent weighted by the wrong intervals differs wherever the chords are uneven.
/// `w` holds p_{i-1} .. p_{i+2} relative to p_i (so rounding is relative to the window's
/// size, not to the distance from the origin), `h` the three chords, `t` in [0, 1].
Vec3 overhauser_blend(const std::array<Vec3, 4>& w, const std::array<double, 3>& h, double t) {
    const double u[4] = {0, h[0], h[0] + h[1], h[0] + h[1] + h[2]};
    const double x = h[0] + t * h[1];
    const auto parabola = [&](int first) {  // through w[first..first+2] at u[first..first+2]
        Vec3 sum = Vec3::Zero();
        for (int a = first; a < first + 3; ++a) {
            double basis = 1;
            for (int b = first; b < first + 3; ++b)
                if (b != a) basis *= (x - u[b]) / (u[a] - u[b]);
            sum += basis * w[a];
        }
        return sum;
    };
    return (1 - t) * parabola(0) + t * parabola(1);
}

/// Every segment of a Bessel-Overhauser chain at 9 parameters against overhauser_blend.
void check_overhauser_blend(const CurveRecord& r, const BezierChain& c, const std::string& label, Checker& out) {
    const size_t n = r.control.size();
    double worst = 0, allowed = 0;
    for (int k = 0; k < c.num_segments(); ++k) {
        const size_t i = static_cast<size_t>(k) + 1;  // segment k runs from point k + 1, as Catmull-Rom's
        const Vec3& origin = r.control[i % n];
        std::array<Vec3, 4> w;
        for (size_t j = 0; j < 4; ++j) w[j] = r.control[(i + n - 1 + j) % n] - origin;
        const std::array<double, 3> h{(w[1] - w[0]).norm(), (w[2] - w[1]).norm(), (w[3] - w[2]).norm()};
        // The Lagrange weights grow with the ratio of the window's chords, and so does their
        // rounding: 64 ulps per unit of that ratio, relative to the chain's size.
        const double ratio = std::max({h[0], h[1], h[2]}) / std::min({h[0], h[1], h[2]});
        allowed = std::max(allowed, rounding_bound(c.degree, 0) * (1 + ratio));
        for (int s = 1; s <= 9; ++s) {
            const double t = s / 10.0;
            worst = std::max(worst, (bezier_point(c.segment(k), t) - origin - overhauser_blend(w, h, t)).norm());
        }
    }
    out.add(label, "overhauser-blend", "analytic", worst / scale_of(c), allowed, "rel",
            "each segment at t = 0.1 .. 0.9 against the linear blend of the two parabolas through its window's points "
            "on chord-length knots (Overhauser's construction, evaluated in Lagrange form)");
}

/// A camera path's orientations: every slerp of its de Casteljau levels against Eigen's, the
/// unit norm, the ends, the rotation matrices (against Eigen's, orthonormal); one row of the
/// report's figure (positions and frames at the tessellation's parameters).
void check_orientations(const CurveRecord& r, const std::string& label, const Polyline& uniform, Checker& out,
                        json& rows) {
    const QuaternionChain q = quaternion_chain(r.orientations);
    double slerp_error = 0, norm_error = 0, ends = 0, matrix_error = 0, orthonormality = 0;
    const auto matrix_checks = [&](const Quat& x) {
        const Eigen::Matrix3d m = rotation_matrix(x);
        matrix_error = std::max(matrix_error, (m - x.toRotationMatrix()).cwiseAbs().maxCoeff());
        orthonormality = std::max(orthonormality, (m.transpose() * m - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff());
    };
    for (int k = 0; k < q.num_segments(); ++k) {
        const std::span<const Quat> seg = q.segment(k);
        for (int i = 0; i <= kSamplesPerSegment; ++i) {
            const double t = sample_t(i);
            const std::vector<std::vector<Quat>> levels = quaternion_casteljau_levels(seg, t);
            for (size_t l = 1; l < levels.size(); ++l)
                for (size_t j = 0; j < levels[l].size(); ++j)
                    slerp_error = std::max(slerp_error, (levels[l][j].coeffs() -
                                                         levels[l - 1][j].slerp(t, levels[l - 1][j + 1]).coeffs()).norm());
            const Quat at = levels.back()[0];
            norm_error = std::max(norm_error, std::abs(at.norm() - 1));
            matrix_checks(at);
            if (i == 0) ends = std::max(ends, (at.coeffs() - seg[0].coeffs()).norm());
            if (i == kSamplesPerSegment)
                ends = std::max(ends, std::min((at.coeffs() - seg[3].coeffs()).norm(), (at.coeffs() + seg[3].coeffs()).norm()));
        }
    }
    out.add(label, "slerp", "eigen", slerp_error, tolerances::kSlerpAgreement, "abs",
            "every slerp of the de Casteljau levels vs Eigen::Quaternion::slerp, 65 t per segment");
    out.add(label, "quaternion-unit-norm", "analytic", norm_error, tolerances::kQuaternionNormUlps * 3 * kEps, "abs",
            "| |q(t)| - 1 | along the cubic quaternion chain");
    out.add(label, "quaternion-ends", "analytic", ends, 0.0, "abs",
            "each piece starts at its first control quaternion and ends at its last (or its negative: the same rotation)");
    out.add(label, "rotation-matrix", "eigen", matrix_error, 4 * kEps, "abs",
            "rotation matrix of q(t) vs Eigen's toRotationMatrix");
    out.add(label, "orientation-frames", "analytic", orthonormality, tolerances::kFrameOrthonormality, "abs",
            "R(q(t))^T R(q(t)) - I: the frames along the path are orthonormal");
    json points = json::array(), frames = json::array();
    for (int i = 0; i < uniform.size(); ++i) {
        const Vec3& p = uniform.positions[i];
        const Eigen::Matrix3d m = rotation_matrix(q.at(uniform.params[i]));
        points.push_back({p.x(), p.y(), p.z()});
        frames.push_back({{m(0, 0), m(1, 0), m(2, 0)}, {m(0, 1), m(1, 1), m(2, 1)}, {m(0, 2), m(1, 2), m(2, 2)}});
    }
    rows.push_back({{"curve", label}, {"points", points}, {"frames", frames}});
}

/// The record's keys and uniform tessellation, for the report's figure of the TCB family.
json shape_row(const CurveRecord& r, const std::string& label, const Polyline& p) {
    json keys = json::array(), points = json::array(), params = json::array();
    for (const Vec3& k : r.control) keys.push_back({k.x(), k.y()});
    for (const Vec3& x : p.positions) points.push_back({x.x(), x.y()});
    for (const TcbParameters& t : r.tcb) params.push_back({t.tension, t.continuity, t.bias});
    return {{"curve", label}, {"type", to_string(r.type)}, {"keys", keys}, {"tcb", params}, {"points", points}};
}

/// Each basis conversion reproduces the seed's matrix form G B T(t).
void check_conversion(const CurveRecord& r, const BezierChain& c, const std::string& label, Checker& out) {
    const CubicBasis basis = r.type == CurveType::BSpline ? CubicBasis::BSpline : CubicBasis::CatmullRom;
    const size_t n = r.control.size();
    double e = 0;
    for (int k = 0; k < c.num_segments(); ++k) {
        std::vector<Vec3> pts;
        tessellate_cubic_spline_segment(r.control[k % n], r.control[(k + 1) % n], r.control[(k + 2) % n],
                                        r.control[(k + 3) % n], basis_matrix(basis), kSamplesPerSegment, true, pts);
        for (int i = 0; i <= kSamplesPerSegment; ++i)
            e = std::max(e, (bezier_point(c.segment(k), static_cast<double>(i) / kSamplesPerSegment) - pts[i]).norm());
    }
    out.add(label, "basis-conversion", "matrix-form", e / scale_of(c), rounding_bound(3, 0), "rel",
            std::string(to_string(basis)) + " -> Bezier vs G B T(t) at 65 t per segment");
}

void check_frames(const CurveRecord& r, const Polyline& p, const std::string& label, Checker& out, json& closure) {
    for (FrameMethod m : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
        std::vector<Frame> f = curve_frames(p.positions, p.tangents, m);
        out.add(label, std::string("frames-") + std::string(to_string(m)), "analytic", max_orthonormality_error(f),
                tolerances::kFrameOrthonormality, "abs", "max deviation of (T, N, B) from orthonormal, right-handed");
        if (!r.closed()) continue;
        const double mismatch = closure_angle(f);
        distribute_closure(p.positions, f, mismatch);
        closure.push_back({{"curve", label}, {"method", to_string(m)}, {"mismatch_deg", mismatch * 180 / M_PI},
                           {"after_distribution_deg", closure_angle(f) * 180 / M_PI}});
        out.add(label, std::string("closure-") + std::string(to_string(m)), "analytic", std::abs(closure_angle(f)), tolerances::kFrameClosureRad,
                "rad", "frame mismatch after one lap once the measured angle is distributed along arc length");
    }
}

/// A curve record's tessellations and their measured deviation: a spline's chain, or a
/// primitive's closed form (tessellate_record tells them apart; the deviation is measured
/// against the exact curve either way).
struct Tessellator {
    const CurveRecord& record;
    std::optional<BezierChain> chain;  ///< a spline's

    explicit Tessellator(const CurveRecord& r) : record(r) {
        if (r.type != CurveType::Primitive) chain = r.chain();
    }
    Polyline uniform(int steps) const {
        return chain ? tessellate_uniform(*chain, steps) : sample_primitive(record.primitive, steps);
    }
    Polyline by_angle(double angle) const {
        TessellationOptions o;
        o.mode = TessellationMode::Angle;
        o.angle_tol = angle;
        return tessellate_record(record, o);
    }
    Polyline by_distance(double tol) const {
        return chain ? tessellate_distance(*chain, tol) : tessellate_primitive_distance(record.primitive, tol);
    }
    double deviation(const Polyline& p) const {
        return chain ? chordal_deviation(*chain, p).max : primitive_deviation(record.primitive, p).max;
    }
    double optimal_edges(double tol) const {
        return chain ? flattening_estimate(*chain, tol) : primitive_flattening_estimate(record.primitive, tol);
    }
};

/// Uniform steps (per segment of a spline): the fewest whose measured deviation meets tol.
int fewest_uniform_steps(const Tessellator& t, double tol) {
    int hi = 1;
    while (t.deviation(t.uniform(hi)) > tol) hi *= 2;
    int lo = hi / 2;  // fails (or 0)
    while (hi - lo > 1) {
        const int mid = (lo + hi) / 2;
        (t.deviation(t.uniform(mid)) <= tol ? hi : lo) = mid;
    }
    return hi;
}

}  // namespace

std::vector<TessellationRow> tessellation_study(const CurveRecord& r, const std::string& label, std::span<const double> tols) {
    std::vector<TessellationRow> rows;
    const Tessellator t(r);
    for (double tol : tols) {
        TessellationRow row;
        row.curve = label;
        row.tol = tol;
        row.optimal_edges = t.optimal_edges(tol);
        row.uniform_steps = fewest_uniform_steps(t, tol);
        const Polyline u = t.uniform(row.uniform_steps);
        row.uniform_edges = u.size() - 1;
        row.uniform_dev = t.deviation(u);
        const Polyline d = t.by_distance(tol);
        row.distance_edges = d.size() - 1;
        row.distance_dev = t.deviation(d);
        row.has_wang = t.chain.has_value();
        if (t.chain) {  // Wang's bound is on a Bezier segment's control points
            const Polyline w = tessellate_uniform(*t.chain, wang_intervals(*t.chain, tol));
            row.wang_edges = w.size() - 1;
            row.wang_dev = t.deviation(w);
        }
        // The largest angle tolerance that meets tol: halve from 90 degrees until it does,
        // then bisect between the last failing and the first passing value.
        double fail = M_PI, pass = 0;
        for (double a = M_PI / 2; a > 1e-6; a /= 2) {
            if (t.deviation(t.by_angle(a)) <= tol) {
                pass = a;
                break;
            }
            fail = a;
        }
        if (pass > 0) {
            for (int it = 0; it < 12; ++it) {
                const double mid = 0.5 * (pass + fail);
                (t.deviation(t.by_angle(mid)) <= tol ? pass : fail) = mid;
            }
            const Polyline a = t.by_angle(pass);
            row.angle_edges = a.size() - 1;
            row.angle_dev = t.deviation(a);
            row.angle_tol_deg = pass * 180 / M_PI;
            row.angle_reached = true;
        } else {
            const Polyline a = t.by_angle(1e-6);  // the 10-level cap: the finest it goes
            row.angle_edges = a.size() - 1;
            row.angle_dev = t.deviation(a);
        }
        rows.push_back(row);
    }
    return rows;
}

json to_json(const TessellationRow& row) {
    const json null;
    return {{"curve", row.curve}, {"tol", row.tol}, {"uniform_edges", row.uniform_edges},
            {"uniform_steps", row.uniform_steps}, {"uniform_dev", row.uniform_dev},
            {"angle_edges", row.angle_edges}, {"angle_dev", row.angle_dev},
            {"angle_tol_deg", row.angle_tol_deg}, {"angle_reached", row.angle_reached},
            {"distance_edges", row.distance_edges}, {"distance_dev", row.distance_dev},
            {"wang_edges", row.has_wang ? json(row.wang_edges) : null}, {"wang_dev", row.has_wang ? json(row.wang_dev) : null},
            {"optimal_edges", row.optimal_edges}};
}

double primitive_size(const Primitive& p) { return bounding_box_diagonal(sample_primitive(p, 256).positions); }

HelixFrameStudy helix_frame_study() {
    const double b = 1.0 / (2 * M_PI), c = std::sqrt(1 + b * b), tau = b / (c * c);
    const double end = 4 * M_PI;  // two turns
    HelixFrameStudy study;
    for (int steps = 16; steps <= 1024; steps *= 2) {
        std::vector<Vec3> pos, tan;
        std::vector<Vec3> exact;
        for (int i = 0; i <= steps; ++i) {
            const double s = end * i / steps;
            pos.emplace_back(std::cos(s), std::sin(s), b * s);
            tan.push_back(Vec3(-std::sin(s), std::cos(s), b) / c);
            const Vec3 n(-std::cos(s), -std::sin(s), 0), bn = Vec3(b * std::sin(s), -b * std::cos(s), 1) / c;
            const double theta = -tau * c * s;  // -tau times arc length
            exact.push_back(std::cos(theta) * n + std::sin(theta) * bn);
        }
        const Vec3 b0 = Vec3(0, -b, 1) / c;  // the exact binormal at s = 0: N_0 = B_0 x T_0 is exact
        HelixFrameRow row{steps, end / steps, 0, 0};
        for (FrameMethod m : {FrameMethod::Recursive, FrameMethod::DoubleReflection}) {
            const std::vector<Frame> f = curve_frames(pos, tan, m, b0);
            double e = 0;
            // atan2, not acos: acos of a dot product near 1 cannot resolve angles below ~1e-8.
            for (int i = 0; i <= steps; ++i) e = std::max(e, std::atan2(f[i].N.cross(exact[i]).norm(), f[i].N.dot(exact[i])));
            (m == FrameMethod::Recursive ? row.recursive_error : row.rmf_error) = e;
        }
        study.rows.push_back(row);
    }
    std::vector<double> h, recursive, rmf;
    for (const HelixFrameRow& r : study.rows) {
        h.push_back(r.h);
        recursive.push_back(r.recursive_error);
        rmf.push_back(r.rmf_error);
    }
    study.recursive_order = fitted_order(h, recursive);
    study.rmf_order = fitted_order(h, rmf);
    return study;
}

namespace {

/// Tessellation guarantees at one tolerance per curve (1e-3 of its size): the distance mode
/// (and a spline's Wang counts) must meet it as measured, the distance mode within
/// kDistanceModeEdgesOverOptimal of N*.
void check_tessellation(const CurveRecord& r, const std::string& label, double size, Checker& out, json& tess) {
    const double tol = 1e-3 * size;
    for (const TessellationRow& row : tessellation_study(r, label, std::span<const double>(&tol, 1))) {
        out.add(label, "distance-mode", "analytic", row.distance_dev, row.tol, "abs",
                "measured deviation of the distance-adaptive polyline (" + std::to_string(row.distance_edges) + " edges)");
        if (row.optimal_edges > 0)
            out.add(label, "distance-mode-edges", "flattening estimate", row.distance_edges / row.optimal_edges,
                    tolerances::kDistanceModeEdgesOverOptimal, "ratio",
                    std::to_string(row.distance_edges) + " edges over N* = " + std::to_string(row.optimal_edges) +
                        ", the fewest any polyline within the tolerance needs");
        if (row.has_wang)
            out.add(label, "wang-bound", "analytic", row.wang_dev, row.tol, "abs",
                    "measured deviation with Wang's per-segment counts (" + std::to_string(row.wang_edges) + " edges)");
        tess.push_back(to_json(row));
    }
}

}  // namespace

CheckReport check_curve_file(const CurveFile& file, const std::string& input) {
    CheckReport report;
    report.input = input;
    Checker out(report);
    json tess = json::array(), continuity = json::array(), closure = json::array(), shapes = json::array(),
         orientations = json::array(), kappa = json::array();
    for (size_t i = 0; i < file.curves.size(); ++i) {
        const CurveRecord& r = file.curves[i];
        const std::string label = r.label(static_cast<int>(i));
        report.subjects.push_back(label);
        const Polyline uniform = tessellate_record(r, {});
        if (r.type == CurveType::Primitive) {
            // Against the exact curve: the samples lie on it, and the tangent is the exact one.
            double on = 0, tangent = 0;
            for (int k = 0; k < uniform.size(); ++k) {
                const bool wrapped = r.closed() && k + 1 == uniform.size();  // sampled at s = 0
                const ChainJet j = r.primitive.jet(wrapped ? 0.0 : uniform.params[k]);
                on = std::max(on, (uniform.positions[k] - j.position).norm());
                tangent = std::max(tangent, (uniform.tangents[k] - j.d1.normalized()).norm());
            }
            // The closed forms are sums of up to three sines times the size: a few ulps of
            // the largest coordinate, which is at most 3 sizes (the trefoil).
            const double size = bounding_box_diagonal(uniform.positions);
            out.add(label, "samples-on-curve", "exact", on / size, 8 * kEps, "rel",
                    "uniform samples vs the closed form (the last sample of a closed curve is the first)");
            out.add(label, "tangent", "exact", tangent, 8 * kEps, "abs", "unit tangent vs the closed-form derivative");
            check_frames(r, uniform, label, out, closure);
            check_tessellation(r, label, primitive_size(r.primitive), out, tess);
            continue;
        }
        const BezierChain c = r.chain();
        const bool planar = r.dim == 2;
        check_bezier_properties(c, label, planar, out);
        if (const Implementation* eigen = spline_reference()) check_against_eigen(*eigen, r, c, label, out);
        check_continuity(r, c, label, out, continuity);
        if (r.type == CurveType::BSpline || r.type == CurveType::CatmullRom || r.type == CurveType::CatmullRomClosed)
            check_conversion(r, c, label, out);
        if (interpolating(r)) check_interpolation(r, c, label, out);
        if (is_tcb(r)) check_tcb_reduction(r, c, label, out);
        if (is_bessel(r)) check_overhauser_blend(r, c, label, out);
        if (is_tcb(r) || is_bessel(r)) shapes.push_back(shape_row(r, label, uniform));
        if (r.type == CurveType::CameraPath) check_orientations(r, label, uniform, out, orientations);
        if (r.type == CurveType::KappaClosed) kappa.push_back(check_kappa_record(r, label, uniform, report));
        check_frames(r, uniform, label, out, closure);
        check_tessellation(r, label, scale_of(c), out, tess);
    }
    report.tables["tessellation"] = tess;
    report.tables["continuity"] = continuity;
    report.tables["closure"] = closure;
    if (!shapes.empty()) report.tables["shapes"] = shapes;
    if (!orientations.empty()) report.tables["orientations"] = orientations;
    if (!kappa.empty()) report.tables["kappa"] = kappa;
    return report;
}

CheckReport check_synthetic() {
    CheckReport report;
    report.input = "curves:synthetic";
    Checker out(report);
    std::mt19937 rng(20261122);
    std::uniform_real_distribution<double> coord(-1, 1);
    json degrees = json::array();
    for (int d = 1; d <= 20; ++d) {
        std::vector<Vec3> ctrl(d + 1);
        for (Vec3& p : ctrl) p = Vec3(coord(rng), coord(rng), coord(rng));
        const BezierChain c = single_bezier(ctrl);
        const std::string label = "degree " + std::to_string(d);
        report.subjects.push_back(label);
        const size_t first = report.checks.size();
        check_bezier_properties(c, label, false, out);
        json row = {{"degree", d}};
        for (size_t k = first; k < report.checks.size(); ++k) row[report.checks[k].check] = report.checks[k].measured;
        if (const Implementation* eigen = spline_reference(); eigen && d <= 10) {
            CurveRecord r;
            r.type = CurveType::Bezier;
            r.control = ctrl;
            const size_t before = report.checks.size();
            check_against_eigen(*eigen, r, c, label, out);
            for (size_t k = before; k < report.checks.size(); ++k) row["eigen_" + report.checks[k].check] = report.checks[k].measured;
        }
        row["bound_position"] = rounding_bound(d, 0);
        degrees.push_back(row);
    }
    report.tables["degrees"] = degrees;

    // Quaternion de Casteljau on a great circle (rotations about one axis, consecutive angles
    // less than pi apart) is the rotation by the planar de Casteljau of the angles; with two
    // control points the angle grows linearly in t (constant angular velocity).
    std::uniform_real_distribution<double> angle_step(-2.5, 2.5);
    const Vec3 axis = Vec3(1, -2, 0.5).normalized();
    const auto about = [&](double a) {
        return Quat(std::cos(a / 2), std::sin(a / 2) * axis.x(), std::sin(a / 2) * axis.y(), std::sin(a / 2) * axis.z());
    };
    double great_circle = 0, angular_velocity = 0;
    for (int d = 1; d <= 10; ++d) {
        std::vector<Quat> c{about(0.3)};
        std::vector<Vec3> planar{Vec3(0.3, 0, 0)};
        for (int i = 0; i < d; ++i) {
            planar.emplace_back(planar.back().x() + angle_step(rng), 0, 0);
            c.push_back(about(planar.back().x()));
        }
        for (int i = 0; i <= kSamplesPerSegment; ++i) {
            const Quat q = quaternion_bezier_point(c, sample_t(i)), want = about(bezier_point(planar, sample_t(i)).x());
            great_circle = std::max(great_circle, std::min((q.coeffs() - want.coeffs()).norm(), (q.coeffs() + want.coeffs()).norm()) / d);
        }
        const std::vector<Quat> two{c.front(), c.back()};
        const double total = rotation_angle_between(two[0], two[1]);
        for (int i = 0; i <= kSamplesPerSegment; ++i)
            angular_velocity = std::max(angular_velocity, std::abs(rotation_angle_between(two[0], quaternion_bezier_point(two, sample_t(i))) -
                                                                   sample_t(i) * total));
    }
    report.subjects.push_back("quaternion curves");
    out.add("quaternion curves", "great-circle", "exact", great_circle, tolerances::kQuaternionNormUlps * 2 * kEps, "abs",
            "degrees 1..10 of rotations about one axis vs the rotation by the planar de Casteljau of the angles, per degree");
    out.add("quaternion curves", "constant-angular-velocity", "exact", angular_velocity, 1e-14, "rad",
            "two control quaternions: the angle turned at t vs t times the whole angle (pi-sized angles, a few ulps)");

    report.tables["kappa_hard_cases"] = kappa_hard_case_study();

    const HelixFrameStudy h = helix_frame_study();
    json rows = json::array();
    for (const HelixFrameRow& r : h.rows)
        rows.push_back({{"steps", r.steps}, {"h", r.h}, {"recursive_error_rad", r.recursive_error}, {"rmf_error_rad", r.rmf_error}});
    report.tables["frames"] = {{"curve", "helix (cos s, sin s, s / 2 pi), two turns"}, {"rows", rows},
                               {"recursive_order", h.recursive_order}, {"rmf_order", h.rmf_order}};
    // Orders as checks: measured is the shortfall below the required order (0 when met; NaN,
    // which fails, when no order could be fitted).
    const auto shortfall = [](double required, double order) { return order >= required ? 0.0 : required - order; };
    out.add("helix", "rmf-order", "exact", shortfall(tolerances::kDoubleReflectionMinOrder, h.rmf_order), 0.0, "order",
            "double reflection: fitted order " + std::to_string(h.rmf_order) + ", required >= " +
                std::to_string(tolerances::kDoubleReflectionMinOrder));
    out.add("helix", "recursive-order", "exact",
            shortfall(tolerances::kRecursiveFrameMinOrder, h.recursive_order), 0.0, "order",
            "recursive frame: fitted order " + std::to_string(h.recursive_order) + ", required >= " +
                std::to_string(tolerances::kRecursiveFrameMinOrder));
    return report;
}

namespace {

std::vector<std::string> bundled_curve_names() {
    std::vector<std::string> names;
    for (const auto& b : datasets::bundled_curves()) names.push_back(b.name);
    return names;
}

const detail::CheckInputFamily& curve_inputs() {
    static const detail::CheckInputFamily f{"curves", "curve", {".swp", ".bzc"}, bundled_curve_names, datasets::course_curve_files};
    return f;
}

}  // namespace

std::vector<std::string> expand_curve_inputs(const std::vector<std::string>& specs) {
    return detail::expand_check_inputs(curve_inputs(), specs);
}

CurveFile load_curve_input(const std::string& spec) {
    if (spec.starts_with("curve:")) return datasets::bundled_curve_file(spec.substr(6));
    if (spec.starts_with("curves:")) throw InputError("'" + spec + "' is a collection, not one curve file");
    return read_curve_file(spec);
}

}  // namespace crossdiv::verification
