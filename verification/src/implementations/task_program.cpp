#include "crossdiv/verification/implementations/task_program.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/datasets/bundled_curves.h"
#include "crossdiv/datasets/bundled_surfaces.h"

#include "crossdiv/error.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/implementations/command_template.h"

namespace crossdiv::verification {

std::string task_input_file(const std::string& spec, const TemporaryFolder& folder) {
    const bool curve = spec.starts_with("curve:"), surface = spec.starts_with("surface:");
    if (!curve && !surface) return spec;
    const std::string name = spec.substr(spec.find(':') + 1);
    const datasets::BundledCurve* b = nullptr;
    if (surface) {
        b = &datasets::bundled_surface(name);
    } else {
        const auto& all = datasets::bundled_curves();
        const auto it = std::find_if(all.begin(), all.end(), [&](const datasets::BundledCurve& c) { return c.name == name; });
        if (it == all.end()) throw InputError("unknown bundled curve '" + spec + "'");
        b = &*it;
    }
    const std::string path = (folder.path() / (name + "." + b->format)).string();
    write_text_file(path, b->text);
    return path;
}

TaskRun run_task_program(const TaskCommand& command, const std::string& input_file, const std::string& out_name,
                         double timeout_seconds, const std::string& ops_file) {
    namespace fs = std::filesystem;
    if (command.dir.empty() && command.text.find("{dir}") != std::string::npos)
        throw InputError("'" + command.text + "': {dir} is a roster's submission folder; it has a meaning in a manifest's "
                         "`subjects NAME dir=...` statement only");
    CommandTemplate cmd(command.text);
    cmd.anchor_relative_paths(command.base_dir);
    TaskRun run;
    run.folder = std::make_unique<TemporaryFolder>("task");
    const fs::path dir = run.folder->path();
    const fs::path in = dir / ("in" + fs::path(input_file).extension().string());
    std::error_code ec;
    fs::copy_file(input_file, in, fs::copy_options::overwrite_existing, ec);
    if (ec) throw InputError(input_file + ": cannot copy it for the program: " + ec.message());
    run.out = (dir / out_name).string();
    // Every input placeholder names the one file the task has.
    TemplateValues values{in.string(), in.string(), in.string(), run.out, {}, in.string(), command.dir, ""};
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
