#include "crossdiv/verification/suite/outputs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/suite/roster_table.h"
#include "crossdiv/verification/suite/shard_results.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string csv_field(const std::string& text) {
    const std::string s = valid_utf8(text);
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

/// Text for an XML attribute or element: valid UTF-8, the markup characters as entities, and
/// the control characters XML 1.0 forbids shown as \xHH.
std::string xml_escape(const std::string& text) {
    std::string out;
    for (char c : valid_utf8(text)) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
                    char escaped[5];
                    std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned char>(c));
                    out += escaped;
                } else {
                    out += c;
                }
        }
    }
    return out;
}

/// "%.6g", or "" for a value not measured (NaN) or not finite.
std::string number_or_empty(double x) {
    if (!std::isfinite(x)) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

/// "measured 3.1e-16 <= tolerance 1.4e-14 rel" for a check ("measured -" when there is no
/// figure, e.g. a reference that refused).
std::string fmt_measured(const RunRecord& r) {
    const std::string measured = number_or_empty(r.measured);
    char buf[160];
    std::snprintf(buf, sizeof buf, "measured %s %s tolerance %.3g %s", measured.empty() ? "-" : measured.c_str(),
                  r.outcome.verdict == Verdict::Agree ? "<=" : ">", std::isfinite(r.tolerance) ? r.tolerance : 0.0,
                  r.unit.c_str());
    return buf;
}

void write_file(const fs::path& p, const std::string& text) { write_text_file(p.string(), text); }

json to_json(const SuiteSummary& s) {
    return {{"cases", s.cases}, {"runs", s.runs}, {"failures", s.failures}, {"outcomes", s.outcomes}};
}

std::string csv(const std::vector<CaseRecord>& cases) {
    std::ostringstream out;
    out << "job,input,operation,weights,boundary,levels,tier,tolerance,reference,status,outcome,max_rel,rms_rel,"
           "hausdorff_rel,worst_valence,worst_boundary,core_seconds,reference_seconds,explanation\n";
    for (const CaseRecord& c : cases) {
        const auto row = [&](const RunRecord* r) {
            out << c.job << "," << csv_field(c.input) << "," << c.operation << "," << c.weights << "," << c.boundary << ","
                << (c.levels > 0 ? std::to_string(c.levels) : "") << "," << c.tier << ","
                << number_or_empty(!c.weights.empty() ? c.tolerance : r ? r->tolerance : NAN) << ","
                << csv_field(r ? r->label() : "") << "," << (r && r->status ? to_string(*r->status) : "") << ","
                << csv_field(r ? outcome_label(c, *r) : outcome_label(c)) << "," << number_or_empty(r ? r->measured : NAN)
                << "," << number_or_empty(r ? r->rms : NAN) << "," << number_or_empty(r ? r->hausdorff : NAN) << ","
                << (r && r->worst_valence >= 0 ? std::to_string(r->worst_valence) : "") << ","
                << (r && r->worst_boundary >= 0 ? (r->worst_boundary ? "true" : "false") : "") << ","
                << number_or_empty(c.core_seconds) << "," << number_or_empty(r ? r->seconds : NAN) << ","
                << csv_field(r ? r->explanation : c.core_error) << "\n";
        };
        if (c.runs.empty()) row(nullptr);
        for (const RunRecord& r : c.runs) row(&r);
    }
    return out.str();
}

/// The subject a case puts in core's place ("" for core).
std::string subject_of(const CaseRecord& c) {
    return c.detail.contains("subject") && c.detail["subject"].is_object() ? c.detail["subject"].value("name", "") : "";
}

/// "; minimal failing input: minimal/x.obj (2 faces; no named rule fits ...)" for the case the
/// suite shrank a subject's failure from (failure_shrink.h), or why it did not; "" otherwise.
std::string minimal_text(const CaseRecord& c) {
    if (!c.detail.contains("minimal") || !c.detail["minimal"].is_object()) return "";
    const json& m = c.detail["minimal"];
    if (m.value("mesh", "").empty()) return m.value("note", "").empty() ? "" : "; " + m.value("note", "");
    return "; minimal failing input: " + m.value("mesh", "") + " (" + std::to_string(m.value("faces", 0)) + " faces: " +
           m.value("symptom", "") + ")";
}

std::string junit(const std::string& suite, const std::vector<CaseRecord>& cases, const SuiteSummary& s) {
    // One test suite for core's cases and one per subject (a roster's class table, case by case).
    std::vector<std::string> suites{""};
    for (const CaseRecord& c : cases)
        if (std::find(suites.begin(), suites.end(), subject_of(c)) == suites.end()) suites.push_back(subject_of(c));
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"crossdiv\" tests=\"" << s.runs << "\" failures=\""
        << s.failures << "\">\n";
    for (const std::string& subject : suites) {
        std::ostringstream body;
        int tests = 0, failures = 0;
        for (const CaseRecord& c : cases) {
            if (subject_of(c) != subject) continue;
            const std::string classname = "crossdiv." + suite + "." + c.operation;
            const auto testcase = [&](const std::string& who, const std::string& outcome, bool failure, const std::string& text,
                                      double seconds) {
                ++tests;
                failures += failure;
                body << "    <testcase classname=\"" << xml_escape(classname) << "\" name=\"" << xml_escape(c.id + " vs " + who)
                     << "\" time=\"" << (std::isfinite(seconds) ? seconds : 0.0) << "\">\n";
                if (failure)
                    body << "      <failure message=\"" << xml_escape(outcome) << "\">" << xml_escape(text + minimal_text(c))
                         << "</failure>\n";
                body << "      <system-out>" << xml_escape(outcome + ": " + text) << "</system-out>\n    </testcase>\n";
            };
            if (c.runs.empty()) testcase("core", outcome_label(c), is_failure(c), c.core_error, 0.0);
            for (const RunRecord& r : c.runs)
                testcase(r.label(), outcome_label(c, r), is_failure(c, r),
                         r.is_check() ? fmt_measured(r) + "; " + r.explanation : r.explanation, r.seconds);
        }
        if (subject.empty() && tests == 0) continue;
        xml << "  <testsuite name=\"" << xml_escape(subject.empty() ? suite : suite + "/" + subject) << "\" tests=\"" << tests
            << "\" failures=\"" << failures << "\">\n"
            << body.str() << "  </testsuite>\n";
    }
    xml << "</testsuites>\n";
    return xml.str();
}

std::string roster_csv(const std::vector<RosterRow>& rows) {
    std::ostringstream out;
    out << "roster,subject,scheme,verdict,cases,ran,rule,failures,diagnosis,minimal_input\n";
    for (const RosterRow& r : rows) {
        std::string failures;
        for (const auto& [how, n] : r.failures) failures += (failures.empty() ? "" : " ") + how + "=" + std::to_string(n);
        out << csv_field(r.roster) << ',' << csv_field(r.subject) << ',' << r.scheme << ',' << to_string(r.verdict) << ','
            << r.cases << ',' << r.ran << ',' << csv_field(r.followed_rule()) << ',' << csv_field(failures) << ','
            << csv_field(r.diagnosis()) << ',' << csv_field(r.minimal_input.empty() ? r.minimal_note : r.minimal_input) << '\n';
    }
    return out.str();
}

}  // namespace

