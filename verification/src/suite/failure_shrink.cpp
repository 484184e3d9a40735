#include "crossdiv/verification/suite/failure_shrink.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <unordered_map>
#include <fstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/harness/program_server.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/verification/suite/operations.h"
#include "crossdiv/verification/suite/roster_table.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// One failure to shrink: a subject's (`run` < 0), or the reference run `run` of the record's.
struct ShrinkTask {
    size_t record = 0;
    int run = -1;
    const SuiteJob* job = nullptr;
    std::string implementation;  ///< the subject's or the reference's name
    std::string file;            ///< the minimal mesh's path in the output folder
};

/// `s` with characters other than letters, digits, '-', '_' and '.' replaced: a file name.
std::string file_safe(std::string s) {
    for (char& c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '_';
    return s;
}

/// The file name of a subject's minimal input: its roster's and its own name and the scheme.
std::string minimal_name(const RosterRow& row) {
    return "minimal/" + file_safe((row.roster.empty() ? "" : row.roster + "-") + row.subject + "-" + row.scheme) + ".obj";
}

/// What the shrinking found, as a record's "minimal" holds it.
json minimal_json(const ShrinkResult& r, const std::string& file, const std::string& symptom) {
    return {{"mesh", file},
            {"faces", r.minimal.num_faces()},
            {"vertices", r.minimal.num_vertices()},
            {"levels", r.levels},  // the fewest at which the case's input shows it
            {"symptom", symptom},
            {"tests", r.tests},
            {"cut_short", r.cut_short},
            // A failure that comes and goes (memory the reference does not own) may not show on
            // the minimal mesh's last comparison though it showed on each kept candidate.
            {"reproduces", symptom_of(r.minimal_comparison) == r.symptom}};
}

/// The case of `task` run again with its subject alone, or with its one reference, shrunk; its
/// minimal mesh written.
json shrink_one(const ShrinkTask& task, const std::string& out_dir) {
    const ManifestEntry& entry = *task.job->entry;
    RefinementRequest req = entry.request;
    req.view_max_faces = 0;
    PolyMesh input = load_input(task.job->input);
    std::vector<std::string> notes;
    ShrinkResult r;
    json result;
    if (task.run < 0) {
        req.subject = entry.subject->program.get();
        req.references.clear();
        req.without_references = true;
        if (req.scheme != Scheme::Loop) req.rule = rule_with_tags(req.scheme, entry.rule_flags, input, notes);
        r = shrink_divergence(input, task.job->input, req);
        result = minimal_json(r, task.file, describe(r.symptom, "subject '" + task.implementation + "'", ""));
        result["reference"] = "";
    } else {
        req.subject = nullptr;
        req.references = {task.implementation};
        resolve_input_rules(req, entry, input, notes);
        r = shrink_divergence(input, task.job->input, req, {kReferenceShrinkSeconds});
        result = minimal_json(r, task.file, describe(r.symptom, "core", task.implementation));
        result["reference"] = task.implementation;
        req.levels = r.levels;  // the fewest that show it
        result["reproduce"] = compare_command(req, task.file, task.implementation);
    }
    const fs::path path = fs::path(out_dir) / task.file;
    create_output_folder(path.parent_path().string());
    write_mesh(path.string(), r.minimal);
    return result;
}

/// Each subject's first failing case (roster_table.h), to shrink, or noted why not.
void subject_tasks(const std::vector<SuiteJob>& jobs, std::vector<CaseRecord>& records, std::vector<ShrinkTask>& tasks) {
    for (const RosterRow& row : roster_table(records)) {
        if (row.failing_case.empty()) continue;
        const auto rec = std::find_if(records.begin(), records.end(), [&](const CaseRecord& c) { return c.id == row.failing_case; });
        if (rec == records.end()) continue;
        const auto job = std::find_if(jobs.begin(), jobs.end(), [&](const SuiteJob& j) { return j.index == rec->job; });
        if (job == jobs.end() || !job->entry->subject) continue;
        if (job->entry->operation->kind != OperationKind::Comparison)
            rec->detail["minimal"] = {{"note", "not shrunk: shrinking takes a subdivision scheme's mesh, not a course task's input"}};
        else if (rec->detail["subject"].value("status", "") == "timeout")
            rec->detail["minimal"] = {{"note", "not shrunk: it hangs, and each smaller try would cost its time limit"}};
        else if (!job->entry->subject->program)
            rec->detail["minimal"] = {{"note", "not shrunk: a result file is not re-run on a smaller input"}};
        else
            tasks.push_back({static_cast<size_t>(rec - records.begin()), -1, &*job, row.subject, minimal_name(row)});
    }
}

/// Whether a reference's run is a failure of the reference's to shrink: it crashed, threw or
/// timed out, wrote an invalid result, or diverges (in positions or texture coordinates) for no
/// class's reason.
bool reference_failed(const RunRecord& run) {
    const Verdict v = run.outcome.verdict;
    return v == Verdict::RefCrashed || v == Verdict::RefInvalidOutput ||
           (v == Verdict::Diverge && run.outcome.cls == DivergenceClass::Unexplained);
}

/// A reference's failing run that another case's shrinking serves: the same failure of the
/// same run of the reference (same input, scheme, levels, the reference's own rule), which
/// only core's rule set apart (a crash does not depend on it).
struct RepeatedFailure {
    size_t record = 0;
    int run = 0;
    size_t task = 0;  ///< the task that shrinks it
};

/// What makes two reference failures one: the reference's run, and how it failed. Only a run
/// that failed (crashed, threw, invalid output) has one: a divergence depends on core's rule.
std::string failure_key(const SuiteJob& job, const RunRecord& run) {
    if (run.outcome.verdict != Verdict::RefCrashed && run.outcome.verdict != Verdict::RefInvalidOutput) return "";
    const RefinementRequest& req = job.entry->request;
    return run.reference + "\n" + job.input + "\n" + std::string(to_string(req.scheme)) + "\n" + std::to_string(req.levels) + "\n" +
           run.detail.value("rule", "") + "\n" + (run.detail.contains("ran_with") ? run.detail["ran_with"].dump() : "") +
           "\n" + (req.face_varying ? std::string(to_string(*req.face_varying)) : "") + "\n" +
           std::string(to_string(run.status.value_or(RunStatus::Ok)));
}

/// Every failure of a reference in a comparison case of core's, to shrink, or noted why not.
/// A case's texture coordinates' run and its positions' run of one reference are one task; a
/// failure another case's task already shrinks is a repeat of it.
void reference_tasks(const std::vector<SuiteJob>& jobs, std::vector<CaseRecord>& records, std::vector<ShrinkTask>& tasks,
                     std::vector<RepeatedFailure>& repeats) {
    std::unordered_map<std::string, size_t> task_of_failure;
    std::vector<const SuiteJob*> by_index;
    for (const SuiteJob& j : jobs) {
        if (static_cast<size_t>(j.index) >= by_index.size()) by_index.resize(static_cast<size_t>(j.index) + 1, nullptr);
        by_index[static_cast<size_t>(j.index)] = &j;
    }
    for (size_t c = 0; c < records.size(); ++c) {
        CaseRecord& rec = records[c];
        const SuiteJob* job = static_cast<size_t>(rec.job) < by_index.size() ? by_index[static_cast<size_t>(rec.job)] : nullptr;
        if (!job || job->entry->subject || job->entry->operation->kind != OperationKind::Comparison) continue;
        std::vector<std::string> taken;
        for (size_t i = 0; i < rec.runs.size(); ++i) {
            RunRecord& run = rec.runs[i];
            if (!reference_failed(run) || std::find(taken.begin(), taken.end(), run.reference) != taken.end()) continue;
            taken.push_back(run.reference);
            if (run.status == RunStatus::Timeout)
                run.detail["minimal"] = {{"note", "not shrunk: it timed out, and each smaller try would cost its time limit"}};
            else if (const std::string key = failure_key(*job, run); !key.empty() && task_of_failure.count(key))
                repeats.push_back({c, static_cast<int>(i), task_of_failure[key]});
            else {
                if (!key.empty()) task_of_failure[key] = tasks.size();
                tasks.push_back({c, static_cast<int>(i), job, run.reference,
                                 "minimal/job" + std::to_string(job->index) + "-" + file_safe(run.reference) + ".obj"});
            }
        }
    }
}

}  // namespace

