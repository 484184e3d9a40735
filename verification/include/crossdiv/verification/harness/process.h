#pragma once
/// @file
/// Running an external program from an argument vector, never through a shell: no quoting,
/// no word splitting, no injection through a file name.

#include <sys/types.h>

#include <string>
#include <vector>

namespace crossdiv::verification {

/// Runs argv[0] (looked up on PATH when it has no slash) with the arguments argv[1..],
/// inheriting standard output and error, and waits for it. Returns its exit status, or
/// 128 + the signal number when a signal ended it.
/// @throws InputError when the program cannot be started (naming it and the reason).
int run_process(const std::vector<std::string>& argv);

/// How to run a program that is itself under test: confined to a folder and a time limit.
struct ProcessLimits {
    std::string working_dir;      ///< its current folder (empty: ours)
    double timeout_seconds = 120; ///< then its whole process group is killed
    std::string stdout_path;      ///< where its standard output goes (empty: /dev/null)
    std::string stderr_path;      ///< where its standard error goes (empty: /dev/null)
};

/// How a confined run ended.
struct ProcessResult {
    bool started = false;    ///< false: the program could not be started (`start_error` says why)
    std::string start_error;
    bool timed_out = false;  ///< killed at the time limit
    int exit_code = 0;       ///< when it exited
    int signal = 0;          ///< the signal that ended it (0: it exited)
    double seconds = 0;      ///< wall time
};

/// Runs argv as run_process does, but in its own process group (so that a time-out kills what
/// it started too), in `limits.working_dir`, with its output in files, and kills the group at
/// the time limit. Never throws for what the program does.
ProcessResult run_confined(const std::vector<std::string>& argv, const ProcessLimits& limits);

/// Waits for the child `pid` to end, at most `seconds`: true with its wait status in `status`
/// when it ended (reaped), false when the time ran out (still running, not reaped). It wakes
/// when the child ends (a pidfd polled), not at the next tick of a sleep: a run of 10 ms is
/// not charged 13 or 20.
bool wait_for_child(pid_t pid, int& status, double seconds);

/// Memory a program under test may take (RLIMIT_DATA: its heap and private writable mappings,
/// not the address space an interpreter or a JIT reserves without using): a program that
/// allocates without bound fails fast, as a library run does (kIsolatedMemoryBytes, 6 GiB, the
/// same reasoning). Not applied under the address sanitizer, whose shadow memory counts.
inline constexpr long long kProgramMemoryBytes = 6LL << 30;

/// The first and the last `bytes` of a regular file (all of it when it is shorter than twice
/// that), joined by "\n...\n": what a program wrote on stderr, read without holding gigabytes of
/// it. "" for a file that is not regular.
/// `from`: where in the file to start (what a long-running program wrote since a mark).
std::string head_and_tail(int fd, size_t bytes = 64 * 1024, off_t from = 0);

/// What a process said on stderr, on one line: the last `max_chars` characters, preceded by
/// the first line of a sanitizer report when there is one before them (ASan's legend fills
/// the tail and would hide which error it was).
std::string stderr_summary(std::string text, size_t max_chars = 400);

/// stderr_summary of a text file (a program's stderr), read by head_and_tail; "" when absent.
std::string tail_of_file(const std::string& path, size_t max_chars = 400);

}  // namespace crossdiv::verification
