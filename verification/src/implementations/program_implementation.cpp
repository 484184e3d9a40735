#include "crossdiv/verification/implementations/program_implementation.h"

#include <stdlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/harness/program_server.h"
#include "crossdiv/verification/harness/temporary_folder.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;

bool all_triangles(const PolyMesh& mesh) {
    for (int f = 0; f < mesh.num_faces(); ++f)
        if (mesh.face_size(f) != 3) return false;
    return true;
}

/// A label safe in a file name: the implementation's name with anything unusual replaced.
std::string file_label(const std::string& name) {
    std::string s;
    for (char c : name) s += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    return s.empty() ? "program" : s;
}

bool contains(const std::vector<std::string>& list, std::string_view name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

/// Every named rule of `scheme`, as core's own implementation declares them: never a stand-in
/// for core (ScopedCoreImplementation), which may have fewer schemes or rules, so that a
/// program's rules do not depend on what a test put in core's place.
const std::vector<SchemeRule>& named_rules(Scheme scheme) {
    const SchemeSupport* support = find_implementation("core").support(scheme);
    if (!support) throw InputError(std::string("core has no ") + to_string(scheme));
    return support->rules;
}

/// The rules a program declares for `scheme`: those of core's named rules whose weight family
/// (Loop) and boundary rule are in the spec's lists; a list that is empty keeps every value
/// when the template passes its placeholder, else the default rule's.
std::vector<SchemeRule> program_rules(const ProgramSpec& spec, Scheme scheme, bool passes_weights, bool passes_boundary) {
    const SchemeRule fallback{};
    std::vector<SchemeRule> rules;
    for (const SchemeRule& r : named_rules(scheme)) {
        const bool weights = scheme != Scheme::Loop ||
                             (spec.weights.empty() ? passes_weights || r.loop.weights == fallback.loop.weights
                                                   : contains(spec.weights, to_string(r.loop.weights)));
        const std::string boundary = boundary_name(scheme, r);
        const bool bounds = boundary.empty() || (spec.boundaries.empty()
                                                     ? passes_boundary || boundary == boundary_name(scheme, fallback)
                                                     : contains(spec.boundaries, boundary));
        if (weights && bounds) rules.push_back(r);
    }
    return rules;
}

Capabilities program_capabilities(const ProgramSpec& spec, bool passes_weights, bool passes_boundary, bool reads_tags) {
    Capabilities c;
    c.precision = spec.precision;
    const std::vector<Scheme> schemes = spec.schemes.empty() ? all_schemes() : spec.schemes;
    for (Scheme s : schemes) {
        SchemeSupport support{s, program_rules(spec, s, passes_weights, passes_boundary), reads_tags && traits(s).sdc_tags, 0,
                              ""};
        if (support.rules.empty())
            throw InputError("program '" + spec.name + "': none of its weights and boundary rules is a rule of " + to_string(s));
        c.schemes.push_back(std::move(support));
    }
    return c;
}

/// Checks the spec's weight and boundary names against every rule of its schemes.
void check_rule_names(const ProgramSpec& spec) {
    for (const std::string& w : spec.weights) loop_weights_from_string(w);
    const std::vector<Scheme> schemes = spec.schemes.empty() ? all_schemes() : spec.schemes;
    for (const std::string& b : spec.boundaries) {
        bool known = false;
        for (Scheme s : schemes)
            for (const SchemeRule& r : named_rules(s)) known |= boundary_name(s, r) == b;
        if (!known) throw InputError("program '" + spec.name + "': boundary rule '" + b + "' belongs to none of its schemes");
    }
}

/// Runs the setup command once; its failure, in words, or "" when the program is available.
std::string run_setup(const ProgramSpec& spec) {
    if (spec.setup.empty()) return "";
    CommandTemplate setup(spec.setup, false);
    setup.anchor_relative_paths(spec.base_dir);
    const TemporaryFolder folder(file_label(spec.name) + "-setup");
    const std::string err = (folder.path() / "stderr.txt").string();
    const ProcessResult r = run_confined(setup.expand({}), {folder.path().string(), std::min(spec.timeout_seconds, 60.0),
                                                            (folder.path() / "stdout.txt").string(), err});
    const std::string said = tail_of_file(err);
    const std::string what = "setup '" + spec.setup + "' ";
    if (!r.started) return what + "could not start: " + r.start_error;
    if (r.timed_out) return what + "did not finish";
    if (r.signal) return what + "died by signal " + std::to_string(r.signal);
    if (r.exit_code != 0) return what + "exited with status " + std::to_string(r.exit_code) + (said.empty() ? "" : ": " + said);
    return "";
}

class Program final : public Implementation {
public:
    Program(const ProgramSpec& spec, CommandTemplate command)
        : Implementation(spec.name, "command: " + spec.command + (spec.serve.empty() ? "" : "; served by: " + spec.serve),
                         ImplementationKind::Program,
                         program_capabilities(spec, command.text().find("{weights}") != std::string::npos,
                                              command.text().find("{boundary}") != std::string::npos, command.reads_tags())),
          spec_(spec),
          command_(std::move(command)),
          unavailable_(run_setup(spec)) {
        if (!spec.serve.empty()) {
            CommandTemplate serve(spec.serve, false);
            serve.anchor_relative_paths(spec.base_dir);
            request_from_ = serve.shared_words(command_);
            server_ = std::make_unique<ProgramServer>(serve.expand({"", "", "", "", {}, "", spec.dir, ""}), file_label(spec.name));
        }
    }

    bool confines_itself() const override { return true; }
    std::string reference_option() const override { return verification::reference_option(spec_); }

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& request) const override {
        check_refinable(request.scheme);
        check_available();
        return trace_from_input(mesh, request, spec_.levels == LevelMode::Final ? request.levels : 1,
                                [&](const RefineRequest& one) { return run_once(mesh, one); });
    }

    PolyMesh refine_last(const PolyMesh& mesh, const RefineRequest& request) const override {
        check_refinable(request.scheme);
        check_available();
        return run_once(mesh, request);
    }

private:
    void check_available() const {
        if (!unavailable_.empty()) throw ImplementationFailure(RunStatus::Unavailable, name() + " is not on this machine: " + unavailable_);
    }

    /// One run of the program for `request.levels` levels of `mesh`.
    PolyMesh run_once(const PolyMesh& mesh, const RefineRequest& request) const {
        const TemporaryFolder folder(file_label(name()));
        TemplateValues values{(folder.path() / "in.obj").string(),
                              (folder.path() / "in.off").string(),
                              (folder.path() / "in.ply").string(),
                              (folder.path() / (std::string("out.") + to_string(command_.output_format()))).string(),
                              request,
                              (folder.path() / "in-untagged.obj").string(),
                              spec_.dir,
                              ""};
        if (!mesh.creases.empty() && !command_.reads_tags())
            throw adapters::Rejected(name() + " reads its input without tags (" +
                                     (command_.reads_untagged_obj() ? "{in.untagged}" : "OFF or PLY") + "), and this one has " +
                                     mesh.creases.describe() + "; name {in} to be given them as OBJ 't' lines");
        if (command_.reads(MeshFormat::Obj)) write_mesh(values.in_obj, mesh);  // with its 't' lines
        PolyMesh untagged = mesh;
        untagged.creases = {};
        if (command_.reads_untagged_obj()) write_mesh(values.in_untagged, untagged);
        if (command_.reads(MeshFormat::Off)) write_mesh(values.in_off, untagged);
        if (command_.reads(MeshFormat::Ply)) write_mesh(values.in_ply, untagged);
        const auto [r, err] = run_program(command_.expand(values), folder);
        const std::string with_err = err.empty() ? "" : "; stderr: " + err;
        const std::string level = " (level " + std::to_string(request.levels) + ")";
        const std::string out_name = fs::path(values.out).filename().string();
        if (!r.started) throw ImplementationFailure(RunStatus::Crashed, r.start_error);
        if (r.timed_out)
            throw ImplementationFailure(RunStatus::Timeout, "no result after " + fmt_seconds(spec_.timeout_seconds) + level + with_err);
        if (r.signal)
            throw ImplementationFailure(RunStatus::Crashed, "signal " + std::to_string(r.signal) + " (" + strsignal(r.signal) + ")" +
                                                                level + with_err);
        if (std::find(spec_.refusal_exit_codes.begin(), spec_.refusal_exit_codes.end(), r.exit_code) != spec_.refusal_exit_codes.end())
            throw adapters::Rejected(name() + " refuses the input (exit status " + std::to_string(r.exit_code) + level + ")" +
                                     (err.empty() ? "" : ": " + err));
        if (r.exit_code != 0)
            throw ImplementationFailure(RunStatus::ExitStatus, "exit status " + std::to_string(r.exit_code) + level + with_err);
        try {
            PolyMesh result = read_program_result(values.out, out_name);
            check_program_result(result, request.scheme, mesh, request.levels, out_name);
            return result;
        } catch (const ImplementationFailure& e) {
            throw ImplementationFailure(e.status(), e.what() + level + with_err);
        }
    }

    /// One run of `argv`: started in `folder`, or handed to the server. How it ended, and what
    /// it said on stderr.
    std::pair<ProcessResult, std::string> run_program(const std::vector<std::string>& argv, const TemporaryFolder& folder) const {
        if (server_) {
            const std::lock_guard<std::mutex> one_run_at_a_time(server_mutex_);
            const std::vector<std::string> args(argv.begin() + static_cast<std::ptrdiff_t>(request_from_), argv.end());
            ServedRun served = server_->run(args, spec_.timeout_seconds);
            if (served.out_of_turn)
                throw ImplementationFailure(RunStatus::Crashed, "the serving program broke its protocol: " + served.stderr_text);
            return {served.process, served.stderr_text};
        }
        const std::string stderr_path = (folder.path() / "stderr.txt").string();
        const ProcessResult r = run_confined(argv, {folder.path().string(), spec_.timeout_seconds,
                                                    (folder.path() / "stdout.txt").string(), stderr_path});
        return {r, tail_of_file(stderr_path)};
    }

    static std::string fmt_seconds(double s) {
        std::string t = std::to_string(s);
        t.erase(t.find_last_not_of('0') + 1);
        if (!t.empty() && t.back() == '.') t.pop_back();
        return t + " s";
    }

    ProgramSpec spec_;
    CommandTemplate command_;
    std::string unavailable_;  ///< why the setup says the program is not here ("" when it is)
    /// The running server (ProgramSpec::serve), or null when the program starts for each run;
    std::unique_ptr<ProgramServer> server_;
    mutable std::mutex server_mutex_;  ///< a server takes one run at a time
    size_t request_from_ = 0;  ///< the command's words before this one start the server, not a run
};

