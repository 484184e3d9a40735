#include "crossdiv/verification/suite/subject_shrink.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <fstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/verification/suite/operations.h"
#include "crossdiv/verification/suite/roster_table.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct ShrinkTask {
    size_t record = 0;
    const SuiteJob* job = nullptr;
    std::string subject, file;  ///< the subject's name; the minimal mesh's path in the output folder
};

/// The file name of a subject's minimal input: its roster's and its own name and the scheme,
/// characters other than letters, digits, '-', '_' and '.' replaced.
std::string minimal_name(const RosterRow& row) {
    std::string s = (row.roster.empty() ? "" : row.roster + "-") + row.subject + "-" + row.scheme;
    for (char& c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '_';
    return "minimal/" + s + ".obj";
}

/// The case of `task` run again with the subject alone, shrunk; its minimal mesh written.
json shrink_one(const ShrinkTask& task, const std::string& out_dir) {
    const ManifestEntry& entry = *task.job->entry;
    RefinementRequest req = entry.request;
    req.subject = entry.subject->program.get();
    req.references.clear();
    req.without_references = true;
    req.view_max_faces = 0;
    PolyMesh input = load_input(task.job->input);
    std::vector<std::string> notes;
    if (req.scheme != Scheme::Loop) req.rule = rule_with_tags(req.scheme, entry.rule_flags, input, notes);
    const ShrinkResult r = shrink_divergence(input, task.job->input, req);
    const fs::path path = fs::path(out_dir) / task.file;
    create_output_folder(path.parent_path().string());
    write_mesh(path.string(), r.minimal);
    return {{"mesh", task.file},
            {"faces", r.minimal.num_faces()},
            {"vertices", r.minimal.num_vertices()},
            {"symptom", describe(r.symptom, "subject '" + task.subject + "'", "")},
            {"tests", r.tests},
            {"reference", ""}};
}

}  // namespace

void shrink_subject_failures(const std::vector<SuiteJob>& jobs, std::vector<CaseRecord>& records, const std::string& out_dir,
                             int workers) {
    std::vector<ShrinkTask> tasks;
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
            tasks.push_back({static_cast<size_t>(rec - records.begin()), &*job, row.subject, minimal_name(row)});
    }
    if (tasks.empty()) return;
    // Children, each every workers-th task, each task's result a JSON file the parent reads back:
    // a subject that takes a child down takes only its own record with it.
    workers = std::max(1, std::min<int>(workers, static_cast<int>(tasks.size())));
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
                } catch (const std::exception& e) {
                    result = {{"note", std::string("not shrunk: ") + e.what()}};
                }
                std::ofstream(result_file(t)) << json_text(result) << "\n";
            }
            _exit(0);
        }
        pids.push_back(pid);
        registrations.push_back(std::make_unique<RegisteredChild>(pid, ChildRole::Worker));
    }
    for (const pid_t pid : pids) {
        int status = 0;
        waitpid(pid, &status, 0);
    }
    for (size_t t = 0; t < tasks.size(); ++t) {
        std::ifstream in(result_file(t));
        json result = in ? json::parse(in, nullptr, false) : json();
        if (result.is_discarded() || !result.is_object()) result = {{"note", "not shrunk: the shrinking child ended without a result"}};
        records[tasks[t].record].detail["minimal"] = std::move(result);
        std::error_code ec;
        fs::remove(result_file(t), ec);
    }
}

}  // namespace crossdiv::verification
