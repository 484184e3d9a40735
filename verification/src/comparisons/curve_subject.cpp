#include "crossdiv/verification/comparisons/curve_subject.h"

#include <algorithm>
#include <charconv>
#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "crossdiv/curves/cubic_spline.h"
#include "crossdiv/curves/frames.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/vector_angle.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {
namespace {


/// A subject writes its numbers as text: six significant digits (printf's %g) put up to 5e-7
/// of a coordinate's magnitude into it, 1e-6 rad into a unit vector. Positions fit within 1e-5
/// of the curve's diagonal (20 times that) and directions within 0.01 degrees (1.7e-4 rad:
/// the recursive frame carries its rounding through up to ~100 updates); a swapped basis or
/// another frame rule moves samples by 1e-2 of the diagonal and frames by degrees.
constexpr double kPositionTolerance = 1e-5, kDirectionToleranceDeg = 0.01;
/// A unit vector written with six digits is unit within 1e-6; 1e-4 leaves room for a float
/// implementation, and a tangent left unnormalized is off by its speed (order 1).
constexpr double kUnitLengthTolerance = 1e-4;

/// One sample the subject wrote.
struct Sample {
    Vec3 p;
    std::optional<Vec3> t, n, b;
};

/// The angle in degrees; a zero vector (a direction the program left undecided) is as far as can be.
double angle_deg(const Vec3& a, const Vec3& b) {
    if (a.isZero() || b.isZero()) return 180;
    return vector_angle(a, b) * 180 / M_PI;
}

/// The record index a `curve` cell names: "3", or crossdiv's label "#3 bsp2".
std::optional<int> curve_index(std::string_view cell) {
    if (!cell.empty() && cell[0] == '#') cell.remove_prefix(1);
    int v = -1;
    const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (ec != std::errc() || v < 0 || (end != cell.data() + cell.size() && *end != ' ')) return std::nullopt;
    return v;
}

/// The subject's table, by record index. @throws ImplementationFailure naming file:line.
std::map<int, std::vector<Sample>> read_table(const std::string& path, const std::string& shown) {
    require_regular_output(path, shown);
    std::ifstream in(path);
    if (!in) throw ImplementationFailure(RunStatus::NoOutput, "no output file " + shown);
    std::string line;
    int number = 0;
    const auto fail = [&](RunStatus s, const std::string& what) {
        throw ImplementationFailure(s, shown + ":" + std::to_string(number) + ": " + what);
    };
    std::vector<std::string> header;
    std::map<int, std::vector<Sample>> out;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        std::vector<std::string> cells;
        std::stringstream ss(line);
        for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
        if (header.empty()) {
            header = cells;
            for (const char* need : {"curve", "x", "y", "z"})
                if (std::find(header.begin(), header.end(), need) == header.end())
                    fail(RunStatus::UnreadableOutput, std::string("the header has no '") + need + "' column (it needs curve,index,x,y,z)");
            continue;
        }
        if (cells.size() != header.size())
            fail(RunStatus::UnreadableOutput, std::to_string(cells.size()) + " cells where the header names " + std::to_string(header.size()));
        std::map<std::string, double> value;
        std::optional<int> curve;
        for (size_t k = 0; k < cells.size(); ++k) {
            if (header[k] == "curve") {
                curve = curve_index(cells[k]);
                if (!curve) fail(RunStatus::UnreadableOutput, "curve '" + cells[k] + "' is not a record index");
                continue;
            }
            static const std::vector<std::string> numeric = {"x", "y", "z", "tx", "ty", "tz", "nx", "ny", "nz",
                                                             "fnx", "fny", "fnz", "bx", "by", "bz"};
            if (std::find(numeric.begin(), numeric.end(), header[k]) == numeric.end()) continue;
            const std::string& c = cells[k];
            double v = 0;
            const auto [end, ec] = std::from_chars(c.data(), c.data() + c.size(), v);
            if (ec != std::errc() || end != c.data() + c.size()) {
                const bool non_finite = c.find("nan") != std::string::npos || c.find("inf") != std::string::npos;
                fail(non_finite ? RunStatus::NonFiniteOutput : RunStatus::UnreadableOutput,
                     header[k] + " '" + c + "' is not a " + (non_finite ? "finite number" : "number"));
            }
            if (!std::isfinite(v)) fail(RunStatus::NonFiniteOutput, header[k] + " is not finite");
            value[header[k]] = v;
        }
        const auto vec = [&](const char* a, const char* b, const char* c) -> std::optional<Vec3> {
            if (!value.count(a) || !value.count(b) || !value.count(c)) return std::nullopt;
            return Vec3(value[a], value[b], value[c]);
        };
        Sample s{*vec("x", "y", "z"), vec("tx", "ty", "tz"), vec("fnx", "fny", "fnz"), vec("bx", "by", "bz")};
        if (!s.n) s.n = vec("nx", "ny", "nz");
        out[*curve].push_back(s);
    }
    if (header.empty()) throw ImplementationFailure(RunStatus::NoOutput, "empty output file " + shown);
    return out;
}