SuiteSummary summarize(const std::vector<CaseRecord>& cases) {
    SuiteSummary s;
    s.cases = static_cast<int>(cases.size());
    for (const CaseRecord& c : cases) {
        if (c.runs.empty()) {
            ++s.outcomes[outcome_label(c)];
            s.failures += is_failure(c);
            ++s.runs;
        }
        for (const RunRecord& r : c.runs) {
            ++s.outcomes[outcome_label(c, r)];
            s.failures += is_failure(c, r);
            ++s.runs;
        }
    }
    return s;
}

SuiteSummary write_suite_outputs(const std::string& dir, const json& header, const std::vector<CaseRecord>& cases) {
    create_output_folder(dir);
    const SuiteSummary summary = summarize(cases);
    json results = header;
    results["summary"] = to_json(summary);
    json records = json::array();
    for (const CaseRecord& c : cases) records.push_back(to_json(c));
    results["cases"] = std::move(records);
    const std::vector<RosterRow> roster = roster_table(cases);
    if (!roster.empty()) {
        results["roster"] = to_json(roster);
        write_file(fs::path(dir) / "roster.csv", roster_csv(roster));
    }
    write_file(fs::path(dir) / "results.json", json_text(results, 1) + "\n");
    write_file(fs::path(dir) / "results.csv", csv(cases));
    write_file(fs::path(dir) / "junit.xml", junit(header.value("suite", "suite"), cases, summary));
    return summary;
}

