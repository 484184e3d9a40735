#pragma once
/// @file
/// Implementations that are not compiled into crossdiv: a program run from a command template
/// (a student's submission, a researcher's new code, a library with only a command-line tool)
/// and result files that some program already wrote. Both are Implementations like core and
/// the libraries, so every comparison, classification and report works on them unchanged.
///
/// A program runs in its own temporary folder, in its own process group, with a time limit and
/// its stderr kept; the folder is removed afterwards. A program that can serve (ProgramSpec::serve)
/// is started once per process of the harness and handed each run, under the same limits. Every way it can fail is a RunStatus
/// (thrown as ImplementationFailure and recorded by refine_isolated): nonzero exit, signal,
/// time-out, no output file, unreadable output (file:line of the first bad line), NaN or
/// infinity, a vertex or face count other than the scheme makes, faces that are not triangles
/// where the scheme makes triangles. Vertex and face order are the program's own: the
/// comparisons find the correspondence.

#include <functional>
#include <memory>
#include <optional>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "crossdiv/verification/implementations/command_template.h"
#include "crossdiv/verification/implementations/implementation.h"
#include "crossdiv/verification/implementations/output_size.h"

namespace crossdiv::verification {

/// Which levels a program is asked for.
enum class LevelMode {
    Each,   ///< run once per level 1..N ({levels} = k), so that every level is compared
    Final,  ///< run once for level N; the levels before it are not compared
};
/// "each", "final".
const char* to_string(LevelMode mode);
/// @throws InputError for another name.
LevelMode level_mode_from_string(std::string_view name);

/// A program as an implementation, as a manifest's `subject` / `reference` statement or the
/// CLI's --subject names it.
struct ProgramSpec {
    std::string name;                 ///< how results name it ("mine", "meshlab")
    std::string command;              ///< the command template
    std::vector<Scheme> schemes;      ///< the schemes it implements (empty: every scheme)
    LevelMode levels = LevelMode::Each;
    Precision precision = Precision::Double;
    double timeout_seconds = 120;     ///< per run of the program
    /// The Loop weight families it has, by name (empty: every family when the template passes
    /// {weights}, else loop).
    std::vector<std::string> weights;
    /// The boundary rules it has, by each scheme's names (rule_from_boundary_name; empty:
    /// every rule when the template passes {boundary}, else the scheme's default).
    std::vector<std::string> boundaries;
    /// A command run once, when the implementation is made, to tell whether the program is on
    /// this machine (say, that an executable exists); when it cannot be started, fails or hangs,
    /// every run is RunStatus::Unavailable with its words. Empty: none.
    std::string setup;
    /// Where relative paths in `command` and `setup` are anchored (empty: the current folder;
    /// a manifest's statements: the manifest's folder).
    std::string base_dir;
    /// The submission folder {dir} stands for (a roster's subject; absolute), empty otherwise.
    std::string dir;
    /// A command that starts the program as a server (program_server.h), kept running for every
    /// run of this process instead of one start per run. It begins with the same words as
    /// `command` (the program, say `python3 x.py`); the command's words after those are sent
    /// as each run's arguments, and the server answers as `command` would have ended. Only
    /// {adapters} and {dir} may appear in it. Empty: the program is started for every run.
    std::string serve;
    /// Exit statuses by which a reference says it has no rule for the input (its reason on
    /// stderr): such a run is rejected, the reason kept, not a failure of the program. Empty:
    /// every nonzero status is a failure. References only: a subject's refusal is a failure.
    std::vector<int> refusal_exit_codes;
};

/// The value of `crossdiv compare --reference` that makes the program of `spec` again from any
/// folder, as a reproduce line needs it: NAME=command='...' and each key that differs from a
/// program's defaults (serve, setup, schemes, precision, weights, boundary, levels, timeout,
/// rejects), the relative paths of its commands made absolute as the manifest's folder means them.
std::string reference_option(const ProgramSpec& spec);

/// Vertex and face counts of a refined mesh, and the named rule that makes them ("" when
/// every rule of the scheme does).
struct RefinedCounts {
    long vertices = 0, faces = 0;
    std::string rule;
    friend bool operator==(const RefinedCounts&, const RefinedCounts&) = default;
};

/// The counts `scheme` makes from `input` after `levels` levels: one entry where they follow
/// from the input's counts alone (Loop and the Butterflies: V + E, 4F; Catmull-Clark and
/// bilinear: V + E + F, one quad per face corner); for the schemes whose counts depend on the
/// boundary rule (Doo-Sabin's border, sqrt3's parity), those of core under each named rule
/// that refines the input, each once. Empty when they cannot be told (polygons asked of a
/// triangle scheme, an input core refuses).
std::vector<RefinedCounts> expected_counts(Scheme scheme, const PolyMesh& input, int levels);

/// The checks every program result passes before it is compared: finite coordinates,
/// triangles where the scheme makes them, one of the counts of expected_counts. `file` names the
/// result in messages. @throws ImplementationFailure with the status that names the fault.
void check_program_result(const PolyMesh& result, Scheme scheme, const PolyMesh& input, int levels,
                          const std::string& file);

/// Levels 0..N of `request` for an implementation that makes each level from the input in a
/// call of its own: level 0 is `mesh`, levels first_made..N are make_level(request with
/// levels = k), the levels before first_made are empty (not made, not compared).
adapters::LevelTrace trace_from_input(const PolyMesh& mesh, const RefineRequest& request, int first_made,
                                      const std::function<PolyMesh(const RefineRequest&)>& make_level);

/// Reads a result file (OBJ, OFF or PLY by extension) as check_program_result wants it.
/// @throws ImplementationFailure: NoOutput (missing or empty), UnreadableOutput (file:line),
///         NonFiniteOutput.
PolyMesh read_program_result(const std::string& path, const std::string& shown_name);

/// A program's output is read only if it is a regular file it wrote, of at most this many bytes:
/// four times the OBJ text of the largest level a comparison takes (kMaxComparedFaces faces
/// and their vertices, about 60 bytes each).
inline constexpr std::uintmax_t kMaxProgramOutputBytes = 4ull * 60 * 3 * static_cast<std::uintmax_t>(kMaxComparedFaces);

/// Before a program's output at `path` (`shown` in messages) is opened: it exists (NoOutput),
/// and is a regular file, not a symbolic link, a FIFO (which would block the read past the
/// time limit) or a device, of at most kMaxProgramOutputBytes (UnreadableOutput).
/// @throws ImplementationFailure with that status.
void require_regular_output(const std::string& path, const std::string& shown);

/// Every check make_program_implementation makes of `spec` (name, time limit, rule names,
/// command and setup templates, declared rules), without running anything.
/// @throws InputError as make_program_implementation.
void check_program_spec(const ProgramSpec& spec);

/// A program run from a command template. It declares the rules of `spec.weights` and
/// `spec.boundaries`; where those are empty, every named rule of its schemes when its template
/// passes {weights} or {boundary}, else only each scheme's default rule; what it really
/// applies is measured (rule_identification.h). Runs `spec.setup` once, here.
/// @throws InputError for a bad template, an unknown scheme, weight family or boundary name.
std::unique_ptr<Implementation> make_program_implementation(const ProgramSpec& spec);

/// Result files already written (a submitted OBJ): refine returns the file as the last level
/// of the request, the levels before it empty (not compared). The file is read at each call.
std::unique_ptr<Implementation> make_result_file_implementation(const std::string& name, const std::string& path,
                                                                Scheme scheme);

}  // namespace crossdiv::verification