void shrink_failures(const std::vector<SuiteJob>& jobs, std::vector<CaseRecord>& records, const std::string& out_dir,
                     int workers) {
    std::vector<ShrinkTask> tasks;
    std::vector<RepeatedFailure> repeats;
    subject_tasks(jobs, records, tasks);
    reference_tasks(jobs, records, tasks, repeats);
    if (tasks.empty()) return;
    // Children, each every workers-th task, each task's result a JSON file the parent reads back:
    // a subject that takes a child down takes only its own record with it.
    workers = std::max(1, std::min<int>(workers, static_cast<int>(tasks.size())));
    std::printf("shrinking %zu failure(s) to minimal meshes (%d at a time; a reference's at most %.0f s each)", tasks.size(),
                workers, kReferenceShrinkSeconds);
    if (!repeats.empty()) std::printf("; %zu more the same run of a reference under another rule of core's", repeats.size());
    std::printf("\n");
    const fs::path scratch = fs::path(out_dir) / "minimal";
    create_output_folder(scratch.string());
    const auto result_file = [&](size_t t) { return scratch / ("task" + std::to_string(t) + ".json"); };
    std::fflush(nullptr);
    std::vector<pid_t> pids;
    std::vector<std::unique_ptr<RegisteredChild>> registrations;
    for (int w = 0; w < workers; ++w) {
        const pid_t pid = fork();
        if (pid < 0) throw std::runtime_error("fork failed");
        if (pid == 0) {
            stop_cleanly_on_signals();
            for (size_t t = static_cast<size_t>(w); t < tasks.size(); t += static_cast<size_t>(workers)) {
                json result;
                try {
                    result = shrink_one(tasks[t], out_dir);
                    std::printf("  %s: %s, %d face(s): %s\n", tasks[t].job->id.c_str(), result.value("mesh", "").c_str(),
                                result.value("faces", 0), result.value("symptom", "").c_str());
                } catch (const std::exception& e) {
                    result = {{"note", std::string("not shrunk: ") + e.what()}};
                    std::printf("  %s: %s %s\n", tasks[t].job->id.c_str(), tasks[t].implementation.c_str(),
                                result.value("note", "").c_str());
                }
                std::fflush(stdout);
                std::ofstream(result_file(t)) << json_text(result) << "\n";
            }
            stop_program_servers();  // the subject's, if it serves: destructors do not run at _exit
            _exit(0);
        }
        pids.push_back(pid);
        registrations.push_back(std::make_unique<RegisteredChild>(pid, ChildRole::Worker));
    }
    for (const pid_t pid : pids) {
        int status = 0;
        waitpid(pid, &status, 0);
    }
    std::vector<json> results(tasks.size());
    for (size_t t = 0; t < tasks.size(); ++t) {
        std::ifstream in(result_file(t));
        json result = in ? json::parse(in, nullptr, false) : json();
        if (result.is_discarded() || !result.is_object()) result = {{"note", "not shrunk: the shrinking child ended without a result"}};
        results[t] = std::move(result);
        std::error_code ec;
        fs::remove(result_file(t), ec);
    }
    const auto minimal_of = [&](size_t record, int run) -> json& {
        CaseRecord& rec = records[record];
        return (run < 0 ? rec.detail : rec.runs[static_cast<size_t>(run)].detail)["minimal"];
    };
    for (const RepeatedFailure& r : repeats) {
        json& m = minimal_of(r.record, r.run) = results[r.task];
        m["same_as"] = tasks[r.task].job->id;  // the case whose shrinking this is
    }
    for (size_t t = 0; t < tasks.size(); ++t) minimal_of(tasks[t].record, tasks[t].run) = std::move(results[t]);
}

}  // namespace crossdiv::verification
