#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/harness/fans.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include "crossdiv/error.h"
#include "harness/sci.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/eigendecomposition.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/harness/json_text.h"

namespace crossdiv::verification {
namespace {

using detail::sci;

/// OpenSubdiv's limit points of `request` as three meshes {level, positions, normals}, and a
/// fourth, the level with its limit texture coordinates, when it computed them (the isolation
/// ships a LevelTrace).
adapters::LevelTrace reference_limit(const PolyMesh& input, const RefineRequest& request) {
    const std::vector<const Implementation*> refs = select_references(&Capabilities::limit_positions, {}, "limit");
    if (refs.empty()) throw adapters::Rejected("OpenSubdiv is not built into this binary");
    if (std::string refusal = hierarchical_edits_refusal(*refs.front(), request.scheme, input); !refusal.empty())
        throw adapters::Rejected(refusal);
    const adapters::LimitPoints l = refs.front()->limit_points(input, request);
    PolyMesh positions, normals;
    positions.positions = l.position;
    normals.positions = l.normal;
    adapters::LevelTrace out{l.level, positions, normals};
    if (l.uv) {
        PolyMesh uv = l.level;
        uv.face_varying = {*l.uv};
        out.push_back(std::move(uv));
    }
    return out;
}

}  // namespace

LimitComparison compare_limit(const PolyMesh& input, const std::string& name, const RefineRequest& request, bool isolate) {
    adapters::LimitPoints ours;
    std::string core_error;
    try {
        ours = core_implementation().limit_points(input, request);
    } catch (const InputError& e) {
        core_error = e.what();
    }
    return compare_limit_points(ours, core_error, input, name, request, isolate);
}

LimitComparison compare_limit_points(const adapters::LimitPoints& ours, const std::string& core_error, const PolyMesh& input,
                                     const std::string& name, const RefineRequest& request, bool isolate) {
    LimitComparison out;
    out.input = name;
    out.scheme = request.scheme;
    out.rule = rule_name(request.scheme, request.rule);
    out.levels = request.levels;
    out.core_error = core_error;
    out.vertices = ours.level.num_vertices();
    const IsolatedTrace it = run_isolated([&] { return reference_limit(input, request); }, 300, isolate);
    out.outcome = it.outcome;
    if (const std::optional<EarlyVerdict> early = verdict_before_comparing(it.outcome, out.core_error, out.core_error)) {
        out.verdict = early->verdict;
        out.explanation = early->explanation;
        return out;
    }
    const adapters::LevelTrace& t = *it.trace;
    const Correspondence c = match_nearest(ours.level.positions, t[0].positions);
    if (c.method == MatchMethod::None) {
        out.verdict = Verdict::Diverge;
        out.explanation = "the refined levels do not match vertex for vertex: " + c.note;
        return out;
    }
    const double diagonal = bounding_box_diagonal(ours.level.positions);
    out.max_rel_position = 0;
    out.max_normal_angle = 0;
    for (size_t i = 0; i < c.ref_to_ours.size(); ++i) {
        const size_t v = static_cast<size_t>(c.ref_to_ours[i]);
        out.max_rel_position = std::max(out.max_rel_position, (ours.position[v] - t[1].positions[i]).norm() / diagonal);
        const Vec3& n = ours.normal[v];
        if (std::isnan(n.x())) continue;  // core computes no boundary normal
        ++out.normals_compared;
        const Vec3& m = t[2].positions[i];
        out.max_normal_angle = std::max(out.max_normal_angle, std::atan2(n.cross(m).norm(), n.dot(m)));
    }
    const bool positions_ok = out.max_rel_position <= tolerances::kLimitAgreementRelative;
    const bool normals_ok = out.normals_compared == 0 || out.max_normal_angle <= tolerances::kLimitNormalRad;
    // Texture coordinates, corner by corner through the same vertex match, relative to the UV
    // box and held to the same bar as the positions (both are sums of the same masks).
    bool uv_ok = true;
    std::string uv_text;
    if (ours.uv) {
        PolyMesh mine = ours.level, theirs = t[0];
        mine.face_varying = {*ours.uv};
        theirs.face_varying.clear();
        if (t.size() > 3) theirs.face_varying = t[3].face_varying;
        out.uv = compare_corner_values(mine, theirs, c.ref_to_ours);
        double largest = 0;
        for (double x : ours.uv->values) largest = std::max(largest, std::abs(x));
        const double bar = std::max(tolerances::kLimitAgreementRelative * out.uv->uv_box, tolerances::kFarFloatLimitWeight * largest);
        uv_ok = out.uv->compared() && out.uv->max_abs <= bar;
        uv_text = out.uv->compared() ? "; limit texture coordinates within " + sci(out.uv->max_rel) + " of the UV box over " +
                                           std::to_string(out.uv->corners) + " corners (bar " +
                                           sci(out.uv->uv_box > 0 ? bar / out.uv->uv_box : bar) +
                                           ": Far weighs a seam's values with float constants)"
                                     : "; limit texture coordinates not compared: " + out.uv->not_compared;
    }
    out.verdict = positions_ok && normals_ok && uv_ok ? Verdict::Agree : Verdict::Diverge;
    out.explanation = "limit positions within " + sci(out.max_rel_position) + " of the diagonal (bar " +
                      sci(tolerances::kLimitAgreementRelative) + "), " + std::to_string(out.normals_compared) +
                      " interior normals within " + sci(out.max_normal_angle) + " rad (bar " +
                      sci(tolerances::kLimitNormalRad) + ")" + uv_text;
    return out;
}

nlohmann::json to_json(const LimitComparison& c) {
    return {{"input", c.input},
            {"scheme", to_string(c.scheme)},
            {"rule", c.rule},
            {"levels", c.levels},
            {"vertices", c.vertices},
            {"core_error", c.core_error},
            {"reference", "opensubdiv"},
            {"outcome", c.outcome.summary()},
            {"verdict", to_string(c.verdict)},
            {"max_rel_position", finite_or_null(c.max_rel_position)},
            {"normals_compared", c.normals_compared},
            {"max_normal_angle", finite_or_null(c.max_normal_angle)},
            {"uv", c.uv ? nlohmann::json{{"compared", c.uv->compared()},
                                         {"not_compared", c.uv->not_compared},
                                         {"corners", c.uv->corners},
                                         {"max_rel", finite_or_null(c.uv->max_rel)}}
                        : nlohmann::json(nullptr)},
            {"explanation", c.explanation}};
}

// ---- Eigen-analysis ------------------------------------------------------------------------

namespace {

bool is_loop_family(const std::string& s) { return s == "loop" || s == "warren"; }

/// The local matrix: rows of the refined 1-ring of the centre in core's S, columns of the
/// coarse 1-ring (the whole fan).
Eigen::MatrixXd local_matrix(const std::string& scheme, int n) {
    if (is_loop_family(scheme)) {
        const TriMesh m = loop_fan(n);
        const Eigen::MatrixXd S(loop_subdivision_matrix(
            m, {scheme == "loop" ? LoopWeights::Loop : LoopWeights::Warren, LoopBoundary::EdgeOnly}));
        const TriConnectivity conn = build_tri_connectivity(m);
        // Row i must be the refined counterpart of column i (a similarity, not a permutation
        // of rows only): the edge point of spoke (0, k) sits at row k.
        Eigen::MatrixXd L(n + 1, n + 1);
        L.row(0) = S.row(0);
        for (int e = 0; e < conn.num_edges(); ++e) {
            const auto& ev = conn.edge_vertices[e];
            if (ev[0] == 0 || ev[1] == 0) L.row(ev[0] + ev[1]) = S.row(m.num_vertices() + e);
        }
        return L;
    }
    const PolyMesh m = quad_fan(n);
    const Eigen::MatrixXd S(catmull_clark_subdivision_matrix(m, {CatmullClarkBoundary::EdgeOnly}));
    const PolyConnectivity conn = build_poly_connectivity(m);
    // Refined counterparts: the edge point of spoke (0, 1 + 2k) replaces the spoke end
    // 1 + 2k, the face point of quad k the vertex opposite the centre in it, 2 + 2k.
    Eigen::MatrixXd L(2 * n + 1, 2 * n + 1);
    L.row(0) = S.row(0);
    for (int f = 0; f < m.num_faces(); ++f) L.row(2 + 2 * f) = S.row(m.num_vertices() + f);
    for (int e = 0; e < conn.num_edges(); ++e) {
        const auto& ev = conn.edge_vertices[e];
        if (ev[0] == 0 || ev[1] == 0) L.row(ev[0] + ev[1]) = S.row(m.num_vertices() + m.num_faces() + e);
    }
    return L;
}

std::vector<double> sorted_desc(std::vector<double> v) {
    std::sort(v.begin(), v.end(), std::greater<>());
    return v;
}

}  // namespace

SpectrumRow local_spectrum(const std::string& scheme, int n) {
    if (!is_loop_family(scheme) && scheme != "catmull-clark")
        throw InputError("spectrum: unknown scheme '" + scheme + "' (loop, warren, catmull-clark)");
    if (n < 3) throw InputError("spectrum: valence must be at least 3, got " + std::to_string(n));
    SpectrumRow row;
    row.scheme = scheme;
    row.valence = n;
    const Eigen::VectorXcd values = eigendecomposition(local_matrix(scheme, n), false).values;
    row.max_imaginary = 0;
    for (const std::complex<double>& value : values) {
        row.eigenvalues.push_back(std::abs(value));
        row.max_imaginary = std::max(row.max_imaginary, std::abs(value.imag()));
    }
    row.eigenvalues = sorted_desc(row.eigenvalues);

    // Published spectra, block by block of the discrete Fourier transform around the vertex.
    std::vector<double> cf{1.0};
    if (is_loop_family(scheme)) {
        // Loop 1987 sec. 3.3: the rotation-invariant block gives 1 and 5/8 - n beta, Fourier
        // mode k the edge-part eigenvalue 3/8 + cos(2 pi k / n) / 4. The published values of
        // 5/8 - n beta, written out here rather than read from core's masks (loop_mask.h), so
        // that a wrong beta there shows: Loop's (3/8 + cos(2 pi / n) / 4)^2, Warren's
        // 5/8 - 3/8 = 1/4, and 5/8 - 3 (3/16) = 1/16 at n = 3.
        const double loop_rate = std::pow(0.375 + 0.25 * std::cos(2 * M_PI / n), 2);
        row.vertex_rate = scheme == "loop" ? loop_rate : n == 3 ? 1.0 / 16.0 : 0.25;
        cf.push_back(row.vertex_rate);
        for (int k = 1; k < n; ++k) cf.push_back(0.375 + 0.25 * std::cos(2 * M_PI * k / n));
    } else {
        // Catmull-Clark (Ball and Storry 1988; Halstead et al. 1993): mode k != 0 is the 2x2 block
        // with eigenvalues (5 + cos t +- cos(t/2) sqrt(2 (9 + cos t))) / 16, t = 2 pi k / n; the
        // rotation-invariant block acts on (v, mean e, mean f).
        Eigen::MatrixXd M0(3, 3);
        M0 << (n - 2.0) / n + 1.0 / (4.0 * n), 3.0 / (2.0 * n), 1.0 / (4.0 * n), 0.375, 0.5, 0.125, 0.25, 0.5, 0.25;
        std::vector<double> b0;
        for (const std::complex<double>& value : eigendecomposition(M0, false).values) b0.push_back(std::abs(value));
        b0 = sorted_desc(b0);  // b0[0] is 1
        row.vertex_rate = b0[1];
        cf = b0;
        for (int k = 1; k < n; ++k) {
            const double t = 2 * M_PI * k / n;
            const double root = std::cos(t / 2) * std::sqrt(2 * (9 + std::cos(t)));
            cf.push_back((5 + std::cos(t) + root) / 16);
            cf.push_back(std::abs(5 + std::cos(t) - root) / 16);
        }
    }
    row.closed_form = sorted_desc(cf);
    row.max_difference = 0;
    for (size_t i = 0; i < row.eigenvalues.size() && i < row.closed_form.size(); ++i)
        row.max_difference = std::max(row.max_difference, std::abs(row.eigenvalues[i] - row.closed_form[i]));
    if (row.eigenvalues.size() != row.closed_form.size()) row.max_difference = INFINITY;

    constexpr double kSame = tolerances::kEigenvalueMultiplicity;
    const auto below_one = std::find_if(row.eigenvalues.begin(), row.eigenvalues.end(), [](double x) { return x < 1 - kSame; });
    if (below_one != row.eigenvalues.end()) {
        row.subdominant = *below_one;
        row.subdominant_multiplicity = static_cast<int>(std::count_if(
            row.eigenvalues.begin(), row.eigenvalues.end(), [&](double x) { return std::abs(x - row.subdominant) <= kSame; }));
        const auto next = std::find_if(below_one, row.eigenvalues.end(), [&](double x) { return x < row.subdominant - kSame; });
        row.next = next == row.eigenvalues.end() ? 0.0 : *next;
    }
    row.regular_characteristic_map =
        row.max_imaginary <= kSame && row.subdominant_multiplicity == 2 && row.next < row.subdominant - kSame;
    return row;
}

ConvergenceRow convergence(const std::string& scheme, int n, int levels) {
    ConvergenceRow row;
    row.scheme = scheme;
    row.valence = n;
    const SpectrumRow spectrum = local_spectrum(scheme, n);
    row.vertex_rate = spectrum.vertex_rate;
    row.subdominant = spectrum.subdominant;
    if (is_loop_family(scheme)) {
        const LoopOptions o{scheme == "loop" ? LoopWeights::Loop : LoopWeights::Warren, LoopBoundary::EdgeOnly};
        const TriMesh fan = loop_fan(n);
        const Vec3 limit = loop_limit(fan, o).position[0];
        const double diagonal = bounding_box_diagonal(fan.positions);
        TriMesh level = fan;
        TriConnectivity conn = build_tri_connectivity(level);
        for (int k = 1; k <= levels; ++k) {
            TriMesh next = loop_refine_once(level, conn, o);
            if (k < levels) conn = refine_tri_connectivity(level, conn);
            level = std::move(next);
            row.distance.push_back((level.positions[0] - limit).norm() / diagonal);
        }
    } else {
        const CatmullClarkOptions o{CatmullClarkBoundary::EdgeOnly};
        const PolyMesh fan = quad_fan(n);
        const Vec3 limit = catmull_clark_limit(fan, o).position[0];
        const double diagonal = bounding_box_diagonal(fan.positions);
        PolyMesh level = fan;
        for (int k = 1; k <= levels; ++k) {
            level = catmull_clark_subdivide(level, o, 1);
            row.distance.push_back((level.positions[0] - limit).norm() / diagonal);
        }
    }
    if (row.distance.size() >= 2 && row.distance.front() > 0)
        row.fitted_rate = std::pow(row.distance.back() / row.distance.front(), 1.0 / (row.distance.size() - 1));
    return row;
}

nlohmann::json to_json(const SpectrumRow& r) {
    return {{"scheme", r.scheme},
            {"valence", r.valence},
            {"eigenvalues", r.eigenvalues},
            {"closed_form", r.closed_form},
            {"max_difference", finite_or_null(r.max_difference)},
            {"max_imaginary", finite_or_null(r.max_imaginary)},
            {"subdominant", finite_or_null(r.subdominant)},
            {"subdominant_multiplicity", r.subdominant_multiplicity},
            {"next", finite_or_null(r.next)},
            {"regular_characteristic_map", r.regular_characteristic_map},
            {"vertex_rate", finite_or_null(r.vertex_rate)}};
}

nlohmann::json to_json(const ConvergenceRow& r) {
    return {{"scheme", r.scheme},       {"valence", r.valence},
            {"distance", r.distance},   {"fitted_rate", finite_or_null(r.fitted_rate)},
            {"vertex_rate", finite_or_null(r.vertex_rate)}, {"subdominant", finite_or_null(r.subdominant)}};
}

}  // namespace crossdiv::verification