/// Samples of a cubic record read with `basis` over the record's own windows (a Bezier
/// chain's points 3k..3k+3, a B-spline's sliding window k..k+3): the record's STEPS intervals
/// per window, joints shared, unit tangents, and the Frenet normal (the second derivative's
/// part across the tangent; zero where the curve is straight).
struct CubicSamples {
    Polyline poly;
    std::vector<Vec3> frenet;
};

CubicSamples cubic_samples(const CurveRecord& r, CubicBasis basis) {
    const Eigen::Matrix4d B = basis_matrix(basis);
    const int stride = r.type == CurveType::BezierChain ? 3 : 1, n = static_cast<int>(r.control.size());
    CubicSamples out;
    for (int k = 0; k + 3 < n; k += stride) {
        Eigen::Matrix<double, 3, 4> G;
        for (int c = 0; c < 4; ++c) G.col(c) = r.control[static_cast<size_t>(k + c)];
        for (int j = k == 0 ? 0 : 1; j <= r.steps; ++j) {
            const double t = static_cast<double>(j) / r.steps;
            const Vec3 d1 = G * B * Eigen::Vector4d(0, 1, 2 * t, 3 * t * t), d2 = G * B * Eigen::Vector4d(0, 0, 2, 6 * t);
            const Vec3 tangent = d1.normalized();
            out.poly.positions.push_back(G * B * Eigen::Vector4d(1, t, t * t, t * t * t));
            out.poly.tangents.push_back(tangent);
            const Vec3 across = d2 - d2.dot(tangent) * tangent;
            out.frenet.push_back(across.norm() > 1e-12 * d2.norm() ? across.normalized() : Vec3::Zero());
        }
    }
    return out;
}

/// A reading of the record: its samples and, for a cubic record, the Frenet normals.
struct Reading {
    std::string name;
    Polyline poly;
    std::vector<Vec3> frenet;
};

/// The position conventions of a record: as written (core's tessellation), and for a Bezier
/// chain or a uniform B-spline the other basis matrix over the same windows (a student's
/// swapped matrix).
std::vector<Reading> position_conventions(const CurveRecord& r) {
    std::vector<Reading> out{{"as written", tessellate_record(r, TessellationOptions{}), {}}};
    if (r.type != CurveType::BezierChain && r.type != CurveType::BSpline) return out;
    const bool bezier = r.type == CurveType::BezierChain;
    out[0].frenet = cubic_samples(r, bezier ? CubicBasis::Bezier : CubicBasis::BSpline).frenet;
    CubicSamples other = cubic_samples(r, bezier ? CubicBasis::BSpline : CubicBasis::Bezier);
    out.push_back({bezier ? "b-spline basis" : "bezier basis", std::move(other.poly), std::move(other.frenet)});
    return out;
}

