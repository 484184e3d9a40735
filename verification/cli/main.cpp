// crossdiv: the command-line front of the testbed. Exit codes: 0 success (compare: every
// reference agrees), 1 a disagreement or a failed check, 2 bad input or usage (with a
// message), 3 an internal error. Each command group adds its subcommands (*_commands.h).
#include <CLI/CLI.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <iostream>

#include "bench_commands.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/verification/implementations/registry.h"
#include "curvature_command.h"
#include "curve_commands.h"
#include "edit_commands.h"
#include "editor_command.h"
#include "fit_command.h"
#include "isosurface_command.h"
#include "mesh_commands.h"
#include "nearest_name.h"
#include "multires_command.h"
#include "scheme_commands.h"
#include "suite_commands.h"
#include "surface_commands.h"

namespace {

/// What `crossdiv --version` prints: crossdiv's version and compiler, then every implementation
/// the registry holds at start-up with the version of what it calls (the libraries built in and
/// the programs crossdiv registers itself; a manifest's `reference` programs join later).
std::string version_text() {
    std::string text = fmt::format("crossdiv {} ({} build, {} {}, C++{})\n", CROSSDIV_VERSION, CROSSDIV_BUILD_TYPE,
#if defined(__clang__)
                                   "clang", __clang_version__,
#else
                                   "GCC", __VERSION__,
#endif
                                   __cplusplus / 100 % 100);
    text += "implementations built in:\n";
    for (const crossdiv::verification::Implementation* impl : crossdiv::verification::implementations())
        text += fmt::format("  {:<18} {}\n", impl->name(), impl->version());
    text.pop_back();  // CLI11 ends the text with a line break of its own
    return text;
}

/// The names of `app`'s subcommands.
std::vector<std::string> command_names(CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) names.push_back(sub->get_name());
    return names;
}

/// A first argument that names no command: the error, with the nearest command when one is
/// near (exit 2, as for any usage error). CLI11 alone would only say that a command is needed.
bool refuse_unknown_command(CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return false;
    const std::vector<std::string> names = command_names(app);
    const std::string typed = argv[1];
    if (std::find(names.begin(), names.end(), typed) != names.end()) return false;
    std::cerr << "crossdiv: unknown command '" << typed << "'";
    if (const auto near = crossdiv::cli::nearest_name(typed, names)) std::cerr << "; did you mean '" << *near << "'?";
    std::cerr << "\nRun crossdiv --help for the commands.\n";
    return true;
}

/// After CLI11's "argument was not expected": for each `--name` the command does not have, the
/// nearest one it has, when one is near.
void suggest_options(CLI::App& app, int argc, char** argv) {
    const std::vector<CLI::App*> chosen = app.get_subcommands();
    if (chosen.empty()) return;
    std::vector<std::string> known;
    for (const CLI::Option* option : chosen.front()->get_options())
        for (const std::string& name : option->get_lnames()) known.push_back("--" + name);
    for (int i = 2; i < argc; ++i) {
        std::string typed = argv[i];
        if (!typed.starts_with("--")) continue;
        typed = typed.substr(0, typed.find('='));
        if (std::find(known.begin(), known.end(), typed) != known.end()) continue;
        if (const auto near = crossdiv::cli::nearest_name(typed, known))
            std::cerr << "crossdiv " << chosen.front()->get_name() << ": no option " << typed << "; did you mean " << *near << "?\n";
    }
}

}  // namespace

int main(int argc, char** argv) {
    namespace cli = crossdiv::cli;
    // Ctrl-C or SIGTERM during a run stops the programs under test and removes their folders too.
    crossdiv::verification::stop_cleanly_on_signals();
    CLI::App app{"crossdiv: spline and subdivision algorithms verified against OpenSubdiv, OpenMesh and CGAL"};
    app.set_version_flag("--version", version_text, "Print crossdiv's version and the libraries built in, and exit");
    // Every command's help on one page: what the man page is generated from (help2man).
    app.set_help_all_flag("--help-all", "Print the help of every command and exit");
    app.require_subcommand(1);
    int status = 0;
    cli::add_mesh_commands(app, status);     // subdivide, compare, check, datasets, edgecases, diff
    cli::add_suite_commands(app, status);    // suite, merge, report
    cli::add_bench_command(app, status);     // bench
    cli::add_curve_commands(app, status);    // tessellate, casteljau
    cli::add_surface_commands(app, status);  // sweep, patch
    cli::add_edit_commands(app, status);     // edit, normals
    cli::add_curvature_command(app, status);  // curvature
    cli::add_isosurface_command(app, status);  // isosurface
    cli::add_fit_command(app, status);         // fit
    cli::add_multires_command(app, status);    // multires
    cli::add_editor_command(app, status);      // editor
    cli::add_scheme_commands(app, status);   // limit, spectrum
    if (refuse_unknown_command(app, argc, argv)) return 2;
    try {
        app.parse(argc, argv);  // runs the selected command
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        if (dynamic_cast<const CLI::ExtrasError*>(&e)) suggest_options(app, argc, argv);
        return code == 0 ? 0 : 2;
    } catch (const crossdiv::InputError& e) {
        std::cerr << "crossdiv: error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "crossdiv: internal error: " << e.what() << "\n";
        return 3;
    }
    return status;
}
