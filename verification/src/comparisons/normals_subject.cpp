#include "crossdiv/verification/comparisons/normals_subject.h"

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <sstream>

#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/vertex_normals.h"
#include "crossdiv/verification/harness/temporary_folder.h"
#include "crossdiv/verification/harness/vector_angle.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {
namespace {

/// Six printed digits put 1e-6 rad into a unit vector; 0.01 degrees (1.7e-4 rad) leaves room for
/// a float implementation, and another weighting moves a normal by degrees wherever the faces
/// around a vertex differ in size or angle.
constexpr double kNormalToleranceDeg = 0.01, kNormalUnitTolerance = 1e-4;

double normal_angle_deg(const Vec3& a, const Vec3& b) { return vector_angle(a, b) * 180 / M_PI; }

/// The normals the program wrote: its `vn` lines, or, without any, its lines of three numbers.
/// @throws ImplementationFailure naming file:line.
std::vector<Vec3> read_normals(const std::string& path, const std::string& shown) {
    require_regular_output(path, shown);
    std::ifstream in(path);
    if (!in) throw ImplementationFailure(RunStatus::NoOutput, "no output file " + shown);
    std::vector<Vec3> vn, plain;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string first;
        if (!(words >> first) || first[0] == '#') continue;
        const bool is_vn = first == "vn";
        if (!is_vn && (first == "v" || first == "f" || first == "vt" || first == "o" || first == "g" || first == "s")) continue;
        std::vector<std::string> cells;
        if (!is_vn) cells.push_back(first);
        for (std::string w; words >> w;) cells.push_back(w);
        const auto fail = [&](RunStatus s, const std::string& what) {
            throw ImplementationFailure(s, shown + ":" + std::to_string(number) + ": " + what);
        };
        if (cells.size() != 3) fail(RunStatus::UnreadableOutput, "expected three numbers, got " + std::to_string(cells.size()) + " words");
        Vec3 n;
        for (int k = 0; k < 3; ++k) {
            try {
                size_t used = 0;
                n[k] = std::stod(cells[static_cast<size_t>(k)], &used);
                if (used != cells[static_cast<size_t>(k)].size()) throw std::invalid_argument("trailing");
            } catch (const std::exception&) {
                fail(RunStatus::UnreadableOutput, "'" + cells[static_cast<size_t>(k)] + "' is not a number");
            }
            if (!std::isfinite(n[k])) fail(RunStatus::NonFiniteOutput, "'" + cells[static_cast<size_t>(k)] + "' is not finite");
        }
        (is_vn ? vn : plain).push_back(n);
    }
    return vn.empty() ? plain : vn;
}

}  // namespace

bool NormalsSubjectComparison::passed() const {
    return outcome.status == RunStatus::Ok && !weighting.empty() && weighting.find("reversed") == std::string::npos &&
           length_error <= kNormalUnitTolerance;
}

std::string NormalsSubjectComparison::summary() const {
    if (outcome.status != RunStatus::Ok) return "subject '" + subject + "' failed: " + outcome.summary();
    std::string s = "subject '" + subject + "': " + (weighting.empty() ? std::string("no named weighting") : weighting + " weighting") +
                    " on " + std::to_string(compared) + " vertices";
    if (weighting.empty() && !weightings.empty()) {
        const WeightingFit* best = &weightings[0];
        for (const WeightingFit& w : weightings)
            if (w.max_deg < best->max_deg) best = &w;
        s += " (nearest: " + best->name + ", off by " + std::to_string(best->max_deg) + " deg at vertex " +
             std::to_string(best->worst_vertex) + ")";
    }
    if (length_error > kNormalUnitTolerance) s += "; normals not unit (length off by up to " + std::to_string(length_error) + ")";
    return s;
}

NormalsSubjectComparison compare_normals_subject(const std::string& input, const TriMesh& mesh, const std::string& subject,
                                                 const TaskCommand& command, double timeout_seconds) {
    NormalsSubjectComparison out;
    out.input = input;
    out.subject = subject;
    out.vertices = mesh.num_vertices();
    const TemporaryFolder folder("normals-input");
    const std::string obj = (folder.path() / "mesh.obj").string();
    write_mesh(obj, to_poly_mesh(mesh));
    const TaskRun run = run_task_program(command, obj, "out.obj", timeout_seconds);
    out.outcome = run.outcome;
    if (run.outcome.status != RunStatus::Ok) return out;
    std::vector<Vec3> normals;
    try {
        normals = read_normals(run.out, "out.obj");
    } catch (const ImplementationFailure& e) {
        out.outcome.status = e.status();
        out.outcome.message = e.what() + run.stderr_tail;
        return out;
    }
    if (static_cast<int>(normals.size()) != mesh.num_vertices()) {
        out.outcome.status = RunStatus::WrongCount;
        out.outcome.message = "out.obj: " + std::to_string(normals.size()) + " normals for " + std::to_string(mesh.num_vertices()) +
                              " vertices";
        return out;
    }
    for (NormalWeighting w : {NormalWeighting::Area, NormalWeighting::Angle, NormalWeighting::Uniform}) {
        const std::vector<Vec3> core = vertex_normals(mesh, w);
        for (const bool reversed : {false, true}) {
            WeightingFit fit{std::string(to_string(w)) + (reversed ? ", reversed" : ""), 0, -1, false};
            int compared = 0;
            for (size_t v = 0; v < core.size(); ++v) {
                if (core[v].isZero()) continue;  // no direction to hold it to
                ++compared;
                const double a = normal_angle_deg(normals[v], reversed ? Vec3(-core[v]) : core[v]);
                if (!(a <= fit.max_deg)) {
                    fit.max_deg = a;
                    fit.worst_vertex = static_cast<int>(v);
                }
            }
            fit.fits = fit.max_deg <= kNormalToleranceDeg;
            if (fit.fits && out.weighting.empty()) out.weighting = fit.name;
            out.compared = compared;
            out.weightings.push_back(fit);
        }
    }
    const std::vector<Vec3> area = vertex_normals(mesh, NormalWeighting::Area);
    for (size_t v = 0; v < area.size(); ++v)
        if (!area[v].isZero()) out.length_error = std::max(out.length_error, std::abs(normals[v].norm() - 1));
    return out;
}

}  // namespace crossdiv::verification