CurveSubjectCurve compare_curve(const CurveRecord& record, int index, const std::vector<Sample>& samples) {
    CurveSubjectCurve c;
    c.curve = record.label(index);
    c.subject_samples = static_cast<int>(samples.size());
    const std::vector<Reading> conventions = position_conventions(record);
    c.core_samples = conventions.front().poly.size();
    if (samples.empty()) {
        c.problem = "no samples";
        return c;
    }
    const Reading* named = nullptr;  // the reading that fits
    for (const Reading& reading : conventions) {
        const std::string& name = reading.name;
        const Polyline& poly = reading.poly;
        CurveConventionFit fit{name, INFINITY, false};
        if (poly.size() == c.subject_samples) {
            const double d = bounding_box_diagonal(poly.positions);
            fit.max = 0;
            for (size_t k = 0; k < samples.size(); ++k)
                fit.max = std::max(fit.max, (samples[k].p - poly.positions[k]).norm() / (d > 0 ? d : 1));
            fit.fits = fit.max <= kPositionTolerance;
        }
        if (fit.fits && c.position_rule.empty()) {
            c.position_rule = name;
            named = &reading;
        }
        c.positions.push_back(fit);
    }
    if (c.subject_samples != c.core_samples && c.position_rule.empty()) {
        c.problem = std::to_string(c.subject_samples) + " samples where core makes " + std::to_string(c.core_samples) +
                    " (STEPS " + std::to_string(record.steps) + " intervals per segment)";
        return c;
    }
    if (c.position_rule.empty()) return c;
    if (std::all_of(samples.begin(), samples.end(), [](const Sample& s) { return s.t.has_value(); })) {
        c.tangent_deg = 0;
        for (size_t k = 0; k < samples.size(); ++k) {
            c.tangent_deg = std::max(c.tangent_deg, angle_deg(*samples[k].t, named->poly.tangents[k]));
            c.tangent_length = std::max(c.tangent_length, std::abs(samples[k].t->norm() - 1));
        }
    }
    if (std::all_of(samples.begin(), samples.end(), [](const Sample& s) { return s.n.has_value(); })) {
        const Polyline& p = named->poly;
        std::vector<std::pair<std::string, std::vector<Vec3>>> normals;
        for (const auto& [name, method, side] : {std::tuple{"recursive", FrameMethod::Recursive, NormalSide::Left},
                                                 std::tuple{"rmf", FrameMethod::DoubleReflection, NormalSide::Left},
                                                 std::tuple{"planar-left", FrameMethod::Planar, NormalSide::Left},
                                                 std::tuple{"planar-right", FrameMethod::Planar, NormalSide::Right}}) {
            std::vector<Vec3> n;
            for (const Frame& f : curve_frames(p.positions, p.tangents, method, side)) n.push_back(f.N);
            normals.push_back({name, std::move(n)});
        }
        // Frenet's normal is undefined where the curve is straight: it names a subject only on
        // a curve that bends at every sample.
        if (!named->frenet.empty() &&
            std::none_of(named->frenet.begin(), named->frenet.end(), [](const Vec3& v) { return v.isZero(); }))
            normals.push_back({"frenet", named->frenet});
        for (const auto& [name, frames] : normals) {
            CurveConventionFit fit{name, 0, false};
            for (size_t k = 0; k < samples.size(); ++k) fit.max = std::max(fit.max, angle_deg(*samples[k].n, frames[k]));
            fit.fits = fit.max <= kDirectionToleranceDeg;
            if (fit.fits && c.frame_rule.empty()) c.frame_rule = name;
            c.frames.push_back(fit);
        }
        if (std::all_of(samples.begin(), samples.end(), [](const Sample& s) { return s.b.has_value() && s.t.has_value(); })) {
            c.binormal_deg = 0;
            for (const Sample& s : samples) c.binormal_deg = std::max(c.binormal_deg, angle_deg(*s.b, s.t->cross(*s.n)));
        }
    }
    return c;
}

}  // namespace

