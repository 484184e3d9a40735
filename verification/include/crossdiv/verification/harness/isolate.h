#pragma once
/// @file
/// Runs a reference library in a child process with a time limit, so that a crash, an abort,
/// a hang or an exception in the library is recorded and the run goes on.

#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/verification/harness/verdict.h"

namespace crossdiv::verification {

/// How a run of an implementation ended. The first five apply to every implementation; the
/// rest to a program (an external subject or reference), whose result is read from a file.
enum class RunStatus {
    Ok,                ///< returned a result
    Rejected,          ///< refused the input or option (adapters::Rejected)
    Threw,             ///< threw any other exception
    Crashed,           ///< died by a signal, or exited without a result
    Timeout,           ///< still running at the time limit; killed
    ExitStatus,        ///< a program exited with a nonzero status
    NoOutput,          ///< a program exited 0 without writing its output file
    UnreadableOutput,  ///< its output does not read as a mesh: a program's file does not parse (the message
                       ///< names file:line), a library's mesh has a face that never closes (adapters::InvalidResult)
    NonFiniteOutput,   ///< its output has a NaN or infinite coordinate
    WrongCount,        ///< its output has another number of vertices or faces than the scheme makes
    NotTriangles,      ///< its output has a face that is not a triangle where the scheme makes triangles
    Unavailable,       ///< a program that is not on this machine (its setup command failed); not run
};

/// "ok", "rejected", "threw", "crashed", "timeout", "exit-status", "no-output",
/// "unreadable-output", "non-finite-output", "wrong-count", "not-triangles", "unavailable".
const char* to_string(RunStatus status);
/// The status to_string names. @throws InputError for another name.
RunStatus run_status_from_string(const std::string& name);

/// Whether the run made a result that is not a mesh of the scheme (an implementation that lies).
inline bool is_invalid_output(RunStatus status) {
    return status == RunStatus::UnreadableOutput || status == RunStatus::NonFiniteOutput ||
           status == RunStatus::WrongCount || status == RunStatus::NotTriangles;
}

/// An implementation's run failed in a way it names: thrown by implementations that run a
/// program, caught by run_isolated and recorded as the run's status.
class ImplementationFailure : public std::runtime_error {
public:
    ImplementationFailure(RunStatus status, const std::string& message) : std::runtime_error(message), status_(status) {}
    RunStatus status() const { return status_; }

private:
    RunStatus status_;
};

struct RunOutcome {
    RunStatus status = RunStatus::Ok;
    std::string message;  ///< the library's or exception's words; the signal name when crashed
    double seconds = 0;   ///< wall time of the run (the child's, when isolated)
    /// "ok", "rejected: <message>", "threw: <message>", "crashed: <signal>", "timeout".
    std::string summary() const;
    /// What a failed run's verdict explains: a refusal in the library's words, else summary().
    std::string failure_explanation() const { return status == RunStatus::Rejected ? message : summary(); }
};

/// The verdict on a reference run that made no usable result: ref-rejected when it refused,
/// ref-unavailable when it is not on this machine,
/// ref-invalid-output when its result is not a mesh of the scheme, ref-crashed when it threw,
/// crashed, hung or wrote nothing.
inline Verdict verdict_of_failed_run(RunStatus status) {
    return status == RunStatus::Rejected      ? Verdict::RefRejected
           : status == RunStatus::Unavailable ? Verdict::RefUnavailable
           : is_invalid_output(status)        ? Verdict::RefInvalidOutput
                                              : Verdict::RefCrashed;
}

/// A verdict reached before anything is compared, with its explanation.
struct EarlyVerdict {
    Verdict verdict;
    std::string explanation;
};

/// The verdict of a comparison that has nothing to compare: the reference made no result
/// (ref-rejected or ref-crashed, in its words), or core refused the input (`core_error`) while
/// the reference made one (ours-rejected, explained by `ours_rejected`). Nothing when both made one.
inline std::optional<EarlyVerdict> verdict_before_comparing(const RunOutcome& reference, const std::string& core_error,
                                                            const std::string& ours_rejected) {
    if (reference.status != RunStatus::Ok) return EarlyVerdict{verdict_of_failed_run(reference.status), reference.failure_explanation()};
    if (!core_error.empty()) return EarlyVerdict{Verdict::OursRejected, ours_rejected};
    return std::nullopt;
}

struct IsolatedTrace {
    RunOutcome outcome;
    /// Present when outcome.status is Ok; refine_isolated keeps it for NonFiniteOutput too (the
    /// positions as the implementation made them), so that a comparison can tell where they are.
    std::optional<adapters::LevelTrace> trace;
};

/// The byte glibc's malloc fills an isolated child's memory with (mallopt M_PERTURB: new
/// allocations get its complement, freed ones the byte itself). A library that reads memory it
/// never wrote (OpenMesh's Loop leaves an isolated vertex's new position unset) then reads the
/// same bytes in every run, whatever this process's heap held before the fork, so its result
/// depends on its input alone; a second run with kSecondHeapFill shows whether it reads such
/// memory at all. Not in effect under the address sanitizer, whose allocator replaces malloc's.
inline constexpr int kHeapFill = 0xA5;
inline constexpr int kSecondHeapFill = 0x3C;

/// Memory an isolated run may take beyond what this process already holds (RLIMIT_AS in the
/// child): a reference that allocates without bound on hostile input fails fast and is
/// recorded, instead of taking the machine's memory. 6 GiB
/// is 15x what the largest comparison a reference is given (16M faces, about 150 bytes per
/// face each) needs. Not applied under the address sanitizer, which reserves its shadow
/// memory as address space.
inline constexpr long long kIsolatedMemoryBytes = 6LL << 30;

/// What a host process does around the forks of run_isolated so that the child can run its code.
/// The Python module sets them to Python's own PyOS_BeforeFork / PyOS_AfterFork_*: a Python
/// thread that held or wanted the interpreter's lock at the fork does not exist in the child, and
/// without them the child waits for it forever (a subject recorded as a timeout).
struct ForkHooks {
    void (*before)() = nullptr;     ///< in the parent, just before fork()
    void (*in_parent)() = nullptr;  ///< in the parent, just after (whether or not the fork worked)
    void (*in_child)() = nullptr;   ///< in the child, first thing
};
/// Sets the hooks of every later run_isolated in this process.
void set_fork_hooks(const ForkHooks& hooks);

/// The outcome of a call run in an isolated child and, when it is Ok, the value it returned.
template <class T>
struct IsolatedValue {
    RunOutcome outcome;
    std::optional<T> value;
};

namespace detail {
// The child's answer as raw bytes: trivially copyable values and vectors of them.
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

/// `call`'s outcome: Ok, or the status its exception names (adapters::Rejected: Rejected,
/// adapters::InvalidResult: UnreadableOutput, ImplementationFailure: its own, any other: Threw),
/// the message on one line; with its wall time.
RunOutcome outcome_of(const std::function<void()>& call);

/// Forks; the child runs `work`, which calls the library and writes its value to the file it is
/// given, under the time and memory limits and the heap fill; the parent reads the value back
/// with `read` when the child's outcome is Ok. `here` runs the call in this process instead when
/// no child can be made (no temporary file, fork fails).
RunOutcome run_in_child(const std::function<void(FILE*)>& work, const std::function<bool(FILE*)>& read,
                        const std::function<RunOutcome()>& here, double timeout_seconds, int heap_fill);
}  // namespace detail

/// `fn` in a forked child as run_isolated runs a refinement, for any value that `write` and
/// `read` ship through a file (detail::put_vector and friends). With `isolate` false it runs here.
template <class T>
IsolatedValue<T> run_isolated_value(const std::function<T()>& fn, void (*write)(FILE*, const T&), bool (*read)(FILE*, T&),
                                    double timeout_seconds, bool isolate = true, int heap_fill = kHeapFill) {
    IsolatedValue<T> r;
    const auto here = [&] { return detail::outcome_of([&] { r.value = fn(); }); };
    if (!isolate) {
        r.outcome = here();
        return r;
    }
    r.outcome = detail::run_in_child([&](FILE* f) { write(f, fn()); },
                                     [&](FILE* f) {
                                         T v;
                                         if (!read(f, v)) return false;
                                         r.value = std::move(v);
                                         return true;
                                     },
                                     here, timeout_seconds, heap_fill);
    if (r.outcome.status != RunStatus::Ok) r.value.reset();
    return r;
}

/// Runs `fn` in a forked child with a time limit of `timeout_seconds`, a memory limit of
/// kIsolatedMemoryBytes and its heap filled with `heap_fill`, and ships its result back through
/// a temporary file; the child's stderr is captured into the outcome's message when the run
/// fails. With `isolate` false it runs in this process (for debugging; a crash then takes the
/// process down, and the heap is not filled).
IsolatedTrace run_isolated(const std::function<adapters::LevelTrace()>& fn, double timeout_seconds, bool isolate = true,
                           int heap_fill = kHeapFill);

}  // namespace crossdiv::verification