class ResultFile final : public Implementation {
public:
    ResultFile(const std::string& name, std::string path, Scheme scheme)
        : Implementation(name, "result file: " + path, ImplementationKind::Program,
                         // The file was made from the input, tags and all, by whatever made it.
                         program_capabilities({name, "", {scheme}, LevelMode::Final, Precision::Double, 0, {}, {}, "", "", "", "", {}},
                                              true, true, true)),
          path_(std::move(path)) {}

    bool confines_itself() const override { return true; }

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& request) const override {
        check_refinable(request.scheme);
        return trace_from_input(mesh, request, request.levels, [&](const RefineRequest& r) { return refine_last(mesh, r); });
    }

    PolyMesh refine_last(const PolyMesh& mesh, const RefineRequest& request) const override {
        check_refinable(request.scheme);
        PolyMesh result = read_program_result(path_, path_);
        check_program_result(result, request.scheme, mesh, request.levels, path_);
        return result;
    }

private:
    std::string path_;
};

}  // namespace

const char* to_string(LevelMode mode) { return mode == LevelMode::Each ? "each" : "final"; }

LevelMode level_mode_from_string(std::string_view name) {
    if (name == "each") return LevelMode::Each;
    if (name == "final") return LevelMode::Final;
    throw InputError("unknown level mode '" + std::string(name) + "' (known: each, final)");
}

