#include "crossdiv/verification/suite/task_cases.h"

#include <algorithm>

#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/io/patch_io.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/surfaces/bezier_patch.h"
#include "crossdiv/verification/comparisons/casteljau_subject.h"
#include "crossdiv/verification/comparisons/curve_subject.h"
#include "crossdiv/verification/comparisons/edit_subject.h"
#include "crossdiv/verification/comparisons/normals_subject.h"
#include "crossdiv/verification/comparisons/surface_subject.h"
#include "crossdiv/verification/harness/temporary_folder.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/suite/operations.h"

namespace crossdiv::verification {
namespace {

using nlohmann::json;

/// What one task case found: the convention the case asks (core's), the one the subject
/// follows where one fits ("" none), whether it passed, and the comparison's one line.
struct TaskFinding {
    RunOutcome outcome;
    std::string asked, followed, summary;
    bool passed = false;
};

TaskFinding curves(const std::string& file, const std::string& subject, const TaskCommand& command, double timeout) {
    const CurveFile f = read_curve_file(file);
    if (f.curves.empty()) throw InputError(file + ": no curves");
    const CurveSubjectComparison c = compare_curve_subject(file, f, subject, command, timeout);
    TaskFinding out{c.outcome, "as written", "", c.summary(), c.passed()};
    if (out.passed) out.followed = out.asked;
    else if (c.outcome.status == RunStatus::Ok &&
             std::all_of(c.curves.begin(), c.curves.end(), [](const CurveSubjectCurve& k) { return !k.position_rule.empty(); }))
        for (const CurveSubjectCurve& k : c.curves)
            if (k.position_rule != out.asked && out.followed.empty()) out.followed = k.position_rule;
    return out;
}

TaskFinding casteljau(const std::string& file, double t, const std::string& subject, const TaskCommand& command, double timeout) {
    const CasteljauSubjectComparison c = compare_casteljau_subject(file, read_curve_file(file), t, subject, command, timeout);
    return {c.outcome, "t", c.parameter, c.summary(), c.passed()};
}

/// A surface comparison's finding: core's convention asked; another named where its positions
/// and normals fit one and its faces neither turn nor crack more than core's.
TaskFinding surface(const SurfaceSubjectComparison& c) {
    TaskFinding out{c.outcome, c.core_convention.empty() ? "as core's" : c.core_convention, "", c.summary(), c.passed()};
    const bool sound = c.outcome.status == RunStatus::Ok && !c.convention.empty() && !c.normal_rule.empty() &&
                       c.faces_against_normals <= c.core_folded_faces && c.boundary_edges <= c.core_boundary_edges;
    if (out.passed) out.followed = out.asked;
    else if (sound) out.followed = (c.follows_core() ? out.asked : c.convention) + (c.normal_rule == "reversed" ? ", normals reversed" : "");
    return out;
}

TaskFinding patch(const std::string& file, int res, const std::string& subject, const TaskCommand& command, double timeout) {
    if (!(file.ends_with(".bez") || file.ends_with(".BEZ"))) throw InputError(file + ": the patch task takes BEZ files");
    const std::vector<BezierPatch> patches = read_bez(file);
    const SurfaceSamples samples = patch_samples(patches, res, tessellate_patches(patches, res));
    return surface(compare_surface_subject(file, {&samples, 1}, subject, command, timeout));
}

TaskFinding sweep(const std::string& file, const std::string& frames, const std::string& subject, const TaskCommand& command,
                  double timeout) {
    const CurveFile f = read_swp(file);
    if (f.sweeps.empty()) throw InputError(file + ": no srev or gcyl record");
    SweepOptions o;
    o.frames = frames == "rmf" ? FrameMethod::DoubleReflection : FrameMethod::Recursive;
    return surface(compare_surface_subject(file, sweep_conventions(f, o), subject, command, timeout));
}

TaskFinding normals(const std::string& spec, const std::string& subject, const TaskCommand& command, double timeout) {
    const TriMesh mesh = to_tri_mesh(load_input(spec, UnknownTags::Ignore), "vertex normals");
    const NormalsSubjectComparison c = compare_normals_subject(spec, mesh, subject, command, timeout);
    TaskFinding out{c.outcome, "area", "", c.summary(), c.passed()};
    if (c.outcome.status == RunStatus::Ok && !c.weighting.empty()) out.followed = c.weighting;
    out.passed = out.passed && c.weighting == out.asked;
    return out;
}

TaskFinding flip_split(const std::string& spec, const std::string& ops, const std::string& subject, const TaskCommand& command,
                       double timeout) {
    const TriMesh mesh = to_tri_mesh(load_input(spec, UnknownTags::Ignore), "edit");
    const EditSubjectComparison c = compare_edit_subject(spec, mesh, parse_edit_operations(ops), subject, command, timeout);
    TaskFinding out{{}, "core's half-edge operations", "", c.summary(), c.passed()};
    // A step whose run failed ends the comparison: its outcome is the case's.
    for (const EditStep& s : c.steps)
        if (s.outcome.status != RunStatus::Ok) out.outcome = s.outcome;
    if (out.passed) out.followed = out.asked;
    return out;
}

}  // namespace

CaseRecord run_task_case(const SuiteJob& job, const std::string&) {
    const ManifestEntry& e = *job.entry;
    const std::string& op = e.operation->name;
    if (!e.subject || !e.subject->task) throw InputError("the " + op + " task needs a subject with command=");
    const ManifestSubject& s = *e.subject;
    const TemporaryFolder folder("task-input");
    const std::string file = task_input_file(job.input, folder);
    TaskFinding f;
    if (op == "tessellate") f = curves(file, s.name, *s.task, s.timeout_seconds);
    else if (op == "casteljau") f = casteljau(file, e.task.t, s.name, *s.task, s.timeout_seconds);
    else if (op == "patch") f = patch(file, e.task.res, s.name, *s.task, s.timeout_seconds);
    else if (op == "sweep") f = sweep(file, e.task.frames, s.name, *s.task, s.timeout_seconds);
    else if (op == "vertex-normals") f = normals(job.input, s.name, *s.task, s.timeout_seconds);
    else f = flip_split(job.input, e.task.ops, s.name, *s.task, s.timeout_seconds);

    CaseRecord c;
    c.input = job.input;
    c.operation = op;
    c.boundary = f.asked;  // the rule the case names, as the class table reads it
    json subject = {{"name", s.name}, {"roster", s.roster}, {"status", to_string(f.outcome.status)},
                    {"status_message", f.outcome.message}, {"match", {{"method", "task"}}}, {"summary", f.summary}};
    subject["rules"] = f.followed.empty() ? json{{"classes", json::array()}} : json{{"rule", f.followed}};
    c.detail["subject"] = std::move(subject);
    if (f.outcome.status != RunStatus::Ok) {
        // The implementation under test failed: the case's failure, as a comparison's subject's is.
        c.ours_failed = true;
        c.core_error = f.summary;
        return c;
    }
    RunRecord r;
    r.reference = "core";
    r.outcome = f.passed             ? Outcome{Verdict::Agree, DivergenceClass::None}
                : !f.followed.empty() ? Outcome{Verdict::Diverge, DivergenceClass::Convention}
                                     : Outcome{Verdict::Diverge, DivergenceClass::Unexplained};
    r.explanation = f.summary;
    c.runs.push_back(std::move(r));
    return c;
}

}  // namespace crossdiv::verification
