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
#ifndef CROSSDIV_ADDRESS_SANITIZER
void* taken_chunks[65 * 7];  // settle_heap's; at namespace scope, so that the allocations stay
#endif

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

using detail::get;
using detail::get_vector;
using detail::put;
using detail::put_vector;

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
        put(f, m.face_varying.size());
        for (const FaceVaryingChannel& ch : m.face_varying) {
            put_string(f, ch.name);
            put(f, ch.dimension);
            put_vector(f, ch.values);
            put_vector(f, ch.corner_values);
        }
        put(f, m.source.notes.size());  // what a reader noted (an input read in a child)
        for (const std::string& note : m.source.notes) put_string(f, note);
        // A non-manifold level's tags inherited from its parent, which its faces do not state
        // (core's levels by OpenSubdiv's rules): without them a level run on again in this
        // process would be another mesh.
        put_vector(f, m.derived.corner_edges);
        put_vector(f, m.derived.nonmanifold_edges);
        put_vector(f, m.derived.sharp_vertices);
    }
}
bool read_trace(FILE* f, adapters::LevelTrace& trace) {
    size_t n = 0;
    if (!get(f, n) || n > 64) return false;
    trace.resize(n);
    for (PolyMesh& m : trace) {
        if (!get_vector(f, m.positions) || !get_vector(f, m.face_start) || !get_vector(f, m.face_vertices) ||
            !get_vector(f, m.creases.holes))
            return false;
        size_t channels = 0;
        if (!get(f, channels) || channels > 64) return false;
        m.face_varying.resize(channels);
        for (FaceVaryingChannel& ch : m.face_varying) {
            ch.name = get_string(f);
            if (!get(f, ch.dimension) || !get_vector(f, ch.values) || !get_vector(f, ch.corner_values)) return false;
        }
        size_t notes = 0;
        if (!get(f, notes) || notes > 4096) return false;
        m.source.notes.resize(notes);
        for (std::string& note : m.source.notes) note = get_string(f);
        if (!get_vector(f, m.derived.corner_edges) || !get_vector(f, m.derived.nonmanifold_edges) ||
            !get_vector(f, m.derived.sharp_vertices))
            return false;
    }
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

namespace detail {

RunOutcome outcome_of(const std::function<void()>& call) {
    RunOutcome o;
    const auto t0 = Clock::now();
    try {
        call();
    } catch (const adapters::Rejected& e) {
        o = {RunStatus::Rejected, one_line(e.what()), 0};
    } catch (const adapters::InvalidResult& e) {
        o = {RunStatus::UnreadableOutput, one_line(e.what()), 0};
    } catch (const ImplementationFailure& e) {
        o = {e.status(), one_line(e.what()), 0};
    } catch (const std::exception& e) {
        o = {RunStatus::Threw, one_line(e.what()), 0};
    }
    o.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return o;
}

RunOutcome run_in_child(const std::function<void(FILE*)>& work, const std::function<bool(FILE*)>& read,
                        const std::function<RunOutcome()>& here, double timeout_seconds, int heap_fill) {
    FILE* answer = std::tmpfile();
    FILE* header = std::tmpfile();
    FILE* errors = std::tmpfile();
    const auto close_all = [&] {
        for (FILE* f : {answer, header, errors})
            if (f) std::fclose(f);
    };
    if (!answer || !header || !errors) {
        close_all();
        return here();  // no temporary files: better unisolated than not at all
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
        const RunOutcome o = outcome_of([&] { work(answer); });
        std::fflush(answer);
        put(header, static_cast<int>(o.status));
        put_string(header, o.message);
        std::fflush(header);
        _exit(0);
    }
    if (hooks.in_parent) hooks.in_parent();
    if (pid < 0) {
        close_all();
        return here();
    }
    const RegisteredChild registration(pid, ChildRole::Isolated);
    int status = 0;
    bool timed_out = false;
    if (!wait_for_child(pid, status, timeout_seconds - std::chrono::duration<double>(Clock::now() - t0).count())) {
        kill(pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
        timed_out = true;
    }
    RunOutcome o;
    o.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    const std::string stderr_tail = tail_of(errors);
    int code = -1;
    std::rewind(header);
    if (timed_out) {
        o.status = RunStatus::Timeout;
        o.message = "no answer after " + std::to_string(timeout_seconds) + " s";
    } else if (WIFSIGNALED(status)) {
        o.status = RunStatus::Crashed;
        o.message = std::string("signal ") + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
        if (!stderr_tail.empty()) o.message += "; stderr: " + stderr_tail;
    } else if (!get(header, code)) {
        o.status = RunStatus::Crashed;
        o.message = "exited with code " + std::to_string(WEXITSTATUS(status)) + " before answering";
        if (!stderr_tail.empty()) o.message += "; stderr: " + stderr_tail;
    } else {
        o.status = static_cast<RunStatus>(code);
        o.message = get_string(header);
        if (o.status == RunStatus::Ok) {
            std::rewind(answer);
            if (!read(answer)) o = {RunStatus::Crashed, "answer truncated", o.seconds};
        } else if (!stderr_tail.empty()) {
            o.message += " (stderr: " + stderr_tail + ")";
        }
    }
    close_all();
    return o;
}

}  // namespace detail

IsolatedTrace run_isolated(const std::function<adapters::LevelTrace()>& fn, double timeout_seconds, bool isolate,
                           int heap_fill) {
    IsolatedValue<adapters::LevelTrace> v =
        run_isolated_value<adapters::LevelTrace>(fn, write_trace, read_trace, timeout_seconds, isolate, heap_fill);
    return {v.outcome, std::move(v.value)};
}

}  // namespace crossdiv::verification
