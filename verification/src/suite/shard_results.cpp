#include "crossdiv/verification/suite/shard_results.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <utility>

#include "crossdiv/error.h"

namespace crossdiv::verification {
namespace {

using nlohmann::json;

/// results.json nests about ten levels (a case, its runs, their detail, a table's rows).
constexpr int kMaxResultsDepth = 64;

/// Whether `j` nests deeper than `limit` arrays and objects, found without recursion.
bool nests_deeper(const json& j, int limit) {
    std::vector<std::pair<const json*, int>> stack{{&j, 0}};
    while (!stack.empty()) {
        const auto [v, depth] = stack.back();
        stack.pop_back();
        if (depth > limit) return true;
        if (v->is_structured())
            for (const json& child : *v) stack.push_back({&child, depth + 1});
    }
    return false;
}

/// A header field of its type, or the fallback when absent. (Checked when the shard is read.)
template <class T>
T header_field(const json& header, const char* key, T fallback) {
    return header.value(key, fallback);
}

/// The minimal mesh a record's "minimal" names (failure_shrink.h), if it names one.
void add_minimal_mesh(const nlohmann::json& detail, std::vector<std::string>& files) {
    if (detail.contains("minimal") && detail["minimal"].is_object() && detail["minimal"].contains("mesh") &&
        detail["minimal"]["mesh"] != "")
        files.push_back(detail["minimal"]["mesh"].is_string() ? detail["minimal"]["mesh"].get<std::string>() : "");
}

/// The files case `c` names (its view, its minimal mesh, its runs' minimal meshes), each
/// checked to be inside the shard's views/ or minimal/ folder.
std::vector<std::string> named_files(const CaseRecord& c, const std::string& name, size_t k) {
    std::vector<std::string> files;
    if (c.detail.contains("view")) files.push_back(c.detail["view"].is_string() ? c.detail["view"].get<std::string>() : "");
    add_minimal_mesh(c.detail, files);
    for (const RunRecord& r : c.runs) add_minimal_mesh(r.detail, files);
    for (const std::string& file : files) {
        const std::filesystem::path rel(file);
        const bool inside = !file.empty() && rel.is_relative() &&
                            std::none_of(rel.begin(), rel.end(), [](const std::filesystem::path& part) { return part == ".."; }) &&
                            (file.starts_with("views/") || file.starts_with("minimal/"));
        if (!inside)
            throw InputError(name + ": case " + std::to_string(k) + " names the file '" + file +
                             "', not one of its views/ or minimal/ folders");
    }
    return files;
}

}  // namespace

std::string ShardResults::suite() const { return header_field(header, "suite", std::string()); }
long long ShardResults::jobs_total() const {
    return whole_number_field(header, "jobs_total", -1, -1, std::numeric_limits<int>::max());
}
std::string ShardResults::jobs_fingerprint() const { return header_field(header, "jobs_fingerprint", std::string()); }
std::string ShardResults::shard() const { return header_field(header, "shard", std::string("?")); }

ShardResults read_shard_results(std::istream& in, const std::string& name) {
    json r = json::parse(in, nullptr, false);
    if (r.is_discarded() || !r.is_object() || !r.contains("cases") || !r["cases"].is_array())
        throw InputError(name + ": not a crossdiv suite results file");
    // Copying or walking a value recurses as deep as it nests: a results file nests a few
    // levels; one nested thousands deep is refused before anything recurses into it.
    if (nests_deeper(r, kMaxResultsDepth))
        throw InputError(name + ": nests deeper than " + std::to_string(kMaxResultsDepth) + " levels: not a crossdiv results file");
    ShardResults s;
    s.header = r;
    s.header.erase("cases");
    s.header.erase("summary");
    // A header field of the wrong type names the file, as a missing one does.
    const auto check = [&](const char* key, auto fallback) {
        try {
            (void)s.header.value(key, fallback);
        } catch (const json::exception&) {
            throw InputError(name + ": \"" + key + "\" has the wrong type");
        }
    };
    check("suite", std::string());
    try {
        (void)s.jobs_total();
    } catch (const InputError& e) {
        throw InputError(name + ": " + e.what());
    }
    check("jobs_fingerprint", std::string());
    check("shard", std::string());
    const json& records = r["cases"];
    for (size_t k = 0; k < records.size(); ++k) {
        CaseRecord c;
        try {
            c = case_record_from_json(records[k]);
        } catch (const std::exception& e) {  // a field missing or of the wrong type
            throw InputError(name + ": case " + std::to_string(k) + ": " + e.what());
        }
        s.files.push_back(named_files(c, name, k));
        s.cases.push_back(std::move(c));
    }
    return s;
}

}  // namespace crossdiv::verification
