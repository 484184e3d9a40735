#pragma once
// How a command group adds its subcommands to the crossdiv CLI: each subcommand keeps its
// options in an Args struct (with add_to(CLI::App&)) and runs a function of them, whose exit
// status becomes the program's.

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::cli {

/// Adds subcommand `name`; when the command line selects it, `run(args)` runs after parsing
/// and its result is stored in `status`. Exceptions pass through to main.
template <class Args>
void add_command(CLI::App& app, const char* name, const char* help, int& status, int (*run)(const Args&)) {
    auto args = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand(name, help);
    args->add_to(*sub);
    sub->callback([args, run, &status] { status = run(*args); });
}

/// Refuses a blank value: an unset variable in a script (`--subject "$CMD"`) would otherwise
/// drop the option, and the run would say nothing of the program it was meant to test.
inline const CLI::Validator kNotBlank(
    [](std::string& s) {
        return s.find_first_not_of(" \t") == std::string::npos ? std::string("empty (is a variable unset?)") : std::string();
    },
    "", "NOT_BLANK");

/// A subject's name must not be core's or a reference's (verification::check_subject_name).
inline const CLI::Validator kSubjectName(
    [](std::string& s) {
        try {
            verification::check_subject_name(s);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    },
    "", "SUBJECT_NAME");

/// A course task's program in core's place (task_program.h): --subject CMD (what it is given
/// and writes: `what`), --subject-name, --timeout.
struct TaskSubjectOptions {
    std::string command, name = "subject";
    double timeout = 60;
    void add_to(CLI::App& app, const std::string& what) {
        app.add_option("--subject", command, "Put a program under test in core's place: a command template, " + what)
            ->check(kNotBlank);
        app.add_option("--subject-name", name, "The subject's name in the output")->check(kSubjectName)->capture_default_str();
        app.add_option("--timeout", timeout, "Seconds the subject may run")->check(CLI::PositiveNumber)->capture_default_str();
    }
};

/// The names of a comma-separated list ("opensubdiv,cgal"), empty items dropped.
inline std::vector<std::string> split_commas(const std::string& s) {
    std::vector<std::string> out;
    for (size_t b = 0, e; b < s.size(); b = e + 1) {
        e = s.find(',', b);
        if (e == std::string::npos) e = s.size();
        if (e > b) out.push_back(s.substr(b, e - b));
    }
    return out;
}

}  // namespace crossdiv::cli
