#pragma once
/// @file
/// A suite manifest (cases x operations x rules x tolerances; the format is documented in
/// reports/suite-manifest.md) and its expansion into jobs, whole or one shard of them.

#include <string>
#include <vector>

#include "crossdiv/verification/comparisons/loop_comparison.h"

namespace crossdiv::verification {

struct SuiteOperation;

/// One `case` line of a manifest: inputs x one operation with its rules and tier.
struct ManifestEntry {
    int line = 0;                      ///< in the manifest file
    std::vector<std::string> inputs;   ///< as the operation's expand() accepts them (collections allowed)
    const SuiteOperation* operation = nullptr;
    LoopComparisonRequest request;     ///< loop: rules, levels, references, tier, tolerance
};

struct Manifest {
    std::string file;  ///< where it was read from
    std::string name;  ///< the `suite` line
    double timeout_seconds = 60;
    std::vector<ManifestEntry> entries;
};

/// Reads a manifest. @throws ParseError naming the file and line of any bad statement.
Manifest read_manifest(const std::string& path);

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
