#include "crossdiv/verification/suite/case_record.h"

#include <cmath>
#include <limits>

#include "crossdiv/error.h"
#include "crossdiv/verification/harness/json_text.h"

namespace crossdiv::verification {
namespace {

using nlohmann::json;

/// A whole number of int range at `key` (whole_number_field).
int int_field(const json& j, const char* key, int fallback) {
    return static_cast<int>(whole_number_field(j, key, fallback, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}


double number(const json& j, const char* key) {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : NAN;
}

std::string text(const json& j, const char* key) { return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : ""; }

json to_json(const RunRecord& r) {
    json j = r.detail;
    j["reference"] = r.reference;
    if (r.is_check()) {
        j["check"] = r.check;
        j["subject"] = r.subject;
        j["measured"] = finite_or_null(r.measured);
        j["tolerance"] = finite_or_null(r.tolerance);
        j["unit"] = r.unit;
    }
    j["verdict"] = to_string(r.outcome.verdict);
    if (r.outcome.cls != DivergenceClass::None || !r.is_check()) j["divergence_class"] = to_string(r.outcome.cls);
    j["explanation"] = r.explanation;
    return j;
}

RunRecord run_from_json(const json& j) {
    RunRecord r;
    r.detail = j;
    r.reference = text(j, "reference");
    r.check = text(j, "check");
    r.subject = text(j, "subject");
    r.outcome = {verdict_from_string(text(j, "verdict")), divergence_class_from_string(text(j, "divergence_class"))};
    if (const std::string status = text(j, "status"); !status.empty()) r.status = run_status_from_string(status);
    r.explanation = text(j, "explanation");
    r.seconds = number(j, "seconds");
    r.hausdorff = number(j, "hausdorff_rel");
    if (r.is_check()) {
        r.measured = number(j, "measured");
        r.tolerance = number(j, "tolerance");
        r.unit = text(j, "unit");
    } else if (j.contains("positions")) {  // a comparison's run that was matched
        const json& p = j["positions"];
        r.measured = number(p, "max_rel");
        r.rms = number(p, "rms_rel");
        if (p.contains("worst") && !p["worst"].empty()) {
            r.worst_valence = p["worst"][0].is_object() ? int_field(p["worst"][0], "valence", -1) : -1;
            r.worst_boundary = p["worst"][0].value("boundary", false) ? 1 : 0;
        }
    }
    return r;
}

/// What a comparison's reference run records: its JSON, verdict, class, how it ended, and its
/// figures where it was matched.
RunRecord reference_run(const json& detail, const RefinementRun& run) {
    RunRecord r;
    r.detail = detail;
    r.reference = run.reference;
    r.outcome = {run.verdict, run.divergence_class};
    r.status = run.outcome.status;
    r.seconds = run.outcome.seconds;
    r.hausdorff = run.hausdorff_rel;
    r.explanation = run.explanation;
    if (run.outcome.status == RunStatus::Ok && run.correspondence.method != MatchMethod::None) {
        r.measured = run.comparison.max_rel;
        r.rms = run.comparison.rms_rel;
        if (!run.comparison.worst.empty()) {
            r.worst_valence = run.comparison.worst[0].valence;
            r.worst_boundary = run.comparison.worst[0].boundary ? 1 : 0;
        }
    }
    return r;
}

}  // namespace

std::string RunRecord::label() const { return is_check() ? subject + " " + check + " vs " + reference : reference; }

std::string outcome_label(const CaseRecord& c, const RunRecord& r) { return c.ours_failed ? "ours-failed" : to_string(r.outcome); }

std::string outcome_label(const CaseRecord& c) {
    return c.ours_failed ? "ours-failed" : to_string(Outcome{Verdict::OursRejected, c.refusal});
}

bool is_failure(const CaseRecord& c, const RunRecord& r) { return c.ours_failed || r.outcome.is_failure(); }

bool is_failure(const CaseRecord& c) { return c.ours_failed || Outcome{Verdict::OursRejected, c.refusal}.is_failure(); }

CaseRecord case_record(const RefinementComparison& comparison) {
    CaseRecord c;
    c.detail = to_json(comparison);
    const json runs = c.detail["runs"];
    c.detail.erase("runs");
    c.input = comparison.input;
    c.operation = to_string(comparison.scheme);
    if (comparison.scheme == Scheme::Loop) {
        c.weights = to_string(comparison.rule.loop.weights);
        c.boundary = to_string(comparison.rule.loop.boundary);
    } else {
        c.boundary = comparison.rule_name;
    }
    c.tier = to_string(comparison.tier);
    c.levels = comparison.levels;
    c.tolerance = comparison.tolerance;
    c.core_seconds = comparison.core_seconds;
    c.core_error = comparison.core_error;
    if (comparison.subject != "core" && comparison.subject_failed()) {
        // The implementation under test failed: the case's failure, as core's would be.
        c.ours_failed = true;
        c.core_error = "subject '" + comparison.subject + "' " +
                       (comparison.subject_outcome.status != RunStatus::Ok ? comparison.subject_outcome.summary()
                        : !comparison.subject_unmatched.empty()               ? comparison.subject_unmatched
                                                                               : comparison.subject_topology);
    }
    for (size_t i = 0; i < comparison.runs.size(); ++i) c.runs.push_back(reference_run(runs[i], comparison.runs[i]));
    // Texture coordinates compared per corner: a run of their own, beside the positions', so
    // that the summary, JUnit and the exit status count a face-varying verdict as they count
    // any other (an unexplained one is a failure).
    for (const RefinementRun& run : comparison.runs) {
        if (!run.uv || !run.uv->compared()) continue;
        RunRecord r;
        r.reference = run.reference;
        r.subject = comparison.subject;
        r.check = "texture coordinates (" + std::string(to_string(*comparison.face_varying)) + ")";
        r.outcome = run.uv->outcome;
        r.status = run.outcome.status;
        r.measured = run.uv->comparison.max_rel;
        r.tolerance = comparison.tolerance;
        r.unit = "of the UV box";
        r.explanation = run.uv->explanation;
        c.runs.push_back(std::move(r));
    }
    return c;
}

CaseRecord case_record(const CheckReport& report) {
    CaseRecord c;
    c.input = report.input;
    c.operation = report.operation;
    c.detail = {{"subjects", report.subjects}, {"tables", report.tables}};
    for (const Check& k : report.checks) {
        RunRecord r;
        r.reference = k.reference;
        r.subject = k.subject;
        r.check = k.check;
        r.measured = k.measured;
        r.tolerance = k.tolerance;
        r.unit = k.unit;
        r.outcome = k.outcome();
        r.explanation = k.note;
        c.runs.push_back(std::move(r));
    }
    return c;
}

CaseRecord failed_case(const std::string& input, const std::string& operation, const std::string& why, bool ours_failed) {
    CaseRecord c;
    c.input = input;
    c.operation = operation;
    c.core_error = why;
    c.ours_failed = ours_failed;
    return c;
}

json to_json(const CaseRecord& c) {
    json j = c.detail;
    j["input"] = c.input;
    j["operation"] = c.operation;
    if (c.levels == 0 && !c.boundary.empty()) j["options"] = {{"boundary", c.boundary}};  // a course task's convention
    if (c.levels > 0) {
        j["options"] = {{"boundary", c.boundary}};
        if (!c.weights.empty()) j["options"]["weights"] = c.weights;
        j["levels"] = c.levels;
        j["tier"] = c.tier;
        j["tolerance_rel"] = finite_or_null(c.tolerance);
    }
    if (std::isfinite(c.core_seconds)) j["core_seconds"] = c.core_seconds;
    if (std::isfinite(c.job_seconds)) j["job_seconds"] = c.job_seconds;
    if (!c.core_error.empty() || j.contains("core_error")) j["core_error"] = c.core_error;
    if (c.ours_failed) j["ours_failed"] = true;
    if (c.runs.empty() && !c.ours_failed) j["refusal_class"] = to_string(c.refusal);
    j["job"] = c.job;
    j["id"] = c.id;
    j["manifest_line"] = c.manifest_line;
    // The outcome each run is counted under, written once here so that readers of results.json
    // (the report) need not derive it again.
    json runs = json::array();
    for (const RunRecord& r : c.runs) {
        json run = to_json(r);
        run["outcome"] = outcome_label(c, r);
        runs.push_back(std::move(run));
    }
    j["runs"] = runs;
    if (c.runs.empty()) j["outcome"] = outcome_label(c);
    return j;
}

long long whole_number_field(const json& j, const char* key, long long fallback, long long lo, long long hi) {
    if (!j.contains(key)) return fallback;
    const json& v = j[key];
    const std::string range = "\"" + std::string(key) + "\" is not a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (v.is_number_unsigned()) {
        const auto u = v.get<unsigned long long>();
        if (u > static_cast<unsigned long long>(hi)) throw InputError(range);
        return static_cast<long long>(u);
    }
    if (v.is_number_integer()) {
        const auto x = v.get<long long>();
        if (x < lo || x > hi) throw InputError(range);
        return x;
    }
    if (v.is_number_float()) {
        // Compared as doubles before any conversion: 2^63 itself is past a long long.
        const double x = v.get<double>();
        if (!(x == std::floor(x) && x >= static_cast<double>(lo) && x <= static_cast<double>(hi) && x < 9.2e18 && x > -9.2e18))
            throw InputError(range);
        return static_cast<long long>(x);
    }
    throw InputError("\"" + std::string(key) + "\" is not a number");
}

CaseRecord case_record_from_json(const json& j) {
    if (!j.is_object() || !j.contains("runs") || !j["runs"].is_array())
        throw InputError("not a crossdiv case record (no runs)");
    CaseRecord c;
    try {
        c.detail = j;
        c.detail.erase("runs");
        c.job = int_field(j, "job", 0);
        c.id = text(j, "id");
        c.manifest_line = int_field(j, "manifest_line", 0);
        c.input = text(j, "input");
        c.operation = text(j, "operation");
        if (j.contains("options")) {
            c.weights = text(j["options"], "weights");
            c.boundary = text(j["options"], "boundary");
            c.levels = int_field(j, "levels", 0);
            c.tier = text(j, "tier");
            c.tolerance = number(j, "tolerance_rel");
        }
        c.core_seconds = number(j, "core_seconds");
        c.job_seconds = number(j, "job_seconds");
        c.core_error = text(j, "core_error");
        c.ours_failed = j.value("ours_failed", false);
        if (j.contains("refusal_class")) c.refusal = divergence_class_from_string(text(j, "refusal_class"));
        for (const json& r : j["runs"]) c.runs.push_back(run_from_json(r));
    } catch (const json::exception& e) {
        throw InputError(std::string("a case record has a field of the wrong type: ") + e.what());
    }
    return c;
}

}  // namespace crossdiv::verification