adapters::LevelTrace trace_from_input(const PolyMesh& mesh, const RefineRequest& request, int first_made,
                                      const std::function<PolyMesh(const RefineRequest&)>& make_level) {
    adapters::LevelTrace trace{mesh};
    trace.resize(static_cast<size_t>(std::max(1, first_made)));  // the levels before first_made: empty
    for (int level = std::max(1, first_made); level <= request.levels; ++level) {
        RefineRequest one = request;
        one.levels = level;
        trace.push_back(make_level(one));
    }
    return trace;
}

std::vector<RefinedCounts> expected_counts(Scheme scheme, const PolyMesh& input, int levels) {
    if (scheme == Scheme::DooSabin || scheme == Scheme::Sqrt3) {
        // The border (Doo-Sabin) and the parity (sqrt3) decide the counts: core's, per rule.
        std::vector<RefinedCounts> out;
        for (const SchemeRule& r : core_implementation().support(scheme)->rules) {
            PolyMesh refined;
            try {
                refined = core_implementation().refine_last(input, {scheme, r, levels});
            } catch (const std::exception&) {
                continue;  // core refuses the input under this rule: no count to hold the result to
            }
            const RefinedCounts c{refined.num_vertices(), refined.num_faces(), rule_name(scheme, r)};
            const auto same = std::find_if(out.begin(), out.end(), [&](const RefinedCounts& o) {
                return o.vertices == c.vertices && o.faces == c.faces;
            });
            if (same == out.end()) out.push_back(c);
        }
        if (out.size() == 1) out[0].rule.clear();
        return out;
    }
    long v = input.num_vertices(), f = input.num_faces(), corners = static_cast<long>(input.face_vertices.size()), e = 0;
    // Edges as OpenSubdiv counts them (nonmanifold.h), the vertex pairs on a manifold: a face
    // naming a vertex twice has more edges than pairs. Every later level derives its edges per
    // face, so the recurrence below holds from there.
    try {
        e = static_cast<long>(nonmanifold_edges(input).size());
    } catch (const InputError&) {
        // A face of fewer than three corners: no rule refines it, and core says so; the vertex
        // pairs then (mesh_topology names a vertex the mesh lacks).
        e = mesh_topology(input).edges;
    }
    const bool triangles = all_triangles(input);
    for (int l = 0; l < levels; ++l) {
        if (traits(scheme).triangles) {
            if (!triangles) return {};
            // Each edge gains a vertex and becomes two; each face gains three interior edges.
            std::tie(v, e, f) = std::tuple{v + e, 2 * e + 3 * f, 4 * f};
            corners = 3 * f;
        } else {
            // A vertex per face and per edge; one quad and one new edge per face corner.
            std::tie(v, e, f) = std::tuple{v + e + f, 2 * e + corners, corners};
            corners = 4 * f;
        }
    }
    return {{v, f, ""}};
}

