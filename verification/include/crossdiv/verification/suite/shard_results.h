#pragma once
/// @file
/// One shard's results.json as `crossdiv merge` reads it: checked before anything is trusted
/// (a results object with a cases array, nesting no deeper than a results file does, every
/// field it uses of its type, every case a case record, every file it names inside its own
/// views/ or minimal/ folder), each refusal naming the file and the case.

#include <istream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/verification/suite/case_record.h"

namespace crossdiv::verification {

/// A shard's header (results.json without its cases and summary) and its records.
struct ShardResults {
    nlohmann::json header;
    std::vector<CaseRecord> cases;
    /// Per case, the files it names (its 3D view, its minimal input), relative to the shard's folder.
    std::vector<std::vector<std::string>> files;
    std::string suite() const;             ///< "suite", or "" when absent
    long long jobs_total() const;          ///< "jobs_total", or -1
    std::string jobs_fingerprint() const;  ///< "jobs_fingerprint", or ""
    std::string shard() const;             ///< "shard", or "?"
};

/// Reads the shard results in `in`, named `name` (the file) in every message.
/// @throws InputError naming `name` and, where it applies, the case and the field.
ShardResults read_shard_results(std::istream& in, const std::string& name);

}  // namespace crossdiv::verification
