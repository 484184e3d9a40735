#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/verification/harness/process.h"
#include "sanitizer.h"

#include <malloc.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace crossdiv::verification {
namespace {

using Clock = std::chrono::steady_clock;

/// Caps this (child) process's address space at what it maps now plus kIsolatedMemoryBytes.
void limit_memory() {
#ifndef CROSSDIV_ADDRESS_SANITIZER
    long long pages = 0;
    if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%lld", &pages) != 1) pages = 0;
        std::fclose(statm);
    }
    if (pages <= 0) return;  // unknown size: no cap rather than a wrong one
    const rlim_t cap = static_cast<rlim_t>(pages * sysconf(_SC_PAGESIZE) + kIsolatedMemoryBytes);
    const rlimit limit{cap, cap};
    setrlimit(RLIMIT_AS, &limit);
#endif
}

/// Makes what an isolated child's allocations hold before they are written the same in every
/// run, whatever this process's heap held at the fork: every allocation malloc makes is filled
/// with the complement of `heap_fill` (mallopt M_PERTURB). glibc hands out the thread's cache of
/// recently freed small chunks (the tcache: up to 7 chunks of each size up to 1032 bytes) without
/// filling them, so those chunks, freed before the fork and holding the parent's data, are
/// taken first and kept (the child ends by _exit). The address sanitizer's allocator replaces
/// malloc's and fills on its own.
void* taken_chunks[65 * 7];  // settle_heap's; at namespace scope, so that the allocations stay

void settle_heap(int heap_fill) {
#ifndef CROSSDIV_ADDRESS_SANITIZER
    mallopt(M_PERTURB, heap_fill);
    size_t i = 0;
    for (size_t size = 8; size <= 1032; size += 16)
        for (int k = 0; k < 7; ++k) taken_chunks[i++] = std::malloc(size);
#else
    (void)heap_fill;
#endif
}

// A minimal binary format for the child's answer: a status byte, a message, then the trace.
template <class T>
void put(FILE* f, const T& x) { std::fwrite(&x, sizeof x, 1, f); }
template <class T>
bool get(FILE* f, T& x) { return std::fread(&x, sizeof x, 1, f) == 1; }
template <class T>
void put_vector(FILE* f, const std::vector<T>& v) {
    put(f, v.size());
    if (!v.empty()) std::fwrite(v.data(), sizeof(T), v.size(), f);
}
template <class T>
bool get_vector(FILE* f, std::vector<T>& v) {
    size_t n = 0;
    if (!get(f, n) || n > (size_t(1) << 34) / sizeof(T)) return false;
    v.resize(n);
    return n == 0 || std::fread(v.data(), sizeof(T), n, f) == n;
}
void put_string(FILE* f, const std::string& s) { put_vector(f, std::vector<char>(s.begin(), s.end())); }
std::string get_string(FILE* f) {
    std::vector<char> v;
    get_vector(f, v);
    return {v.begin(), v.end()};
}

void write_trace(FILE* f, const adapters::LevelTrace& trace) {
    put(f, trace.size());
    for (const PolyMesh& m : trace) {
        put_vector(f, m.positions);
        put_vector(f, m.face_start);
        put_vector(f, m.face_vertices);
        put_vector(f, m.creases.holes);  // faces the library does not emit
    }
}
bool read_trace(FILE* f, adapters::LevelTrace& trace) {
    size_t n = 0;
    if (!get(f, n) || n > 64) return false;
    trace.resize(n);
    for (PolyMesh& m : trace)
        if (!get_vector(f, m.positions) || !get_vector(f, m.face_start) || !get_vector(f, m.face_vertices) ||
            !get_vector(f, m.creases.holes))
            return false;
    return true;
}

/// An exception's message on one line (CGAL's assertion messages span several), so that a
/// record's explanation is one line in every output.
std::string one_line(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

IsolatedTrace run_here(const std::function<adapters::LevelTrace()>& fn) {
    IsolatedTrace r;
    const auto t0 = Clock::now();
    try {
        r.trace = fn();
    } catch (const adapters::Rejected& e) {
        r.outcome = {RunStatus::Rejected, one_line(e.what()), 0};
    } catch (const adapters::InvalidResult& e) {
        r.outcome = {RunStatus::UnreadableOutput, one_line(e.what()), 0};
    } catch (const ImplementationFailure& e) {
        r.outcome = {e.status(), one_line(e.what()), 0};
    } catch (const std::exception& e) {
        r.outcome = {RunStatus::Threw, one_line(e.what()), 0};
    }
    r.outcome.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return r;
}

/// The last few lines the child wrote to stderr, to explain a crash or a rejection.
std::string tail_of(FILE* f) {
    std::fflush(f);
    return stderr_summary(head_and_tail(fileno(f)));
}

ForkHooks& fork_hooks() {
    static ForkHooks hooks;
    return hooks;
}

}  // namespace

void set_fork_hooks(const ForkHooks& hooks) { fork_hooks() = hooks; }

