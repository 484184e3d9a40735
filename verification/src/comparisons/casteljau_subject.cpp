#include "crossdiv/verification/comparisons/casteljau_subject.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/task_program.h"
#include "harness/sci.h"

namespace crossdiv::verification {
namespace {

/// Levels written with six significant digits are off by 5e-7 of a coordinate; 1e-5 of the
/// control polygon's diagonal passes them, while 1 - t for t != 1/2 moves points by the
/// distance between t and 1 - t along each leg, order 1e-1.
constexpr double kLevelTolerance = 1e-5;

/// The levels the program wrote, `dim` numbers per point. @throws ImplementationFailure naming file:line.
std::vector<std::vector<Vec3>> read_levels(const std::string& path, int dim) {
    require_regular_output(path, "out.txt");
    std::ifstream in(path);
    if (!in) throw ImplementationFailure(RunStatus::NoOutput, "no output file out.txt");
    std::vector<std::vector<Vec3>> levels;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const auto fail = [&](RunStatus s, const std::string& what) {
            throw ImplementationFailure(s, "out.txt:" + std::to_string(number) + ": " + what);
        };
        std::istringstream words(line);
        std::vector<double> values;
        for (std::string w; words >> w;) {
            double v = 0;
            try {
                size_t used = 0;
                v = std::stod(w, &used);
                if (used != w.size()) throw std::invalid_argument("trailing");
            } catch (const std::exception&) {
                fail(RunStatus::UnreadableOutput, "'" + w + "' is not a number");
            }
            if (!std::isfinite(v)) fail(RunStatus::NonFiniteOutput, "'" + w + "' is not finite");
            values.push_back(v);
        }
        if (values.empty()) continue;
        if (values.size() % static_cast<size_t>(dim) != 0)
            fail(RunStatus::UnreadableOutput, std::to_string(values.size()) + " numbers: not points of " + std::to_string(dim) + " coordinates");
        std::vector<Vec3> level;
        for (size_t k = 0; k < values.size(); k += static_cast<size_t>(dim))
            level.push_back(Vec3(values[k], values[k + 1], dim == 3 ? values[k + 2] : 0.0));
        levels.push_back(std::move(level));
    }
    if (levels.empty()) throw ImplementationFailure(RunStatus::NoOutput, "empty output file out.txt");
    return levels;
}

}  // namespace

std::string CasteljauSubjectComparison::summary() const {
    if (outcome.status != RunStatus::Ok) return "subject '" + subject + "' failed: " + outcome.summary();
    std::string s = "subject '" + subject + "': " + std::to_string(levels) + " levels at t = " + detail::sci(t) + ": ";
    if (parameter == "t") return s + "every level agrees to " + detail::sci(max_at_t);
    if (parameter == "1 - t") return s + "the levels of 1 - t (the weights swapped), off by " + detail::sci(max_at_t) + " at t";
    return s + "no parameter fits (off by " + detail::sci(max_at_t) + " at level " + std::to_string(worst_level) + ")";
}

CasteljauSubjectComparison compare_casteljau_subject(const std::string& input, const CurveFile& file, double t,
                                                     const std::string& subject, const TaskCommand& command,
                                                     double timeout_seconds) {
    if (!(t >= 0 && t <= 1)) throw InputError("t must be in [0, 1], got " + detail::sci(t));
    if (file.curves.size() != 1 || file.curves[0].type == CurveType::Primitive || file.curves[0].chain().num_segments() != 1)
        throw InputError(input + ": the de Casteljau task takes a file with one Bezier curve of one segment");
    const CurveRecord& r = file.curves[0];
    const BezierChain chain = r.chain();
    const auto at_t = casteljau_levels(chain.segment(0), t), at_s = casteljau_levels(chain.segment(0), 1 - t);
    CasteljauSubjectComparison out;
    out.input = input;
    out.subject = subject;
    out.t = t;
    out.levels = static_cast<int>(at_t.size());
    const TaskRun run = run_task_program(command, file.path, "out.txt", timeout_seconds);
    out.outcome = run.outcome;
    if (run.outcome.status != RunStatus::Ok) return out;
    std::vector<std::vector<Vec3>> levels;
    try {
        levels = read_levels(run.out, r.dim);
    } catch (const ImplementationFailure& e) {
        out.outcome.status = e.status();
        out.outcome.message = e.what() + run.stderr_tail;
        return out;
    }
    const auto wrong = [&](const std::string& what) {
        out.outcome.status = RunStatus::WrongCount;
        out.outcome.message = "out.txt: " + what;
        return out;
    };
    if (levels.size() != at_t.size())
        return wrong(std::to_string(levels.size()) + " levels; a curve of degree " + std::to_string(at_t.size() - 1) + " has " +
                     std::to_string(at_t.size()));
    for (size_t k = 0; k < levels.size(); ++k)
        if (levels[k].size() != at_t[k].size())
            return wrong("level " + std::to_string(k) + " has " + std::to_string(levels[k].size()) + " points, not " +
                         std::to_string(at_t[k].size()));
    const double diagonal = bounding_box_diagonal(at_t[0]), d = diagonal > 0 ? diagonal : 1;
    out.max_at_t = out.max_at_one_minus_t = 0;
    for (size_t k = 0; k < levels.size(); ++k)
        for (size_t i = 0; i < levels[k].size(); ++i) {
            const double e = (levels[k][i] - at_t[k][i]).norm() / d;
            if (e > out.max_at_t) {
                out.max_at_t = e;
                out.worst_level = static_cast<int>(k);
            }
            out.max_at_one_minus_t = std::max(out.max_at_one_minus_t, (levels[k][i] - at_s[k][i]).norm() / d);
        }
    out.parameter = out.max_at_t <= kLevelTolerance ? "t" : out.max_at_one_minus_t <= kLevelTolerance ? "1 - t" : "";
    return out;
}

}  // namespace crossdiv::verification
