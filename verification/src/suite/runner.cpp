#include "crossdiv/verification/suite/runner.h"

#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <memory>
#include <fstream>
#include <map>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/harness/program_server.h"
#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/verification/suite/operations.h"
#include "crossdiv/verification/harness/appended_lines.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/implementations/output_size.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// A job that made no record: core refused its input, or failed.
CaseRecord failed_job(const SuiteJob& job, const std::string& why, bool ours_failed) {
    CaseRecord c = failed_case(job.input, job.entry->operation->name, why, ours_failed);
    const OperationKind kind = job.entry->operation->kind;
    if (kind != OperationKind::Comparison && kind != OperationKind::Invariance) return c;
    // The scheme, rule and levels the case was to run, as a case that ran states them: the
    // report counts each scheme's runs (an invariance case's too) on its own row.
    const RefinementRequest& r = job.entry->request;
    if (r.scheme == Scheme::Loop) {
        c.weights = to_string(r.rule.loop.weights);
        c.boundary = to_string(r.rule.loop.boundary);
    } else {
        c.boundary = job.entry->rule_flags.boundary.empty() ? "default" : job.entry->rule_flags.boundary;
    }
    c.levels = r.levels;
    c.tolerance = r.tolerance;
    if (kind == OperationKind::Invariance) c.detail["scheme"] = to_string(r.scheme);
    else c.tier = to_string(r.tier);
    return c;
}

/// The jobs of a run, handed out one at a time to whichever worker is free (a worker with a
/// long job does not hold up the jobs behind it): a counter and, per job, the worker that took
/// it, in memory the forked workers share with the parent.
class JobQueue {
public:
    explicit JobQueue(size_t jobs) : jobs_(static_cast<int>(jobs)) {
        bytes_ = sizeof(std::atomic<int>) * (jobs + 1);
        void* p = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw std::runtime_error("mmap of the job queue failed");
        slots_ = static_cast<std::atomic<int>*>(p);
        new (&slots_[0]) std::atomic<int>(0);
        for (size_t i = 1; i <= jobs; ++i) new (&slots_[i]) std::atomic<int>(-1);
    }
    JobQueue(const JobQueue&) = delete;
    JobQueue& operator=(const JobQueue&) = delete;
    ~JobQueue() { munmap(slots_, bytes_); }

    /// The next job for worker w, -1 when none is left.
    int take(int w) {
        const int i = slots_[0].fetch_add(1);
        if (i >= jobs_) return -1;
        slots_[i + 1].store(w);
        return i;
    }
    /// The worker that took job i, -1 if none did.
    int taker(int i) const { return slots_[i + 1].load(); }

private:
    static_assert(std::atomic<int>::is_always_lock_free, "a lock-free atomic works across processes");
    int jobs_;
    size_t bytes_ = 0;
    std::atomic<int>* slots_ = nullptr;
};

void identify(const SuiteJob& job, CaseRecord& c) {
    c.job = job.index;
    c.id = job.id;
    c.manifest_line = job.entry->line;
}

CaseRecord run_job_untimed(const SuiteJob& job, const std::string& out_dir) {
    CaseRecord c;
    try {
        c = job.entry->operation->run(job, out_dir);
    } catch (const OverSizeLimit& e) {
        // Past the manifest's max-faces: not run, by the manifest's own word.
        c = failed_job(job, e.what(), false);
        c.refusal = DivergenceClass::None;
    } catch (const InputError& e) {
        // An input core refuses, with nothing to hand the references either: a failure unless the
        // case declares the refusal (a check's file that no longer reads would take its checks with it).
        c = failed_job(job, e.what(), false);
        const std::vector<DivergenceClass>& declared = job.entry->request.expected_refusals;
        if (std::find(declared.begin(), declared.end(), DivergenceClass::InvalidInputHandling) != declared.end())
            c.refusal = DivergenceClass::InvalidInputHandling;
        else
            c.core_error += "; a refusal the case does not declare expected (refuses=invalid-input-handling)";
    } catch (const std::exception& e) {
        c = failed_job(job, std::string("internal error: ") + e.what(), true);
    }
    identify(job, c);
    return c;
}

}  // namespace

CaseRecord run_job(const SuiteJob& job, const std::string& out_dir) {
    const auto start = std::chrono::steady_clock::now();
    CaseRecord c = run_job_untimed(job, out_dir);
    c.job_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return c;
}

