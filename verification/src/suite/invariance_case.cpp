#include "crossdiv/verification/suite/invariance_case.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/io/output_file.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/comparisons/classification.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/output_size.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/verification/pages/divergence_view_file.h"
#include "crossdiv/verification/suite/operations.h"

namespace crossdiv::verification {
namespace {

using nlohmann::json;

/// The rule flags of a reproduce line: what `crossdiv invariance` needs to run the same rule.
std::string rule_flags(const RefineRequest& r) {
    std::string s;
    if (r.scheme == Scheme::Loop)
        s = " --weights " + std::string(to_string(r.rule.loop.weights)) + " --boundary " + std::string(to_string(r.rule.loop.boundary));
    else
        s = " --boundary " + boundary_name(r.scheme, r.rule);
    if (r.scheme == Scheme::CatmullClark && r.rule.catmull_clark.smooth_triangles) s += " --triangles smooth";
    if (r.face_varying) s += " --fvar " + std::string(to_string(*r.face_varying));
    return s;
}

/// One check as a run of the case: its outcome as the summary counts it (invariance_case.h).
RunRecord check_run(const Implementation& impl, bool under_test, const InvarianceCheck& check,
                    const std::optional<InvarianceCause>& cause, double tolerance) {
    RunRecord r;
    r.subject = impl.name();
    r.check = to_string(check.transformation);
    r.reference = "the input as written";
    r.measured = std::isfinite(check.max_rel) ? check.max_rel : check.uv_max_rel;
    r.tolerance = check.exact ? 0.0 : tolerance;
    r.unit = "rel";
    r.explanation = check.explanation;
    if (check.worst_vertex >= 0) {
        r.worst_valence = check.worst_valence;
        r.worst_boundary = check.worst_boundary ? 1 : 0;
    }
    r.detail = to_json(check);
    r.detail.erase("transformation");  // the run's check names it
    r.detail.erase("explanation");     // the run's own, with the cause
    switch (check.result) {
        case InvarianceResult::Invariant: r.outcome = {Verdict::Agree, DivergenceClass::None}; break;
        case InvarianceResult::NotCompared: r.outcome = {Verdict::NotCompared, DivergenceClass::None}; break;
        case InvarianceResult::NotInvariant:
        case InvarianceResult::Nondeterministic: {
            // A reference's finding is recorded as what it measures to be; the implementation
            // under test has no input handling of its own to appeal to: its finding is a failure.
            const DivergenceClass cls = under_test || !cause ? DivergenceClass::Unexplained : cause->cls;
            const bool reference_nondeterministic = !under_test && check.result == InvarianceResult::Nondeterministic;
            r.outcome = {reference_nondeterministic ? Verdict::RefNondeterministic : Verdict::Diverge, cls};
            if (check.result == InvarianceResult::Nondeterministic) r.explanation = "nondeterministic: " + r.explanation;
            if (cause) {
                r.explanation += "; " + cause->why;
                if (under_test && cause->cls != DivergenceClass::Unexplained)
                    r.explanation += std::string(" (") + to_string(cause->cls) + " in a reference; the implementation under test fails)";
                r.detail["cause"] = to_string(cause->cls);
            }
            break;
        }
    }
    return r;
}

/// The run of an implementation that failed on the input itself (its checks say nothing).
RunRecord failed_input_run(const Implementation& impl, bool under_test, const RunOutcome& outcome, const PolyMesh& input,
                           const std::vector<DivergenceClass>& expected_refusals) {
    RunRecord r;
    r.subject = impl.name();
    r.check = "input";
    r.reference = "the input as written";
    r.unit = "rel";
    r.status = outcome.status;
    r.explanation = "its run on the input: " + outcome.summary();
    if (!under_test) {
        r.outcome = {verdict_of_failed_run(outcome.status), DivergenceClass::None};
        return r;
    }
    // The implementation under test refused the input: classed by what the input breaks, a
    // failure unless the case declares that refusal, as in the comparison cases.
    DivergenceClass cls = input_handling_class(input);
    if (std::find(expected_refusals.begin(), expected_refusals.end(), cls) == expected_refusals.end()) {
        r.explanation += std::string("; a refusal (") + to_string(cls) + ") the case does not declare expected (refuses=" +
                         to_string(cls) + ")";
        cls = DivergenceClass::Unexplained;
    }
    r.outcome = {Verdict::OursRejected, cls};
    return r;
}

}  // namespace

json to_json(const InvarianceMinimal& m) {
    return {{"mesh", m.mesh},
            {"faces", m.faces},
            {"tests", m.tests},
            {"cut_short", m.cut_short},
            {"transformation", to_string(m.transformation)},
            {"explanation", m.explanation},
            {"reproduce", m.reproduce}};
}

std::optional<InvarianceMinimal> shrink_first_finding(const Implementation& impl, bool subject, bool under_test,
                                                      const PolyMesh& input, const RefineRequest& request,
                                                      const InvarianceReport& report,
                                                      const std::vector<std::optional<InvarianceCause>>& causes,
                                                      std::uint64_t seed, double tolerance, double timeout_seconds,
                                                      bool isolate, const std::string& folder, const std::string& file_stem) {
    // A reference's finding that a class names is what the reference does by a known rule: an
    // unexplained one of its own comes first.
    const auto failing = [&](size_t i) {
        const std::optional<InvarianceCause>& cause = i < causes.size() ? causes[i] : std::nullopt;
        return report.checks[i].finding() && (under_test || !cause || cause->cls == DivergenceClass::Unexplained);
    };
    auto finding = report.checks.end();
    for (size_t i = 0; i < report.checks.size() && finding == report.checks.end(); ++i)
        if (failing(i)) finding = report.checks.begin() + static_cast<std::ptrdiff_t>(i);
    if (finding == report.checks.end())
        finding = std::find_if(report.checks.begin(), report.checks.end(), [](const InvarianceCheck& c) { return c.finding(); });
    if (finding == report.checks.end()) return std::nullopt;
    InvarianceShrink s;
    try {
        s = shrink_not_invariant(impl, input, request, finding->transformation, seed, tolerance, timeout_seconds, isolate,
                                 {kInvarianceShrinkSeconds});
    } catch (const InputError&) {
        return std::nullopt;  // it did not show again: nothing to shrink
    }
    create_output_folder(folder);
    InvarianceMinimal m;
    m.transformation = finding->transformation;
    m.mesh = (std::filesystem::path(folder) / (file_stem + "-" + impl.name() + "-" + to_string(m.transformation) + ".obj")).string();
    write_mesh(m.mesh, s.minimal);
    m.faces = s.minimal.num_faces();
    m.tests = s.tests;
    m.cut_short = s.cut_short;
    m.explanation = s.check.explanation;
    m.reproduce = "crossdiv invariance " + m.mesh + " --scheme " + to_string(request.scheme) + " --levels " +
                  std::to_string(request.levels) + rule_flags(request) +
                  (subject ? " --subject-name " + impl.name() + " --subject '...'" : " --impl " + impl.name()) +
                  " --transform " + to_string(m.transformation) + " --seed " + std::to_string(seed);
    return m;
}

CaseRecord run_invariance_case(const SuiteJob& job, const std::string& out_dir) {
    const ManifestEntry& entry = *job.entry;
    const InvarianceKeys& keys = entry.invariance;
    PolyMesh input = load_input(job.input);
    RefineRequest request{entry.request.scheme, entry.request.rule, entry.request.levels};
    require_refined_size(input, request.scheme, request.levels, entry.max_faces, job.input, "the manifest's max-faces");
    std::vector<std::string> notes;
    if (request.scheme == Scheme::Loop) {
        PolyMesh faces_only = input;  // a polygon is refused by name, as the comparison cases do
        faces_only.creases = {};
        (void)to_tri_mesh(faces_only, "Loop subdivision");
    } else {
        request.rule = rule_with_tags(request.scheme, entry.rule_flags, input, notes);
    }
    request.face_varying = face_varying_rule(request.scheme, entry.rule_flags.face_varying, input, notes);
    const double tolerance = entry.request.tolerance;
    const double timeout = entry.request.timeout_seconds;

    std::vector<const Implementation*> impls;
    if (entry.subject && entry.subject->program) impls.push_back(entry.subject->program.get());
    else
        for (const std::string& name : keys.implementations) impls.push_back(&find_implementation(name));
    std::vector<InputTransformation> transformations = keys.transformations;
    if (transformations.empty()) transformations.assign(kInputTransformations.begin(), kInputTransformations.end());

    CaseRecord rec;
    rec.input = job.input;
    rec.operation = entry.operation->name;
    rec.levels = request.levels;
    rec.tolerance = tolerance;
    if (request.scheme == Scheme::Loop) rec.weights = to_string(request.rule.loop.weights);
    rec.boundary = request.scheme == Scheme::Loop ? to_string(request.rule.loop.boundary) : boundary_name(request.scheme, request.rule);
    rec.detail = {{"scheme", to_string(request.scheme)},
                  {"rule", rule_name(request.scheme, request.rule)},
                  {"seed", keys.seed},
                  {"input_faces", input.num_faces()},
                  {"implementations", json::array()}};
    if (request.face_varying) rec.detail["fvar"] = to_string(*request.face_varying);
    for (InputTransformation t : transformations) rec.detail["transformations"].push_back(to_string(t));
    for (const std::string& note : notes) rec.detail["notes"].push_back(note);

    const std::string stem = "job" + std::to_string(job.index);
    // The case's first finding, drawn for the viewer after the checks.
    const Implementation* drawn = nullptr;
    InvarianceCheck drawn_check;
    for (const Implementation* impl : impls) {
        const bool under_test = impl == &core_implementation() || (entry.subject && impl == entry.subject->program.get());
        const InvarianceReport report = check_invariance(*impl, input, request, transformations, keys.seed, tolerance, timeout);
        json summary = {{"name", impl->name()}, {"under_test", under_test}, {"outcome", report.outcome.summary()}};
        if (report.outcome.status != RunStatus::Ok) {
            rec.runs.push_back(failed_input_run(*impl, under_test, report.outcome, input, entry.request.expected_refusals));
            rec.detail["implementations"].push_back(std::move(summary));
            continue;
        }
        const std::vector<std::optional<InvarianceCause>> causes =
            causes_of(*impl, input, request, report, keys.seed, tolerance, timeout);
        for (size_t i = 0; i < report.checks.size(); ++i) {
            const InvarianceCheck& check = report.checks[i];
            const std::optional<InvarianceCause>& cause = causes[i];
            if (check.finding() && !drawn) {
                drawn = impl;
                drawn_check = check;
            }
            rec.runs.push_back(check_run(*impl, under_test, check, cause, tolerance));
        }
        summary["invariant"] = report.invariant();
        if (const std::optional<InvarianceMinimal> m =
                shrink_first_finding(*impl, entry.subject != nullptr, under_test, input, request, report, causes, keys.seed,
                                     tolerance, timeout,
                                     true, (std::filesystem::path(out_dir) / "invariance").string(), stem)) {
            // Beside the results, named relative to them as the views are.
            summary["minimal"] = to_json(*m);
            summary["minimal"]["mesh"] = std::filesystem::relative(m->mesh, out_dir).string();
        }
        rec.detail["implementations"].push_back(std::move(summary));
    }
    if (entry.subject) rec.detail["subject_name"] = entry.subject->name;
    if (drawn && refined_face_count(input, request.scheme, request.levels) <= kViewMaxFaces)
        if (const std::optional<DivergenceView> view =
                invariance_view(*drawn, input, request, drawn_check.transformation, keys.seed, timeout)) {
            const std::string name = "views/job" + std::to_string(job.index) + ".js";
            create_output_folder((std::filesystem::path(out_dir) / "views").string());
            write_divergence_view(*view, job.index, drawn->name(), (std::filesystem::path(out_dir) / name).string());
            rec.detail["view"] = name;
            rec.detail["view_reference"] = invariance_view_label(drawn->name(), drawn_check.transformation);
            rec.detail["view_worst_vertex"] = drawn_check.worst_vertex;
        }
    return rec;
}

}  // namespace crossdiv::verification