void check_program_result(const PolyMesh& result, Scheme scheme, const PolyMesh& input, int levels, const std::string& file) {
    for (int v = 0; v < result.num_vertices(); ++v)
        if (!result.positions[static_cast<size_t>(v)].allFinite())
            throw ImplementationFailure(RunStatus::NonFiniteOutput, file + ": " + result.source.describe_vertex(v) + " is not finite");
    if (traits(scheme).triangles && all_triangles(input))
        for (int f = 0; f < result.num_faces(); ++f)
            if (result.face_size(f) != 3)
                throw ImplementationFailure(RunStatus::NotTriangles, file + ": " + result.source.describe_face(f) + " has " +
                                                                         std::to_string(result.face_size(f)) + " corners; " +
                                                                         to_string(scheme) + " makes triangles");
    const std::vector<RefinedCounts> want = expected_counts(scheme, input, levels);
    if (want.empty() || std::any_of(want.begin(), want.end(), [&](const RefinedCounts& c) {
            return result.num_vertices() == c.vertices && result.num_faces() == c.faces;
        }))
        return;
    std::string makes;
    for (const RefinedCounts& c : want)
        makes += (makes.empty() ? "" : " or ") + std::to_string(c.vertices) + " vertices, " + std::to_string(c.faces) + " faces" +
                 (c.rule.empty() ? "" : " (" + c.rule + ")");
    throw ImplementationFailure(RunStatus::WrongCount, file + ": " + std::to_string(result.num_vertices()) + " vertices, " +
                                                           std::to_string(result.num_faces()) + " faces; " + to_string(scheme) +
                                                           " makes " + makes + " from this input at level " + std::to_string(levels));
}

void require_regular_output(const std::string& path, const std::string& shown) {
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(path, ec);
    if (ec || !fs::exists(st)) throw ImplementationFailure(RunStatus::NoOutput, "no output file " + shown);
    if (fs::is_symlink(st))
        throw ImplementationFailure(RunStatus::UnreadableOutput, shown + " is a symbolic link, not a file the program wrote");
    if (!fs::is_regular_file(st))
        throw ImplementationFailure(RunStatus::UnreadableOutput, shown + " is " + (fs::is_fifo(st) ? "a FIFO" : fs::is_directory(st) ? "a folder" : "a device or socket") +
                                                                 ", not a regular file");
    const std::uintmax_t bytes = fs::file_size(path, ec);
    if (!ec && bytes > kMaxProgramOutputBytes)
        throw ImplementationFailure(RunStatus::UnreadableOutput, shown + " has " + std::to_string(bytes) + " bytes, more than the " +
                                                                 std::to_string(kMaxProgramOutputBytes) + " a result may have");
}