std::vector<CaseRecord> run_jobs(const std::vector<SuiteJob>& jobs, int workers, const std::string& out_dir,
                                 const std::function<void(int, int, const CaseRecord&)>& progress) {
    workers = std::max(1, std::min<int>(workers, static_cast<int>(jobs.size())));
    create_output_folder(out_dir);
    int pipe_fd[2];
    if (pipe(pipe_fd) != 0) throw std::runtime_error("pipe failed");
    std::vector<pid_t> pids;
    std::vector<std::unique_ptr<RegisteredChild>> registrations;
    std::vector<fs::path> parts;
    JobQueue queue(jobs.size());
    std::fflush(nullptr);
    for (int w = 0; w < workers; ++w) {
        parts.push_back(fs::path(out_dir) / ("worker" + std::to_string(w) + ".jsonl"));
        const pid_t pid = fork();
        if (pid < 0) throw std::runtime_error("fork failed");
        if (pid == 0) {
            // Worker w: the next job nobody has taken, until none is left; one JSON line per
            // record, then a line on the pipe with the job index (short writes to a pipe are
            // atomic).
            stop_cleanly_on_signals();
            close(pipe_fd[0]);
            std::ofstream part(parts.back());
            for (int i; (i = queue.take(w)) >= 0;) {
                part << json_text(to_json(run_job(jobs[static_cast<size_t>(i)], out_dir))) + "\n" << std::flush;
                if (!part) {  // a full disk: the parent records the job as ended without a record
                    std::fprintf(stderr, "crossdiv: %s: cannot write\n", parts.back().c_str());
                    _exit(1);
                }
                const std::string msg = std::to_string(i) + "\n";
                if (write(pipe_fd[1], msg.data(), msg.size()) < 0) _exit(1);
            }
            part.close();
            stop_program_servers();  // their folders go with them: destructors do not run at _exit
            _exit(0);
        }
        pids.push_back(pid);
        registrations.push_back(std::make_unique<RegisteredChild>(pid, ChildRole::Worker));
    }
    close(pipe_fd[1]);

    // Progress: read finished indices as they come; records are read back from the files,
    // whole lines only: a worker may be writing its next record while this one is read.
    std::map<int, CaseRecord> done;
    std::vector<AppendedLines> records;
    for (const fs::path& p : parts) records.emplace_back(p.string());
    auto collect = [&](int w) {
        for (const std::string& line : records[w].take_complete()) {
            const json rec = json::parse(line, nullptr, false);
            if (rec.is_discarded()) continue;  // its job is reported as ended without a record
            CaseRecord c = case_record_from_json(rec);
            done.emplace(c.job, std::move(c));
        }
    };
    std::string buffer;
    char chunk[256];
    for (ssize_t n; (n = read(pipe_fd[0], chunk, sizeof chunk)) != 0;) {
        if (n < 0) {
            if (errno == EINTR) continue;
            break;
        }
        buffer.append(chunk, static_cast<size_t>(n));
        for (size_t nl; (nl = buffer.find('\n')) != std::string::npos;) {
            const size_t i = std::stoul(buffer.substr(0, nl));
            buffer.erase(0, nl + 1);
            collect(queue.taker(static_cast<int>(i)));
            const auto it = done.find(jobs[i].index);
            if (it != done.end()) progress(static_cast<int>(done.size()), static_cast<int>(jobs.size()), it->second);
        }
    }
    close(pipe_fd[0]);
    // Stopped from outside: the watcher ends this process by the signal once it has cleaned up;
    // the jobs the workers did not reach are not failures to record.
    if (stop_requested()) await_stop();
    std::vector<int> died(workers, 0);
    for (int w = 0; w < workers; ++w) {
        int status = 0;
        waitpid(pids[w], &status, 0);
        if (WIFSIGNALED(status)) died[w] = WTERMSIG(status);
        collect(w);
        std::error_code ec;
        fs::remove(parts[w], ec);
    }
    std::vector<CaseRecord> out;
    for (size_t i = 0; i < jobs.size(); ++i) {
        auto it = done.find(jobs[i].index);
        if (it != done.end()) {
            out.push_back(std::move(it->second));
            continue;
        }
        // The worker that took it died in core (a crash of ours, not of a reference: those are
        // isolated); or every worker ended before it was taken.
        const int w = queue.taker(static_cast<int>(i));
        const int sig = w >= 0 ? died[static_cast<size_t>(w)] : 0;
        // SIGINT, SIGTERM, SIGHUP: the run was stopped from outside (the worker then ends
        // by that signal after cleaning up, stop_cleanly_on_signals), not a crash.
        const bool stopped = sig == SIGINT || sig == SIGTERM || sig == SIGHUP;
        const std::string how = stopped ? "worker stopped by signal " : "worker crashed in core: signal ";
        CaseRecord c = failed_job(jobs[i],
                                  w < 0  ? std::string("not run: every worker had ended")
                                  : sig  ? how + std::to_string(sig) + " (" + strsignal(sig) + ")"
                                         : "worker ended without a record",
                                  true);
        identify(jobs[i], c);
        progress(static_cast<int>(out.size() + 1), static_cast<int>(jobs.size()), c);
        out.push_back(std::move(c));
    }
    return out;
}

std::string describe_record(const CaseRecord& c) {
    if (c.runs.empty()) return outcome_label(c) + ": " + c.core_error;
    const OperationKind kind = find_operation(c.operation).kind;
    if (kind == OperationKind::Comparison) {
        std::string s;
        for (const RunRecord& r : c.runs) s += (s.empty() ? "" : ", ") + r.reference + " " + outcome_label(c, r);
        return s;
    }
    // The same counting as the summary and JUnit (is_failure): an unexplained divergence
    // fails; a divergence whose cause is measured (a study's boundary-rule, say) is a
    // finding; a reference that crashed or refused is its own outcome, counted by name.
    int failed = 0, classified = 0;
    std::string which;
    std::map<std::string, int> other;
    for (const RunRecord& r : c.runs) {
        if (r.outcome.verdict == Verdict::Agree) continue;
        if (is_failure(c, r)) {
            ++failed;
            if (which.size() < 200) which += " " + r.subject + "/" + r.check;
        } else if (r.outcome.verdict == Verdict::Diverge) {
            ++classified;
        } else {
            ++other[outcome_label(c, r)];
        }
    }
    const std::string what = c.operation == "curves" ? " curve checks" : c.operation == "surfaces" ? " surface checks" : " checks";
    std::string s = std::to_string(c.runs.size()) + what;
    if (classified) s += ", " + std::to_string(classified) + " classified divergences";
    for (const auto& [label, n] : other) s += ", " + std::to_string(n) + " " + label;
    if (failed) return s + ", " + std::to_string(failed) + " FAILED:" + which;
    return s + (classified || !other.empty() ? ", no failure" : ", all within tolerance");
}

}  // namespace crossdiv::verification