void clear_previous_run_files(const std::string& dir) {
    create_output_folder(dir);  // names a path that is a file, before anything is run
    for (const char* folder : {"views", "minimal"}) {
        const fs::path p = fs::path(dir) / folder;
        std::error_code ec;
        fs::remove_all(p, ec);  // a link is removed, not followed
        if (ec) throw InputError(p.string() + ": cannot remove the previous run's files (" + ec.message() + ")");
    }
}

SuiteSummary merge_suite_outputs(const std::vector<std::string>& dirs, const std::string& out_dir) {
    ShardResults first;  // the first shard's header, which every other shard's must match
    std::map<int, CaseRecord> cases;
    std::vector<std::string> shards;
    for (const std::string& d : dirs) {
        const fs::path p = fs::path(d) / "results.json";
        std::ifstream in(p);
        if (!in) throw InputError(p.string() + ": no results.json (not a suite output folder)");
        ShardResults r = read_shard_results(in, p.string());
        if (first.header.is_null()) {
            first.header = r.header;
        } else if (r.suite() != first.suite() || r.jobs_total() != first.jobs_total()) {
            throw InputError(p.string() + ": suite '" + r.suite() + "' with " + std::to_string(r.jobs_total()) +
                             " jobs does not match '" + first.suite() + "' with " + std::to_string(first.jobs_total()));
        } else if (r.jobs_fingerprint() != first.jobs_fingerprint()) {
            throw InputError(p.string() + ": its jobs are not the other shards' (jobs_fingerprint " + r.jobs_fingerprint() +
                             " against " + first.jobs_fingerprint() + "): two versions of the manifest");
        }
        shards.push_back(r.shard());
        for (size_t k = 0; k < r.cases.size(); ++k) {
            CaseRecord& c = r.cases[k];
            if (cases.count(c.job)) throw InputError(p.string() + ": job " + std::to_string(c.job) + " is in two shards");
            // The 3D view a case names, and its minimal input, move with it.
            for (const std::string& file : r.files[k]) {
                const fs::path src = fs::path(d) / file, dst = fs::path(out_dir) / file;
                std::error_code ec;
                fs::create_directories(dst.parent_path(), ec);
                if (fs::absolute(src) != fs::absolute(dst)) fs::copy_file(src, dst, fs::copy_options::overwrite_existing, ec);
                if (ec) throw InputError(src.string() + ": cannot copy it to " + dst.string() + ": " + ec.message());
            }
            cases.emplace(c.job, std::move(c));
        }
    }
    // Every shard of the run, each once: a set with one missing would be a results set and a
    // report short of its jobs, with nothing to say so.
    int count = 0;
    std::vector<char> seen;
    for (size_t i = 0; i < shards.size(); ++i) {
        int index = 0, n = 0;
        if (std::sscanf(shards[i].c_str(), "%d/%d", &index, &n) != 2 || n < 1 || index < 1 || index > n)
            throw InputError(dirs[i] + ": shard '" + shards[i] + "' is not I/N");
        if (count == 0) count = n, seen.assign(static_cast<size_t>(n) + 1, 0);
        if (n != count)
            throw InputError(dirs[i] + ": shard " + shards[i] + " is of a run in " + std::to_string(n) + " shards, the others of " +
                             std::to_string(count));
        if (seen[static_cast<size_t>(index)]++) throw InputError(dirs[i] + ": shard " + shards[i] + " is given twice");
    }
    std::string missing;
    for (int i = 1; i <= count; ++i)
        if (!seen[static_cast<size_t>(i)]) missing += (missing.empty() ? "" : ", ") + std::to_string(i) + "/" + std::to_string(count);
    if (!missing.empty()) throw InputError("shard(s) " + missing + " missing: merge every shard of the run");
    std::string joined;
    for (const std::string& s : shards) joined += (joined.empty() ? "" : "+") + s;
    json header = std::move(first.header);
    header["shard"] = "merged " + joined;
    header["jobs_run"] = cases.size();
    std::vector<CaseRecord> ordered;
    for (auto& [job, c] : cases) ordered.push_back(std::move(c));
    return write_suite_outputs(out_dir, header, ordered);
}

}  // namespace crossdiv::verification