PolyMesh read_program_result(const std::string& path, const std::string& shown_name) {
    std::error_code ec;
    require_regular_output(path, shown_name);
    if (fs::file_size(path, ec) == 0 && !ec) throw ImplementationFailure(RunStatus::NoOutput, "empty output file " + shown_name);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ImplementationFailure(RunStatus::NoOutput, "cannot open output file " + shown_name);
    try {
        const auto ends_with = [&](const char* ext) { return path.size() >= 4 && path.compare(path.size() - 4, 4, ext) == 0; };
        return ends_with(".off") ? read_off(in, shown_name) : ends_with(".ply") ? read_ply(in, shown_name) : read_obj(in, shown_name);
    } catch (const NonFiniteNumber& e) {
        throw ImplementationFailure(RunStatus::NonFiniteOutput, e.what());
    } catch (const InputError& e) {
        throw ImplementationFailure(RunStatus::UnreadableOutput, e.what());
    }
}

void check_program_spec(const ProgramSpec& spec) {
    if (spec.name.empty()) throw InputError("a program implementation needs a name");
    if (!(spec.timeout_seconds > 0)) throw InputError("program '" + spec.name + "': the time limit must be positive");
    check_rule_names(spec);
    CommandTemplate command(spec.command);
    if (!spec.setup.empty()) CommandTemplate setup(spec.setup, false);
    if (!spec.serve.empty()) {
        const CommandTemplate serve(spec.serve, false);
        if (serve.names_run_values())
            throw InputError("program '" + spec.name + "': its serve command '" + spec.serve +
                             "' names a value of one run; it starts the program once for every run, with {adapters} and {dir} at most");
        if (serve.shared_words(command) == 0)
            throw InputError("program '" + spec.name + "': its serve command '" + spec.serve + "' and its command '" + spec.command +
                             "' start different programs; the serve command begins with the command's first words");
    }
    if (spec.dir.empty() && (spec.command.find("{dir}") != std::string::npos || spec.setup.find("{dir}") != std::string::npos))
        throw InputError("program '" + spec.name + "': {dir} is a roster's submission folder; it has a meaning in a "
                         "manifest's `subjects NAME dir=...` statement only");
    program_capabilities(spec, command.text().find("{weights}") != std::string::npos,
                         command.text().find("{boundary}") != std::string::npos, command.reads_tags());
}

std::string reference_option(const ProgramSpec& spec) {
    const auto anchored = [&](const std::string& text, bool needs_output) {
        CommandTemplate t(text, needs_output);
        t.anchor_relative_paths(spec.base_dir);
        return "'" + t.anchored_text() + "'";
    };
    const auto joined = [](const auto& items, const auto& name_of) {
        std::string s;
        for (const auto& item : items) {
            if (!s.empty()) s += ',';
            s += name_of(item);
        }
        return s;
    };
    const auto same = [](const std::string& s) { return s; };
    std::string o = spec.name + "=command=" + anchored(spec.command, true);
    if (!spec.serve.empty()) o += " serve=" + anchored(spec.serve, false);
    if (!spec.setup.empty()) o += " setup=" + anchored(spec.setup, false);
    if (!spec.schemes.empty()) o += " schemes=" + joined(spec.schemes, [](Scheme s) { return to_string(s); });
    if (spec.precision == Precision::Float) o += " precision=float";
    if (!spec.weights.empty()) o += " weights=" + joined(spec.weights, same);
    if (!spec.boundaries.empty()) o += " boundary=" + joined(spec.boundaries, same);
    if (spec.levels != LevelMode::Each) o += std::string(" levels=") + to_string(spec.levels);
    if (!spec.refusal_exit_codes.empty())
        o += " rejects=" + joined(spec.refusal_exit_codes, [](int c) { return std::to_string(c); });
    char timeout[32];
    std::snprintf(timeout, sizeof timeout, "%.17g", spec.timeout_seconds);
    return o + " timeout=" + timeout;
}

std::unique_ptr<Implementation> make_program_implementation(const ProgramSpec& spec) {
    check_program_spec(spec);
    CommandTemplate command(spec.command);
    command.anchor_relative_paths(spec.base_dir);
    return std::make_unique<Program>(spec, std::move(command));
}

std::unique_ptr<Implementation> make_result_file_implementation(const std::string& name, const std::string& path, Scheme scheme) {
    return std::make_unique<ResultFile>(name, path, scheme);
}

}  // namespace crossdiv::verification