const char* to_string(RunStatus status) {
    switch (status) {
        case RunStatus::Ok: return "ok";
        case RunStatus::Rejected: return "rejected";
        case RunStatus::Threw: return "threw";
        case RunStatus::Crashed: return "crashed";
        case RunStatus::Timeout: return "timeout";
        case RunStatus::ExitStatus: return "exit-status";
        case RunStatus::NoOutput: return "no-output";
        case RunStatus::UnreadableOutput: return "unreadable-output";
        case RunStatus::NonFiniteOutput: return "non-finite-output";
        case RunStatus::WrongCount: return "wrong-count";
        case RunStatus::NotTriangles: return "not-triangles";
        case RunStatus::Unavailable: return "unavailable";
    }
    return "unknown";
}

RunStatus run_status_from_string(const std::string& name) {
    for (RunStatus s : {RunStatus::Ok, RunStatus::Rejected, RunStatus::Threw, RunStatus::Crashed, RunStatus::Timeout,
                        RunStatus::ExitStatus, RunStatus::NoOutput, RunStatus::UnreadableOutput, RunStatus::NonFiniteOutput,
                        RunStatus::WrongCount, RunStatus::NotTriangles, RunStatus::Unavailable})
        if (name == to_string(s)) return s;
    throw InputError("unknown run status '" + name + "'");
}

std::string RunOutcome::summary() const {
    if (status == RunStatus::Ok || status == RunStatus::Timeout) return to_string(status);
    return std::string(to_string(status)) + ": " + message;
}

IsolatedTrace run_isolated(const std::function<adapters::LevelTrace()>& fn, double timeout_seconds, bool isolate,
                           int heap_fill) {
    if (!isolate) return run_here(fn);
    FILE* result = std::tmpfile();
    FILE* errors = std::tmpfile();
    if (!result || !errors) {
        if (result) std::fclose(result);
        if (errors) std::fclose(errors);
        return run_here(fn);  // no temporary files: better unisolated than not at all
    }
    std::fflush(nullptr);
    const auto t0 = Clock::now();
    const ForkHooks hooks = fork_hooks();
    if (hooks.before) hooks.before();
    const pid_t pid = fork();
    if (pid == 0) {
        // Child: run, write the answer, leave without running the parent's atexit handlers.
        if (hooks.in_child) hooks.in_child();
        prctl(PR_SET_PDEATHSIG, SIGKILL);  // not outliving a parent killed outright
        dup2(fileno(errors), STDERR_FILENO);
        limit_memory();
        settle_heap(heap_fill);
        const IsolatedTrace r = run_here(fn);
        put(result, static_cast<int>(r.outcome.status));
        put_string(result, r.outcome.message);
        if (r.trace) write_trace(result, *r.trace);
        std::fflush(result);
        _exit(0);
    }
    if (hooks.in_parent) hooks.in_parent();
    IsolatedTrace r;
    if (pid < 0) {
        std::fclose(result);
        std::fclose(errors);
        return run_here(fn);
    }
    const RegisteredChild registration(pid, ChildRole::Isolated);
    int status = 0;
    bool timed_out = false;
    for (auto pause = std::chrono::microseconds(200);;) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) break;
        if (std::chrono::duration<double>(Clock::now() - t0).count() > timeout_seconds) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            timed_out = true;
            break;
        }
        std::this_thread::sleep_for(pause);
        pause = std::min(pause * 2, std::chrono::microseconds(20000));
    }
    r.outcome.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    const std::string stderr_tail = tail_of(errors);
    if (timed_out) {
        r.outcome.status = RunStatus::Timeout;
        r.outcome.message = "no answer after " + std::to_string(timeout_seconds) + " s";
    } else if (WIFSIGNALED(status)) {
        r.outcome.status = RunStatus::Crashed;
        r.outcome.message = std::string("signal ") + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
        if (!stderr_tail.empty()) r.outcome.message += "; stderr: " + stderr_tail;
    } else {
        std::rewind(result);
        int code = -1;
        if (!get(result, code)) {
            r.outcome.status = RunStatus::Crashed;
            r.outcome.message = "exited with code " + std::to_string(WEXITSTATUS(status)) + " before answering";
            if (!stderr_tail.empty()) r.outcome.message += "; stderr: " + stderr_tail;
        } else {
            r.outcome.status = static_cast<RunStatus>(code);
            r.outcome.message = get_string(result);
            if (r.outcome.status == RunStatus::Ok) {
                adapters::LevelTrace trace;
                if (read_trace(result, trace)) r.trace = std::move(trace);
                else r.outcome = {RunStatus::Crashed, "answer truncated", r.outcome.seconds};
            } else if (!stderr_tail.empty()) {
                r.outcome.message += " (stderr: " + stderr_tail + ")";
            }
        }
    }
    std::fclose(result);
    std::fclose(errors);
    return r;
}

}  // namespace crossdiv::verification