bool CurveSubjectComparison::passed() const {
    if (outcome.status != RunStatus::Ok || curves.empty()) return false;
    // The record's own reading is the task; another basis is a diagnosis of a fault.
    return std::all_of(curves.begin(), curves.end(), [](const CurveSubjectCurve& c) {
        return c.problem.empty() && c.position_rule == "as written" &&
               (c.tangent_deg < 0 || (c.tangent_deg <= kDirectionToleranceDeg && c.tangent_length <= kUnitLengthTolerance)) &&
               (c.frames.empty() || !c.frame_rule.empty()) && (c.binormal_deg < 0 || c.binormal_deg <= kDirectionToleranceDeg);
    });
}

std::string CurveSubjectComparison::summary() const {
    if (outcome.status != RunStatus::Ok) return "subject '" + subject + "' failed: " + outcome.summary();
    const int n = static_cast<int>(curves.size());
    std::map<std::string, int> positions, frames;
    int problems = 0, tangents_off = 0, binormals_off = 0, not_unit = 0;
    for (const CurveSubjectCurve& c : curves) {
        if (!c.problem.empty()) {
            ++problems;
            continue;
        }
        ++positions[c.position_rule.empty() ? "no named rule" : c.position_rule];
        if (!c.frames.empty()) ++frames[c.frame_rule.empty() ? "no named rule" : c.frame_rule];
        tangents_off += c.tangent_deg > kDirectionToleranceDeg;
        not_unit += c.tangent_length > kUnitLengthTolerance;
        binormals_off += c.binormal_deg > kDirectionToleranceDeg;
    }
    const auto tally = [&](const std::map<std::string, int>& m) {
        std::string s;
        for (const auto& [name, k] : m) s += (s.empty() ? "" : ", ") + name + " on " + std::to_string(k) + " of " + std::to_string(n);
        return s;
    };
    std::string s = "subject '" + subject + "': ";
    if (!positions.empty()) s += "positions " + tally(positions);
    if (!frames.empty()) s += "; frames " + tally(frames);
    if (tangents_off) s += "; tangents off on " + std::to_string(tangents_off) + " of " + std::to_string(n);
    if (not_unit) s += "; tangents not unit on " + std::to_string(not_unit) + " of " + std::to_string(n);
    if (binormals_off) s += "; B is not T x N on " + std::to_string(binormals_off) + " of " + std::to_string(n);
    if (problems) s += std::string(positions.empty() ? "" : "; ") + "not compared on " + std::to_string(problems) + " of " +
                       std::to_string(n) + " (no samples, or another count)";
    return s + " curves";
}

CurveSubjectComparison compare_curve_subject(const std::string& input, const CurveFile& file, const std::string& subject,
                                             const TaskCommand& command, double timeout_seconds) {
    CurveSubjectComparison out;
    out.input = input;
    out.subject = subject;
    const TaskRun run = run_task_program(command, file.path, "out.csv", timeout_seconds);
    out.outcome = run.outcome;
    const auto failed = [&](RunStatus s, const std::string& message) {
        out.outcome.status = s;
        out.outcome.message = message;
        return out;
    };
    if (run.outcome.status != RunStatus::Ok) return out;
    std::map<int, std::vector<Sample>> table;
    try {
        table = read_table(run.out, "out.csv");
    } catch (const ImplementationFailure& e) {
        return failed(e.status(), e.what() + run.stderr_tail);
    }
    for (const auto& [index, samples] : table)
        if (index >= static_cast<int>(file.curves.size()))
            return failed(RunStatus::WrongCount, "out.csv names curve " + std::to_string(index) + "; the file has " +
                                                     std::to_string(file.curves.size()));
    for (size_t i = 0; i < file.curves.size(); ++i) {
        const auto it = table.find(static_cast<int>(i));
        out.curves.push_back(compare_curve(file.curves[i], static_cast<int>(i), it == table.end() ? std::vector<Sample>{} : it->second));
    }
    return out;
}

}  // namespace crossdiv::verification
