#pragma once
/// @file
/// A suite manifest (cases x operations x rules x tolerances; the format is documented in
/// reports/suite-manifest.md) and its expansion into jobs, whole or one shard of them.

#include <cstdint>
#include <memory>
#include <optional>
#include <istream>
#include <string>
#include <vector>

#include "crossdiv/verification/comparisons/input_transformation.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/verification/implementations/output_size.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {

struct SuiteOperation;

/// A `subject` statement, or one folder of a `subjects` statement (a roster): the
/// implementation under test of the comparison cases after it, in core's place. A program
/// (command=) is made once; result files (result=) are one file per input, named by a pattern.
struct ManifestSubject {
    std::string name;    ///< the statement's NAME; in a roster, the submission folder's name
    std::string roster;  ///< the `subjects` statement's NAME (empty for a `subject` statement)
    std::string dir;     ///< the submission folder, absolute (a roster's subject)
    std::shared_ptr<const Implementation> program;  ///< command=: the program
    /// command=: the same template as a course task runs it (task_cases.h), with its time limit.
    std::optional<TaskCommand> task;
    double timeout_seconds = 0;
    /// result=: the file of each input, with {input} (the input's name: a file's stem, the
    /// NAME of bundled:NAME) and {levels}; relative to the manifest's folder.
    std::string result_pattern;
    /// The result file of `input` at `levels` under the pattern.
    std::string result_path(const std::string& input, int levels) const;
};

/// One `case` line of a manifest: inputs x one operation with its rules and tier.
/// A course-task case's keys (task_cases.h).
struct TaskKeys {
    double t = 0.5;                     ///< casteljau: the parameter
    int res = 8;                        ///< patch: quads per patch side
    std::string frames = "recursive";   ///< sweep: core's frames for generalized cylinders (recursive | rmf)
    std::string ops;                    ///< flip-split: "flip A B, split C D, ..."
};

/// An invariance case's keys (suite/invariance_case.h): which implementations, which
/// transformations, which seed.
struct InvarianceKeys {
    /// impls=NAME,...: core or registered implementations of the scheme; empty: core and every
    /// reference of the scheme registered when the case is read.
    std::vector<std::string> implementations;
    /// transform=NAME,...; empty: every transformation (kInputTransformations).
    std::vector<InputTransformation> transformations;
    std::uint64_t seed = 1;  ///< seed=K: the random rotations, shuffles and relabellings
};

struct ManifestEntry {
    int line = 0;                      ///< in the manifest file
    std::vector<std::string> inputs;   ///< as the operation's expand() accepts them (collections allowed)
    const SuiteOperation* operation = nullptr;
    /// A comparison's scheme, levels, references, tier and tolerance, and Loop's rule (weights=,
    /// boundary=); another scheme's rule is resolved per input from `rule_flags` and the
    /// input's tags (rule_with_tags).
    RefinementRequest request;
    /// A comparison names its references (`against=`, in its id) rather than taking every
    /// reference of its scheme registered so far.
    bool references_named = false;
    RuleFlags rule_flags;              ///< another scheme's boundary= and crease-method= keys
    TaskKeys task;                     ///< a course task's keys
    InvarianceKeys invariance;         ///< an invariance case's keys (its scheme and rule are in `request`)
    /// The implementation under test (the last `subject` statement before the case, or one
    /// subject of the last `subjects` statement: a case line makes one entry per subject); none: core.
    std::shared_ptr<const ManifestSubject> subject;
    /// A comparison: a job whose final level would have more faces is refused before any work
    /// (the manifest's `max-faces` statement; implementations/output_size.h).
    long long max_faces = kMaxComparedFaces;
};

struct Manifest {
    std::string file;  ///< where it was read from
    std::string name;  ///< the `suite` line
    double timeout_seconds = 60;
    long long max_faces = kMaxComparedFaces;  ///< the `max-faces` statement, given to every case
    std::vector<ManifestEntry> entries;
    /// The names of the `reference` statements, registered in the registry as they were read.
    std::vector<std::string> references;
};

/// What reading does with the programs of `reference` and `subject` statements.
enum class ProgramStatements {
    Register,   ///< make each program (running its setup) and register the references
    CheckOnly,  ///< check each statement as Register would, run nothing, register nothing
};

/// Reads a manifest, registering each `reference` statement's program in the registry
/// (registry.h) as it is read. @throws ParseError naming the file and line of any bad statement.
Manifest read_manifest(const std::string& path);

/// Reads manifest text named `name`; relative paths are anchored at `base_dir`. With
/// CheckOnly (a fuzzer, a check of a manifest from elsewhere) the subjects' programs are null.
Manifest read_manifest(std::istream& in, const std::string& name, const std::string& base_dir, ProgramStatements programs);

/// The words of a statement: split at whitespace, a '...' or "..." group kept whole with its
/// quotes removed (key='a b' is the word key=a b). @throws InputError on an unclosed quote.
std::vector<std::string> statement_words(const std::string& text);

/// A program implementation from `key=value` words (the `reference` and `subject` statements,
/// the CLI's --reference): command= (required), schemes=, precision=, weights=, boundary=,
/// levels=each|final, timeout=, setup=. Relative paths are anchored at `base_dir`.
/// @throws InputError naming the bad key or value.
ProgramSpec program_spec(const std::string& name, const std::vector<std::string>& key_values, const std::string& base_dir,
                         double default_timeout);

/// The folders `pattern` names: a folder path whose last part may hold the wildcards * ? [...]
/// (fnmatch, no shell), relative to `base_dir` unless absolute; sorted by name, absolute.
/// @throws InputError when the parent folder does not exist or nothing matches.
std::vector<std::string> submission_folders(const std::string& pattern, const std::string& base_dir);

/// The manifest `crossdiv suite` runs without an argument (verification/suites/default.suite).
std::string default_manifest_path();

/// One unit of work: an expanded input under one entry. `index` is its place in the whole
/// suite, the same on every machine with the same data, so shards can be merged.
struct SuiteJob {
    int index = 0;
    std::string input;
    const ManifestEntry* entry = nullptr;
    std::string id;  ///< "input | loop weights=.. boundary=.. L3 weak tol=1e-12", "input | spectrum"
};

/// Every job of the manifest, in order. Collections whose data is absent expand to nothing.
/// @throws ParseError naming the manifest line of an input the operation does not take.
std::vector<SuiteJob> expand_jobs(const Manifest& manifest);

/// Slice `shard` (1-based) of `count`: jobs whose index % count == shard - 1.
/// @throws InputError unless 1 <= shard <= count.
std::vector<SuiteJob> shard_jobs(const std::vector<SuiteJob>& jobs, int shard, int count);

}  // namespace crossdiv::verification
