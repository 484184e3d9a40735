#include "curve_commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "crossdiv/io/output_file.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/curves/bezier.h"
#include "crossdiv/curves/quaternion_bezier.h"
#include "crossdiv/datasets/bundled_curves.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "command.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/bench/curve_timing.h"
#include "crossdiv/verification/comparisons/casteljau_subject.h"
#include "crossdiv/verification/comparisons/curve_subject.h"
#include "crossdiv/verification/implementations/task_program.h"
#include "crossdiv/verification/properties/curve_checks.h"

namespace crossdiv::cli {
using nlohmann::json;
using namespace crossdiv::verification;

void TessellateArgs::add_to(CLI::App& app) {
    app.add_option("input", input, "Curve file (.swp, .bzc) or curve:NAME")->required();
    app.add_option("-o,--output", out, "Output: .obj (v and one l line per curve), .csv or .json (required without --subject)");
    app.add_option("--mode", mode, "uniform, angle (--angle-tolerance) or distance (--tolerance)")
        ->check(CLI::IsMember({"uniform", "angle", "distance"}))
        ->capture_default_str();
    app.add_option("--intervals", intervals, "Uniform: intervals per segment (default: the file's STEPS)")->check(CLI::Range(1, 1 << 20));
    app.add_option("--angle-tolerance", angle_tol_deg, "Angle mode: tolerance in degrees, (0, 180]");
    app.add_option("--tolerance", tol, "Distance mode: the largest distance between curve and polyline");
    app.add_option("--frames", frames,
                   "Frames to output: none, recursive (the seed's), rmf (double reflection) or orientation (a cam3 "
                   "record's quaternions: T N B the columns of the rotation)")
        ->check(CLI::IsMember({"none", "recursive", "rmf", "orientation"}))
        ->capture_default_str();
    app.add_option("--normal-side", normal_side,
                   "Planar curves: normals left of travel (CS-C3100, N = +z x T) or right (CS4620, N = T x +z)")
        ->check(CLI::IsMember({"left", "right"}))
        ->capture_default_str();
    app.add_flag("--close-frames", close_frames, "On closed curves, distribute the frame mismatch along arc length");
    subject.add_to(app, "'python3 tess.py {in} {out}' ({in}: the curve file, {out}: the CSV it writes, header curve,index,x,y,z[,tx,ty,tz,nx,ny,nz,bx,by,bz]); each record's uniform samples are compared with core's and the position basis and frame rule named");
}

namespace {

std::string fits_row(const std::vector<CurveConventionFit>& fits, const char* unit) {
    std::string s;
    for (const CurveConventionFit& f : fits)
        s += fmt::format("{}{} {}{:.3g}{}", s.empty() ? "" : ", ", f.name, f.fits ? "= " : "", f.max, unit);
    return s;
}

/// `crossdiv tessellate FILE --subject CMD`: the subject's table against core, curve by curve.
int run_curve_subject(const TessellateArgs& a) {
    if (a.mode != "uniform" || a.intervals > 0)
        throw InputError("--subject compares the uniform tessellation at each record's STEPS: drop --mode and --intervals");
    // A bundled curve is written out for the program; core reads the same file.
    const TemporaryFolder folder("curve-input");
    const CurveFile file = read_curve_file(task_input_file(a.input, folder));
    if (file.curves.empty()) throw InputError(a.input + ": no curves");
    const CurveSubjectComparison c = compare_curve_subject(a.input, file, a.subject.name, a.subject.command, a.subject.timeout);
    if (c.outcome.status == RunStatus::Ok) fmt::print("subject '{}' ran in {:.3f} s\n", c.subject, c.outcome.seconds);
    for (const CurveSubjectCurve& k : c.curves) {
        fmt::print("{}: {} samples (core {})", k.curve, k.subject_samples, k.core_samples);
        if (!k.problem.empty()) {
            fmt::print(": {}\n", k.problem);
            continue;
        }
        fmt::print("\n  positions: {} -> {}\n", fits_row(k.positions, ""),
                   k.position_rule.empty() ? "no named rule" : k.position_rule);
        if (k.tangent_deg >= 0)
            fmt::print("  tangents: {:.3g} deg from core's{}\n", k.tangent_deg,
                       k.tangent_length > 1e-3 ? fmt::format(", not unit (length off by {:.3g})", k.tangent_length) : "");
        if (!k.frames.empty())
            fmt::print("  normals: {} -> {}\n", fits_row(k.frames, " deg"), k.frame_rule.empty() ? "no named rule" : k.frame_rule);
        if (k.binormal_deg >= 0) fmt::print("  binormals: {:.3g} deg from T x N\n", k.binormal_deg);
    }
    fmt::print("\n{}\n", c.summary());
    return c.passed() ? 0 : 1;
}

}  // namespace

namespace {

std::string g(double x) { return fmt::format("{:.17g}", x); }

json vec_json(const Vec3& v, int dim) { return dim == 2 ? json{v.x(), v.y()} : json{v.x(), v.y(), v.z()}; }

struct Tessellated {
    std::string name;
    const CurveRecord* record;
    Polyline poly;
    std::vector<Frame> frames;
    double closure_deg = 0;  ///< mismatch before distribution
    double deviation = 0;
};

}  // namespace

int run_tessellate(const TessellateArgs& a) {
    if (!a.subject.command.empty()) return run_curve_subject(a);
    if (a.out.empty()) throw InputError("tessellate needs -o OUT (.obj, .csv or .json), or --subject CMD");
    const CurveFile file = load_curve_input(a.input);
    if (file.curves.empty()) throw InputError(a.input + ": no curves");
    TessellationOptions o;
    if (a.mode == "uniform") {
        o.mode = TessellationMode::Uniform;
        if (a.intervals > 0) o.intervals = a.intervals;
    } else if (a.mode == "angle") {
        if (!(a.angle_tol_deg > 0 && a.angle_tol_deg <= 180)) throw InputError("--mode angle needs --angle-tolerance in (0, 180] degrees");
        o.mode = TessellationMode::Angle;
        o.angle_tol = a.angle_tol_deg * M_PI / 180;
    } else {
        if (!(a.tol > 0) || !std::isfinite(a.tol)) throw InputError("--mode distance needs a positive, finite --tolerance");
        o.mode = TessellationMode::Distance;
        o.tol = a.tol;
    }
    const std::string ext = std::filesystem::path(a.out).extension().string();
    if (ext != ".obj" && ext != ".csv" && ext != ".json") throw InputError(a.out + ": the output must end in .obj, .csv or .json");

    std::vector<Tessellated> curves;
    for (size_t i = 0; i < file.curves.size(); ++i) {
        const CurveRecord& r = file.curves[i];
        // A record that cannot be tessellated (a curve standing still, an overflow) is named
        // by its file and line.
        const auto poly = [&] {
            try {
                return tessellate_record(r, o);
            } catch (const ParseError&) {
                throw;
            } catch (const InputError& e) {
                throw ParseError(file.path, r.line, r.label(static_cast<int>(i)) + ": " + e.what());
            }
        };
        Tessellated t{r.label(static_cast<int>(i)), &r, poly(), {}, 0, 0};
        if (a.normal_side == "right" && r.dim == 2) {
            const std::vector<Frame> right =
                curve_frames(t.poly.positions, t.poly.tangents, FrameMethod::Planar, NormalSide::Right);
            for (size_t k = 0; k < right.size(); ++k) t.poly.normals[k] = right[k].N;
        }
        t.deviation = r.type == CurveType::Primitive ? primitive_deviation(r.primitive, t.poly).max
                                                     : chordal_deviation(r.chain(), t.poly).max;
        if (a.frames == "orientation") {
            if (r.type != CurveType::CameraPath)
                throw InputError(a.input + ": curve '" + t.name + "' (" + r.keyword +
                                 ") has no orientations; --frames orientation takes cam3 records");
            const QuaternionChain q = quaternion_chain(r.orientations);
            for (double u : t.poly.params) {
                const Eigen::Matrix3d m = rotation_matrix(q.at(u));
                t.frames.push_back({m.col(0), m.col(1), m.col(2)});
            }
        } else if (a.frames != "none") {
            t.frames = curve_frames(t.poly.positions, t.poly.tangents,
                                    a.frames == "rmf" ? FrameMethod::DoubleReflection : FrameMethod::Recursive);
            if (r.closed()) {
                const double mismatch = closure_angle(t.frames);
                t.closure_deg = mismatch * 180 / M_PI;
                if (a.close_frames) distribute_closure(t.poly.positions, t.frames, mismatch);
            }
        }
        fmt::print("{}: {} ({}), {} points, measured max deviation {:.6g}{}\n", t.name, r.keyword, to_string(r.type),
                   t.poly.size(), t.deviation,
                   t.frames.empty() || !r.closed() ? "" : fmt::format(", frame mismatch after one lap {:.4g} deg{}", t.closure_deg,
                                                                       a.close_frames ? " (distributed)" : ""));
        curves.push_back(std::move(t));
    }

    OutputFile output(a.out);
    std::ostream& out = output.stream();
    if (ext == ".obj") {
        out << "# crossdiv tessellate " << a.input << " --mode " << a.mode << "\n";
        int base = 1;
        for (const Tessellated& t : curves) {
            // OBJ names cannot hold '#' (a comment) or spaces: "#0 bez2" becomes "curve0_bez2".
            std::string name = t.name;
            if (name.starts_with("#")) name = "curve" + name.substr(1);
            std::replace(name.begin(), name.end(), ' ', '_');
            out << "o " << name << "\n";
            for (const Vec3& p : t.poly.positions) out << "v " << g(p.x()) << " " << g(p.y()) << " " << g(p.z()) << "\n";
            out << "l";
            for (int i = 0; i < t.poly.size(); ++i) out << " " << base + i;
            out << "\n";
            base += t.poly.size();
        }
    } else if (ext == ".csv") {
        out << "curve,index,param,x,y,z,tx,ty,tz,nx,ny,nz" << (a.frames != "none" ? ",fnx,fny,fnz,bx,by,bz" : "") << "\n";
        for (const Tessellated& t : curves)
            for (int i = 0; i < t.poly.size(); ++i) {
                const Vec3 &p = t.poly.positions[i], &tg = t.poly.tangents[i], &n = t.poly.normals[i];
                out << t.name << "," << i << "," << g(t.poly.params[i]) << "," << g(p.x()) << "," << g(p.y()) << "," << g(p.z())
                    << "," << g(tg.x()) << "," << g(tg.y()) << "," << g(tg.z()) << "," << g(n.x()) << "," << g(n.y()) << ","
                    << g(n.z());
                if (!t.frames.empty()) {
                    const Frame& f = t.frames[i];
                    out << "," << g(f.N.x()) << "," << g(f.N.y()) << "," << g(f.N.z()) << "," << g(f.B.x()) << ","
                        << g(f.B.y()) << "," << g(f.B.z());
                }
                out << "\n";
            }
    } else {
        json doc = {{"input", a.input}, {"mode", a.mode}, {"curves", json::array()}};
        for (const Tessellated& t : curves) {
            const int dim = t.record->dim;
            json c = {{"name", t.name},  {"keyword", t.record->keyword}, {"type", to_string(t.record->type)},
                      {"closed", t.record->closed()}, {"measured_max_deviation", t.deviation}, {"params", t.poly.params}};
            json pts = json::array(), tan = json::array(), nrm = json::array();
            for (int i = 0; i < t.poly.size(); ++i) {
                pts.push_back(vec_json(t.poly.positions[i], dim));
                tan.push_back(vec_json(t.poly.tangents[i], dim));
                nrm.push_back(vec_json(t.poly.normals[i], dim));
            }
            c["points"] = pts;
            c["tangents"] = tan;
            c["normals"] = nrm;
            if (!t.frames.empty()) {
                json T = json::array(), N = json::array(), B = json::array();
                for (const Frame& f : t.frames) {
                    T.push_back(vec_json(f.T, 3));
                    N.push_back(vec_json(f.N, 3));
                    B.push_back(vec_json(f.B, 3));
                }
                c["frames"] = {{"method", a.frames}, {"T", T}, {"N", N}, {"B", B}, {"closure_mismatch_deg", t.closure_deg},
                               {"distributed", a.close_frames && t.record->closed()}};
            }
            doc["curves"].push_back(c);
        }
        out << verification::json_text(doc, 1) << "\n";
    }
    output.close();
    fmt::print("wrote {}\n", a.out);
    return 0;
}

void CasteljauArgs::add_to(CLI::App& app) {
    app.add_option("input", input, "A single Bezier curve: .bzc file, curve:NAME, or an SWP file with one segment")->required();
    app.add_option("--t", t, "Parameter in [0, 1]")->capture_default_str();
    app.add_option("--json", json, "Write {\"t\": T, \"levels\": [[[x, y], ...], ...]} to this file");
    subject.add_to(app, "'python3 casteljau.py {in} 0.5 {out}' ({in}: the curve file, t a literal of the command, equal to "
                        "--t; {out}: one line per level, its points' coordinates); each level is compared with core's at t "
                        "and at 1 - t");
}

int run_casteljau(const CasteljauArgs& a) {
    if (!(a.t >= 0 && a.t <= 1)) throw InputError("--t must be in [0, 1], got " + fmt::format("{}", a.t));
    // A subject is given a file: a bundled curve is written out for it (and read back by core).
    std::optional<TemporaryFolder> folder;
    if (!a.subject.command.empty()) folder.emplace("curve-input");
    const CurveFile file = folder ? read_curve_file(task_input_file(a.input, *folder)) : load_curve_input(a.input);
    if (!a.subject.command.empty()) {
        const CasteljauSubjectComparison c =
            compare_casteljau_subject(a.input, file, a.t, a.subject.name, a.subject.command, a.subject.timeout);
        fmt::print("{}\n", c.summary());
        return c.passed() ? 0 : 1;
    }
    if (file.curves.size() != 1 || file.curves[0].type == CurveType::Primitive)
        throw InputError(a.input + ": casteljau needs exactly one Bezier curve, the file has " +
                         std::to_string(file.curves.size()) + " curve(s)");
    const CurveRecord& r = file.curves[0];
    const BezierChain chain = r.chain();
    if (chain.num_segments() != 1)
        throw InputError(a.input + ": casteljau needs a single Bezier segment; " + r.label(0) + " has " +
                         std::to_string(chain.num_segments()) + " (" + std::string(to_string(r.type)) + ")");
    const auto levels = casteljau_levels(chain.segment(0), a.t);
    json jl = json::array();
    for (size_t k = 0; k < levels.size(); ++k) {
        std::string line = fmt::format("level {}:", k);
        json pts = json::array();
        for (const Vec3& p : levels[k]) {
            line += r.dim == 2 ? fmt::format(" ({:.17g}, {:.17g})", p.x(), p.y()) : fmt::format(" ({:.17g}, {:.17g}, {:.17g})", p.x(), p.y(), p.z());
            pts.push_back(vec_json(p, r.dim));
        }
        fmt::print("{}\n", line);
        jl.push_back(pts);
    }
    if (!a.json.empty()) {
        write_text_file(a.json, verification::json_text(nlohmann::json{{"t", a.t}, {"levels", jl}}, 1) + "\n");
    }
    return 0;
}

json run_curve_bench(int repeats) {
    std::vector<std::pair<std::string, CurveFile>> files;
    for (const auto& b : datasets::bundled_curves()) files.emplace_back("curve:" + b.name, datasets::bundled_curve_file(b.name));
    for (const std::string& f : datasets::course_curve_files())
        if (f.ends_with("wineglass.swp")) files.emplace_back(f, read_curve_file(f));
    fmt::print("\nCurve tessellation: edges (measured max deviation) per mode at each distance tolerance\n");
    fmt::print("{:<28} {:>9}  {:>18} {:>18} {:>18} {:>18} {:>8} {:>10}\n", "curve", "tol", "uniform", "angle", "distance",
               "Wang", "N*", "dist / N*");
    json rows = json::array(), timing = json::array();
    // The goal: the distance mode within kFlatteningGoal N* at every tolerance of at most 1e-3
    // of the curve's size, and never more edges than the fewest equal steps that meet it.
    constexpr double kFlatteningGoal = 1.15;
    double worst_ratio = 0;
    std::string worst_row;
    int above_uniform = 0;
    for (const auto& [input, file] : files) {
        for (size_t i = 0; i < file.curves.size(); ++i) {
            const CurveRecord& r = file.curves[i];
            const std::string label = std::filesystem::path(input).stem().string() + "/" + r.label(static_cast<int>(i));
            const double size = r.type == CurveType::Primitive ? primitive_size(r.primitive) : bounding_box_diagonal(r.chain().points);
            const double tols[] = {1e-2 * size, 1e-3 * size, 1e-4 * size};
            for (const TessellationRow& row : tessellation_study(r, label, tols)) {
                const double relative = row.tol / size;
                if (relative <= 1.01e-3 && row.distance_edges / row.optimal_edges > worst_ratio) {
                    worst_ratio = row.distance_edges / row.optimal_edges;
                    worst_row = fmt::format("{} at {:.0e} of its size", label, relative);
                }
                above_uniform += row.distance_edges > row.uniform_edges;
                auto cell = [](int n, double d) { return fmt::format("{} ({:.2e})", n, d); };
                fmt::print("{:<28} {:>9.2e}  {:>18} {:>18} {:>18} {:>18} {:>8.1f} {:>10.2f}\n", label, row.tol,
                           cell(row.uniform_edges, row.uniform_dev),
                           row.angle_reached ? cell(row.angle_edges, row.angle_dev) : "cap " + cell(row.angle_edges, row.angle_dev),
                           cell(row.distance_edges, row.distance_dev),
                           row.has_wang ? cell(row.wang_edges, row.wang_dev) : std::string("-"), row.optimal_edges,
                           row.distance_edges / row.optimal_edges);
                json j = to_json(row);
                j["input"] = input;
                j["tol_relative"] = relative;
                rows.push_back(std::move(j));
            }
            // Evaluation time: position, d1 and d2 at 1000 parameters per segment, ours vs Eigen.
            if (const std::optional<CurveTiming> t = time_curve_evaluation(r, label, repeats)) timing.push_back(to_json(*t));
        }
    }
    const bool met = worst_ratio <= kFlatteningGoal && above_uniform == 0;
    fmt::print("goal: the distance mode within {} N* at tolerances of at most 1e-3 of the size (largest {:.3f}, {}) and never "
               "above the fewest equal steps ({} rows above): {}\n",
               kFlatteningGoal, worst_ratio, worst_row, above_uniform, met ? "met" : "NOT met");
    const json goal = {{"target_ratio", kFlatteningGoal}, {"largest_ratio", worst_ratio}, {"largest_at", worst_row},
                       {"rows_above_uniform", above_uniform}, {"met", met}};
    if (!timing.empty()) {
        fmt::print("\nCurve evaluation (position, d1, d2), median of {} runs: ours (de Casteljau) vs Eigen (Cox-de Boor)\n", repeats);
        fmt::print("{:<28} {:>6} {:>11} {:>10} {:>10} {:>9}\n", "curve", "degree", "evaluations", "core ms", "eigen ms", "x core");
        for (const json& t : timing)
            fmt::print("{:<28} {:>6} {:>11} {:>10.3f} {:>10.3f} {:>9.2f}\n", t["curve"].get<std::string>(), t["degree"].get<int>(),
                       t["evaluations"].get<size_t>(), t["core_ms"].get<double>(), t["eigen_ms"].get<double>(),
                       t["eigen_over_core"].get<double>());
    }
    return {{"tessellation", rows}, {"timing", timing}, {"goal", goal}};
}

void print_curve_tables(const std::vector<CaseRecord>& records) {
    bool header = false;
    for (const CaseRecord& rec : records) {
        if (rec.operation != "curves" || !rec.detail.contains("tables")) continue;
        if (!header) {
            fmt::print("\nCurves (each check: measured <= tolerance; results.json holds every value)\n");
            header = true;
        }
        int pass = 0, fail = 0;
        double eigen = 0;
        for (const RunRecord& r : rec.runs) {
            (r.outcome.verdict == Verdict::Agree ? pass : fail) += 1;
            if (r.reference == "eigen" && r.check == "position") eigen = std::max(eigen, r.measured);
        }
        fmt::print("  {:<48} {:>3} checks, {} failed{}\n", rec.input, pass + fail, fail,
                   eigen > 0 ? fmt::format(", Eigen position max {:.2g} rel", eigen) : "");
        const json& t = rec.detail["tables"];
        if (t.contains("frames")) {
            fmt::print("    helix frame error vs the exact rotation-minimizing frame (max angle, rad):\n");
            fmt::print("    {:>6} {:>10} {:>12} {:>12}\n", "steps", "h", "recursive", "rmf");
            for (const json& row : t["frames"]["rows"])
                fmt::print("    {:>6} {:>10.4g} {:>12.3e} {:>12.3e}\n", row["steps"].get<int>(), row["h"].get<double>(),
                           row["recursive_error_rad"].get<double>(), row["rmf_error_rad"].get<double>());
            fmt::print("    fitted order: recursive {:.2f}, double reflection {:.2f}\n", t["frames"]["recursive_order"].get<double>(),
                       t["frames"]["rmf_order"].get<double>());
        }
        if (t.contains("degrees")) {
            double bern = 0, eig = 0;
            for (const json& row : t["degrees"]) {
                bern = std::max(bern, row.value("bernstein-sum", 0.0));
                eig = std::max({eig, row.value("eigen_position", 0.0), row.value("eigen_d1", 0.0), row.value("eigen_d2", 0.0)});
            }
            fmt::print("    degrees 1..20: de Casteljau vs Bernstein max {:.2g} rel; degrees 1..10 vs Eigen (position, d1, d2) max {:.2g} rel\n",
                       bern, eig);
        }
        if (t.contains("tessellation"))
            for (const json& row : t["tessellation"])
                fmt::print("    {:<12} tol {:<9.3g} edges: uniform {:>5}  angle {:>5}  distance {:>5}  Wang {:>5}\n",
                           row["curve"].get<std::string>(), row["tol"].get<double>(), row["uniform_edges"].get<int>(),
                           row["angle_edges"].get<int>(), row["distance_edges"].get<int>(),
                           row["wang_edges"].is_number() ? std::to_string(row["wang_edges"].get<int>()) : "-");
    }
}

void add_curve_commands(CLI::App& app, int& status) {
    add_command<TessellateArgs>(app, "tessellate",
                                "Tessellate every curve of an SWP or BZC file (points, tangents, normals, frames)", status,
                                run_tessellate);
    add_command<CasteljauArgs>(app, "casteljau", "Every de Casteljau level of a Bezier curve at t", status, run_casteljau);
}

}  // namespace crossdiv::cli
