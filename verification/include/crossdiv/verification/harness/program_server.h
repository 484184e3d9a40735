#pragma once
/// @file
/// A program under test kept running between runs: started once, then handed one run at a time.
///
/// Some references cost seconds to start and milliseconds to refine (Blender, an interpreter
/// that imports Open3D): started for every run, a suite spends most of its time starting them.
/// A program that can serve is started once per process of the harness (each forked suite
/// worker has its own) and asked for each run over a pipe; a run that crashes it, hangs it or
/// answers out of turn ends it, is recorded as that run's failure, and the next run starts it
/// again, so no run's verdict depends on another's.
///
/// The protocol, for a program to implement (adapters/common/serve.py does it for Python):
///   - requests arrive on its standard input, one line each: a JSON object
///     `{"id": N, "args": ["word", ...]}`, the arguments of one run as it would be started
///     with them alone (ProgramSpec::serve says which words those are);
///   - it answers on file descriptor 3, one line per request, after the run has written its
///     output file: `N STATUS`, the request's id and the exit status the run would have had;
///   - what a run says goes to its standard error, as a program started per run says it; its
///     standard output is discarded;
///   - end of its standard input: it exits.
/// It runs in a temporary folder of its own, in its own process group (killed whole at a
/// time-out or when it answers out of turn), under kProgramMemoryBytes of data.

#include <sys/types.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <vector>

#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/harness/temporary_folder.h"

namespace crossdiv::verification {

/// How one served run ended: as a run started on its own would (ProcessResult: the status it
/// answered, or the signal or exit of the server when it died in the run, or the time-out), and
/// what the server wrote on stderr during it.
struct ServedRun {
    ProcessResult process;
    std::string stderr_text;   ///< stderr_summary of what it wrote since the request
    /// It broke the protocol: answered with another id or an unreadable line, or closed its
    /// answers and went on (then it was killed); `stderr_text` says how.
    bool out_of_turn = false;
    bool started_now = false;  ///< the server was (re)started for this run: its start-up is in the time
};

/// A serving program, started on the first run and again after a run that ended it.
class ProgramServer {
public:
    /// @param argv the command that starts it (never run through a shell)
    /// @param label a name safe in a file name, for its temporary folder
    ProgramServer(std::vector<std::string> argv, std::string label);
    /// Closes its standard input and gives it a moment to exit, then kills its group.
    ~ProgramServer();
    ProgramServer(const ProgramServer&) = delete;
    ProgramServer& operator=(const ProgramServer&) = delete;

    /// One run with `args`, answered within `timeout_seconds` (start-up included when it starts
    /// the server). Never throws for what the program does.
    ServedRun run(const std::vector<std::string>& args, double timeout_seconds);

    /// How many times the program has been started.
    int starts() const { return starts_; }
    /// Whether this process has it running now.
    bool running() const { return process_ && owner_ == getpid(); }

    friend void stop_program_servers();

private:
    struct Process;  ///< the running program: pid, pipes, registration
    /// Starts the program; false with `error` when it cannot be started.
    bool start(std::string& error);
    /// Ends the program: its input closed, then (unless `at_once`) a moment to exit by itself,
    /// then its group killed and reaped. Returns whether it ended by itself; `result` then gets
    /// its exit status or signal.
    bool stop(bool at_once, ProcessResult* result = nullptr);

    std::vector<std::string> argv_;
    std::string label_;
    std::unique_ptr<TemporaryFolder> folder_;  ///< its working folder and stderr file
    std::unique_ptr<Process> process_;
    pid_t owner_ = 0;  ///< the process that started it (a forked worker starts its own)
    long long next_id_ = 1;
    int starts_ = 0;
};

/// Stops every server this process started (its input closed, a moment to exit, then its group
/// killed) and removes their folders. A forked process that ends by _exit, as a suite worker
/// does, calls it first: its servers' destructors never run, and each would leave its folder
/// behind (and a display's lock file, for a server that starts one and stops it on the end of
/// its input). A server stopped so starts again on its next run. Not while a run is in
/// progress in another thread.
void stop_program_servers();

}  // namespace crossdiv::verification
