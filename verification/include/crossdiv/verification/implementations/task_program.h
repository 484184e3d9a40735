#pragma once
/// @file
/// One run of a course-task program put in core's place (a curve tessellator, a vertex-normal
/// program): its command template gets the input file as {in} (copied into a folder of its own,
/// its extension kept) and the path of the file it writes as {out}; it runs without a shell,
/// confined, with a time limit. What the run did is a RunOutcome; reading the file it wrote is
/// the task's (curve_subject.h, normals_subject.h).

#include <memory>
#include <string>

#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/temporary_folder.h"

namespace crossdiv::verification {

/// A task program's command template with where it lives: relative paths in it are anchored
/// to `base_dir` (a manifest's folder; empty: the current one), and {dir} is `dir` (a roster's
/// submission folder; empty elsewhere). A bare template converts to one.
struct TaskCommand {
    std::string text, base_dir, dir;
    TaskCommand(std::string command, std::string base = "", std::string folder = "")
        : text(std::move(command)), base_dir(std::move(base)), dir(std::move(folder)) {}
    TaskCommand(const char* command) : text(command) {}
};

struct TaskRun {
    RunOutcome outcome;                      ///< Ok: it exited 0 (whether it wrote `out` is the reader's to say)
    std::string out;                         ///< where it was told to write
    std::string stderr_tail;                 ///< "; stderr: ..." to append to a message, or ""
    std::unique_ptr<TemporaryFolder> folder; ///< kept until the output is read
};

/// The input `spec` as a file a task program can be given: a path as it is; a bundled curve
/// (curve:NAME) or surface model (surface:NAME) written into `folder` first, as NAME.swp, .bzc
/// or .bez. @throws InputError for an unknown bundled name.
std::string task_input_file(const std::string& spec, const TemporaryFolder& folder);

/// Runs `command` once on `input_file`; `out_name` is the name of the file it writes
/// ("out.csv"). A program that cannot start or dies by a signal is Crashed, one still running
/// at `timeout_seconds` Timeout, one that exits nonzero ExitStatus, each with its stderr's tail.
/// @throws InputError for a command template that cannot run or an input that cannot be copied.
/// `ops_file`, when given, is copied beside the input and named by {ops} (the edit task's
/// list of operations).
TaskRun run_task_program(const TaskCommand& command, const std::string& input_file, const std::string& out_name,
                         double timeout_seconds, const std::string& ops_file = "");

}  // namespace crossdiv::verification
