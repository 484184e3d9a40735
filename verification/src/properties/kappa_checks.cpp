#include "kappa_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/kappa_curve.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {
using nlohmann::json;

namespace {

/// Samples of the signed curvature per piece, for the report's plot.
constexpr int kCurvatureSamplesPerPiece = 16;

/// What a converged (or stopped) kappa-curve measures against its points.
struct KappaMeasures {
    double interpolation = 0;      ///< max |c_i(t_i) - p_i| / diagonal
    double curvature_maximum = 0;  ///< max |c_i(argmax |kappa_i|) - p_i| / diagonal
    double tangent_angle = 0;      ///< max angle between the tangents at a joint (rad)
    double curvature_jump = 0;     ///< max | |kappa_left| - |kappa_right| | / max(|kappa_left|, |kappa_right|)
    int inflections = 0;           ///< joints where the signed curvature flips
    double sharpest = 0;           ///< max |kappa| times the diagonal (a cusp at a point shows as a large value)
};

KappaMeasures measure(const KappaCurve& k, std::span<const Vec3> p) {
    KappaMeasures m;
    const double diagonal = bounding_box_diagonal({p.begin(), p.end()});
    const int n = static_cast<int>(p.size());
    for (int i = 0; i < n; ++i) {
        const auto piece = k.chain.segment(i), after = k.chain.segment((i + 1) % n);
        const double peak = quadratic_max_curvature_param(piece);
        m.interpolation = std::max(m.interpolation, (bezier_point(piece, k.params[i]) - p[i]).norm() / diagonal);
        m.curvature_maximum = std::max(m.curvature_maximum, (bezier_point(piece, peak) - p[i]).norm() / diagonal);
        m.sharpest = std::max(m.sharpest, std::abs(quadratic_signed_curvature(piece, peak)) * diagonal);
        const Vec3 in = piece[2] - piece[1], out = after[1] - after[0];
        m.tangent_angle = std::max(m.tangent_angle, std::atan2(in.cross(out).norm(), in.dot(out)));
        const double left = quadratic_signed_curvature(piece, 1.0), right = quadratic_signed_curvature(after, 0.0);
        const double larger = std::max(std::abs(left), std::abs(right));
        if (larger > 0) m.curvature_jump = std::max(m.curvature_jump, std::abs(std::abs(left) - std::abs(right)) / larger);
        if (left * right < 0) ++m.inflections;
    }
    return m;
}

json measures_json(const KappaMeasures& m) {
    return {{"interpolation", m.interpolation},   {"curvature_maximum", m.curvature_maximum},
            {"tangent_angle", m.tangent_angle},
            {"curvature_jump", m.curvature_jump}, {"inflections", m.inflections},
            {"sharpest", m.sharpest}};
}

json xy(const Vec3& v) { return {v.x(), v.y()}; }

}  // namespace

json check_kappa_record(const CurveRecord& r, const std::string& label, const Polyline& uniform, CheckReport& report) {
    const std::shared_ptr<const KappaCurve> solved =
        r.kappa ? r.kappa : std::make_shared<const KappaCurve>(converged_kappa_curve(r.control));
    const KappaCurve& k = *solved;
    const KappaMeasures m = measure(k, r.control);
    const auto add = [&](const char* check, double measured, double tolerance, const char* unit, const std::string& note) {
        report.checks.emplace_back(label, check, "analytic", measured, tolerance, unit, note);
    };
    add("interpolation", m.interpolation, tolerances::kKappaInterpolation, "rel",
        "|c_i(t_i) - p_i|: each point on its piece at the parameter of the last solve");
    add("curvature-maximum", m.curvature_maximum, tolerances::kKappaCurvatureMaximum, "rel",
        "|c_i(s_i) - p_i| with s_i where piece i is slowest (its |curvature| maximum), found from the piece alone");
    add("continuity-g1", m.tangent_angle, tolerances::kKappaTangentAngle, "rad",
        "angle between the tangents at each joint (both along c_{i,1} c_{i+1,1})");
    add("continuity-g2", m.curvature_jump, tolerances::kKappaCurvatureContinuity, "rel",
        "| |kappa| left - |kappa| right | / the larger at each joint; " + std::to_string(m.inflections) +
            " inflection joints, where the sign flips");

    json points = json::array(), control = json::array(), curve = json::array(), curvature = json::array(),
         at = json::array();
    for (const Vec3& x : r.control) points.push_back(xy(x));
    for (const Vec3& x : k.chain.points) control.push_back(xy(x));
    for (const Vec3& x : uniform.positions) curve.push_back(xy(x));
    for (int i = 0; i < k.chain.num_segments(); ++i) {
        for (int s = 0; s <= kCurvatureSamplesPerPiece; ++s) {
            const double t = static_cast<double>(s) / kCurvatureSamplesPerPiece;
            curvature.push_back({i + t, quadratic_signed_curvature(k.chain.segment(i), t)});
        }
        at.push_back(i + k.params[i]);
    }
    return {{"curve", label},         {"points", points},         {"control", control},
            {"curve_points", curve},  {"curvature", curvature},   {"point_params", at},
            {"iterations", k.iterations()}, {"converged", k.converged}, {"error_estimate", k.error_estimate},
            {"contraction", k.contraction}, {"residuals", k.residuals}, {"measures", measures_json(m)}};
}

json kappa_hard_case_study() {
    struct Case {
        std::string family, name;
        std::vector<Vec3> points;
    };
    std::vector<Case> cases;
    for (double degrees : {90.0, 30.0, 10.0, 3.0, 1.0}) {
        const double h = 10 * std::tan(degrees * M_PI / 360);  // the spike's half-width at its base
        cases.push_back({"spike", std::to_string(static_cast<int>(degrees)) + " deg",
                         {Vec3(0, 0, 0), Vec3(10, h, 0), Vec3(0, 2 * h, 0), Vec3(-3, h, 0)}});
    }
    for (double off : {1e-2, 1e-4, 1e-6, 1e-8}) {
        char name[32];
        std::snprintf(name, sizeof name, "%g off the line", off);
        cases.push_back({"nearly collinear", name,
                         {Vec3(0, 0, 0), Vec3(1, off, 0), Vec3(2, 0, 0), Vec3(3, off, 0), Vec3(4, 0, 0), Vec3(2, 2, 0)}});
    }
    // A spike whose back point is close: the same fixed point exists, but the iteration
    // contracts by about 0.99 per step, and at 0.6 degrees by less than the cap allows.
    cases.push_back({"spike, close back point", "3.4 deg", {Vec3(0, 0, 0), Vec3(10, 0.3, 0), Vec3(0, 0.6, 0), Vec3(-2, 0.3, 0)}});
    cases.push_back({"spike, close back point", "0.6 deg", {Vec3(0, 0, 0), Vec3(10, 0.05, 0), Vec3(0, 0.1, 0), Vec3(-2, 0.05, 0)}});
    json rows = json::array();
    for (const Case& c : cases) {
        const KappaCurve k = kappa_curve(c.points);
        const KappaMeasures m = measure(k, c.points);
        const char* outcome = !k.converged ? "not converged"
                              : m.curvature_maximum > tolerances::kKappaCurvatureMaximum ? "converged, ill-conditioned"
                                                                                         : "converged";
        rows.push_back({{"family", c.family}, {"case", c.name}, {"points", c.points.size()},
                        {"iterations", k.iterations()}, {"converged", k.converged}, {"outcome", outcome},
                        {"residual", k.residual()}, {"error_estimate", k.error_estimate}, {"contraction", k.contraction},
                        {"measures", measures_json(m)}});
    }
    return rows;
}

}  // namespace crossdiv::verification
