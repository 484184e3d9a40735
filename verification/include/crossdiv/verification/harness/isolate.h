#pragma once
/// @file
/// Runs a reference library in a child process with a time limit, so that a crash, an abort,
/// a hang or an exception in the library is recorded and the run goes on.

#include <functional>
#include <optional>
#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/verification/harness/verdict.h"

namespace crossdiv::verification {

/// How a reference run ended.
enum class RunStatus {
    Ok,        ///< returned a result
    Rejected,  ///< refused the input or option (adapters::Rejected)
    Threw,     ///< threw any other exception
    Crashed,   ///< died by a signal, or exited without a result
    Timeout,   ///< still running at the time limit; killed
};

/// "ok", "rejected", "threw", "crashed", "timeout".
const char* to_string(RunStatus status);

struct RunOutcome {
    RunStatus status = RunStatus::Ok;
    std::string message;  ///< the library's or exception's words; the signal name when crashed
    double seconds = 0;   ///< wall time of the run (the child's, when isolated)
    /// "ok", "rejected: <message>", "threw: <message>", "crashed: <signal>", "timeout".
    std::string summary() const;
    /// What a failed run's verdict explains: a refusal in the library's words, else summary().
    std::string failure_explanation() const { return status == RunStatus::Rejected ? message : summary(); }
};

/// The verdict on a reference run that made no result: ref-rejected when it refused,
/// ref-crashed when it threw, crashed or hung.
inline Verdict verdict_of_failed_run(RunStatus status) {
    return status == RunStatus::Rejected ? Verdict::RefRejected : Verdict::RefCrashed;
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
    std::optional<adapters::LevelTrace> trace;  ///< present when outcome.status == Ok
};

/// Runs `fn` in a forked child with a time limit of `timeout_seconds` and ships its result
/// back through a temporary file; the child's stderr is captured into the outcome's message
/// when the run fails. With `isolate` false it runs in this process (for debugging; a crash
/// then takes the process down).
IsolatedTrace run_isolated(const std::function<adapters::LevelTrace()>& fn, double timeout_seconds, bool isolate = true);

}  // namespace crossdiv::verification
