#include "crossdiv/verification/implementations/task_program.h"

#include <cstring>
#include <filesystem>

#include "crossdiv/error.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/implementations/command_template.h"

namespace crossdiv::verification {

TaskRun run_task_program(const std::string& command, const std::string& input_file, const std::string& out_name,
                         double timeout_seconds, const std::string& ops_file) {
    namespace fs = std::filesystem;
    CommandTemplate cmd(command);
    cmd.anchor_relative_paths();
    TaskRun run;
    run.folder = std::make_unique<TemporaryFolder>("task");
    const fs::path dir = run.folder->path();
    const fs::path in = dir / ("in" + fs::path(input_file).extension().string());
    std::error_code ec;
    fs::copy_file(input_file, in, fs::copy_options::overwrite_existing, ec);
    if (ec) throw InputError(input_file + ": cannot copy it for the program: " + ec.message());
    run.out = (dir / out_name).string();
    // Every input placeholder names the one file the task has.
    TemplateValues values{in.string(), in.string(), in.string(), run.out, {}, in.string(), "", ""};
    if (!ops_file.empty()) {
        values.ops = (dir / "ops.txt").string();
        fs::copy_file(ops_file, values.ops, fs::copy_options::overwrite_existing, ec);
        if (ec) throw InputError(ops_file + ": cannot copy it for the program: " + ec.message());
    }
    const std::string err = (dir / "stderr.txt").string();
    const ProcessResult r = run_confined(cmd.expand(values), {dir.string(), timeout_seconds, (dir / "stdout.txt").string(), err});
    run.outcome.seconds = r.seconds;
    const std::string said = tail_of_file(err);
    run.stderr_tail = said.empty() ? "" : "; stderr: " + said;
    const auto failed = [&](RunStatus s, const std::string& message) {
        run.outcome.status = s;
        run.outcome.message = message;
    };
    if (!r.started) failed(RunStatus::Crashed, r.start_error);
    else if (r.timed_out) failed(RunStatus::Timeout, "no result after " + std::to_string(static_cast<int>(timeout_seconds)) + " s" + run.stderr_tail);
    else if (r.signal) failed(RunStatus::Crashed, "signal " + std::to_string(r.signal) + " (" + strsignal(r.signal) + ")" + run.stderr_tail);
    else if (r.exit_code != 0) failed(RunStatus::ExitStatus, "exit status " + std::to_string(r.exit_code) + run.stderr_tail);
    return run;
}

}  // namespace crossdiv::verification
