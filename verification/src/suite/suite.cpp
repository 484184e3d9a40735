#include "crossdiv/verification/suite/suite.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/properties/curve_checks.h"
#include "crossdiv/verification/suite/limit_checks.h"
#include "crossdiv/verification/properties/surface_checks.h"
#include "crossdiv/verification/harness/inputs.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::string item;
    std::istringstream in(s);
    while (std::getline(in, item, sep))
        if (!item.empty()) out.push_back(item);
    return out;
}

double parse_number(const std::string& file, int line, const std::string& key, const std::string& value) {
    try {
        size_t used = 0;
        const double x = std::stod(value, &used);
        if (used == value.size() && std::isfinite(x)) return x;
    } catch (const std::exception&) {
    }
    throw ParseError(file, line, key + "=" + value + " is not a finite number");
}

/// Operations whose records are lists of measured checks (curve_checks.h, surface_checks.h)
/// rather than Loop comparisons.
bool is_check_operation(const std::string& op) { return op == "curves" || op == "surfaces" || op == "limits"; }

ManifestEntry parse_case(const std::string& file, int line, std::istringstream& words) {
    ManifestEntry e;
    e.line = line;
    std::string inputs, op;
    if (!(words >> inputs >> op)) throw ParseError(file, line, "expected: case INPUTS OPERATION [key=value ...]");
    e.inputs = split(inputs, ',');
    if (op != "loop" && !is_check_operation(op))
        throw ParseError(file, line, "unknown operation '" + op + "' (known: loop, curves, surfaces, limits)");
    e.operation = op;
    if (is_check_operation(op)) {
        // The curve and surface checks carry their own named tolerances (tolerances.h).
        if (std::string extra; words >> extra)
            throw ParseError(file, line, "the " + op + " operation takes no keys, got '" + extra + "'");
        return e;
    }
    e.request.options = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    for (std::string kv; words >> kv;) {
        const size_t eq = kv.find('=');
        if (eq == std::string::npos) throw ParseError(file, line, "expected key=value, got '" + kv + "'");
        const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
        if (key == "weights") {
            if (value != "loop" && value != "warren") throw ParseError(file, line, "weights must be loop or warren");
            e.request.options.weights = value == "loop" ? LoopWeights::Loop : LoopWeights::Warren;
        } else if (key == "boundary") {
            if (value != "edge-only" && value != "edge-and-corner")
                throw ParseError(file, line, "boundary must be edge-only or edge-and-corner");
            e.request.options.boundary = value == "edge-only" ? LoopBoundary::EdgeOnly : LoopBoundary::EdgeAndCorner;
        } else if (key == "levels") {
            const double l = parse_number(file, line, key, value);
            if (l != std::floor(l) || l < 1 || l > 6) throw ParseError(file, line, "levels must be an integer 1..6");
            e.request.levels = static_cast<int>(l);
        } else if (key == "against") {
            e.request.references = split(value, ',');
            try {
                select_references(Scheme::Loop, e.request.references);
            } catch (const InputError& err) {
                throw ParseError(file, line, err.what());
            }
        } else if (key == "tier") {
            try {
                e.request.tier = tier_from_string(value);
            } catch (const InputError& err) {
                throw ParseError(file, line, err.what());
            }
        } else if (key == "tolerance") {
            e.request.tolerance = parse_number(file, line, key, value);
            if (!(e.request.tolerance >= 0)) throw ParseError(file, line, "tolerance must be >= 0");
        } else {
            throw ParseError(file, line, "unknown key '" + key + "' (known: weights, boundary, levels, against, tier, tolerance)");
        }
    }
    return e;
}

std::string describe_entry(const ManifestEntry& e) {
    if (is_check_operation(e.operation)) return e.operation;
    const LoopComparisonRequest& r = e.request;
    std::string s = e.operation + " weights=" + std::string(to_string(r.options.weights)) +
                    " boundary=" + std::string(to_string(r.options.boundary)) +
                    " L" + std::to_string(r.levels) + " " + to_string(r.tier);
    if (r.tier != Tier::Strict) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", r.tolerance);
        s += std::string(" tol=") + buf;
    }
    return s;
}

json failed_record(const SuiteJob& job, const std::string& why) {
    if (is_check_operation(job.entry->operation))
        return {{"input", job.input}, {"scheme", job.entry->operation}, {"core_error", why}, {"ours_failed", true}, {"runs", json::array()}};
    return {{"input", job.input}, {"scheme", job.entry->operation}, {"levels", job.entry->request.levels},
            {"tier", to_string(job.entry->request.tier)}, {"tolerance_rel", job.entry->request.tolerance},
            {"options", {{"weights", to_string(job.entry->request.options.weights)},
                         {"boundary", to_string(job.entry->request.options.boundary)}}},
            {"core_error", why}, {"ours_failed", true}, {"runs", json::array()}};
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string xml_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string number_or_empty(const json& j, const char* key) {
    if (!j.contains(key) || !j[key].is_number()) return "";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", j[key].get<double>());
    return buf;
}

/// "measured 3.1e-16 <= tolerance 1.4e-14 rel" for a curve check ("measured -" when there is
/// no figure, e.g. two meshes with different faces).
std::string fmt_measured(const json& r) {
    const std::string measured = number_or_empty(r, "measured");
    char buf[160];
    std::snprintf(buf, sizeof buf, "measured %s %s tolerance %.3g %s", measured.empty() ? "-" : measured.c_str(),
                  r.value("verdict", "") == "agree" ? "<=" : ">", r.value("tolerance", 0.0), r.value("unit", "").c_str());
    return buf;
}

void write_file(const fs::path& p, const std::string& text) {
    std::ofstream out(p);
    if (!out) throw InputError(p.string() + ": cannot write");
    out << text;
}

}  // namespace

Manifest read_manifest(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open manifest");
    Manifest m;
    m.file = path;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (const size_t hash = text.find('#'); hash != std::string::npos) text.resize(hash);
        std::istringstream words(text);
        std::string keyword;
        if (!(words >> keyword)) continue;
        if (keyword == "suite") {
            if (!(words >> m.name)) throw ParseError(path, line, "expected: suite NAME");
        } else if (keyword == "timeout") {
            std::string v;
            if (!(words >> v)) throw ParseError(path, line, "expected: timeout SECONDS");
            m.timeout_seconds = parse_number(path, line, "timeout", v);
            if (m.timeout_seconds <= 0) throw ParseError(path, line, "timeout must be positive");
        } else if (keyword == "case") {
            m.entries.push_back(parse_case(path, line, words));
        } else {
            throw ParseError(path, line, "unknown statement '" + keyword + "' (known: suite, timeout, case)");
        }
        if (std::string extra; keyword != "case" && (words >> extra))
            throw ParseError(path, line, "unexpected '" + extra + "'");
    }
    if (m.name.empty()) throw ParseError(path, 1, "the manifest has no 'suite NAME' line");
    for (ManifestEntry& e : m.entries) e.request.timeout_seconds = m.timeout_seconds;
    return m;
}

std::string default_manifest_path() { return CROSSDIV_SUITES_DIR "/default.suite"; }

std::vector<SuiteJob> expand_jobs(const Manifest& manifest) {
    std::vector<SuiteJob> jobs;
    for (const ManifestEntry& e : manifest.entries) {
        std::vector<std::string> inputs;
        try {
            inputs = e.operation == "curves"     ? expand_curve_inputs(e.inputs)
                     : e.operation == "surfaces" ? expand_surface_inputs(e.inputs)
                     : e.operation == "limits"   ? expand_limit_inputs(e.inputs)
                                                 : expand_inputs(e.inputs);
        } catch (const InputError& err) {
            throw ParseError(manifest.file, e.line, err.what());
        }
        for (const std::string& in : inputs) {
            SuiteJob j;
            j.index = static_cast<int>(jobs.size());
            j.input = in;
            j.entry = &e;
            j.id = in + " | " + describe_entry(e);
            jobs.push_back(j);
        }
    }
    return jobs;
}

std::vector<SuiteJob> shard_jobs(const std::vector<SuiteJob>& jobs, int shard, int count) {
    if (count < 1 || shard < 1 || shard > count)
        throw InputError("shard " + std::to_string(shard) + "/" + std::to_string(count) + " is not of the form I/N with 1 <= I <= N");
    std::vector<SuiteJob> out;
    for (const SuiteJob& j : jobs)
        if (j.index % count == shard - 1) out.push_back(j);
    return out;
}

/// Error fields larger than this are not kept: the report renders them with matplotlib,
/// which stays interactive-fast up to about this many triangles.
constexpr int kErrorFieldMaxFaces = 20000;

namespace {

json run_check_job(const SuiteJob& job) {
    try {
        if (job.entry->operation == "surfaces") return to_json(check_surface_input(job.input));
        if (job.entry->operation == "limits") return check_limits(job.input);
        return to_json(job.input == "curves:synthetic" ? check_synthetic() : check_curve_file(load_curve_input(job.input), job.input));
    } catch (const InputError& e) {
        json rec = failed_record(job, e.what());
        rec["ours_failed"] = false;  // a file core refuses: recorded, not a failure of ours
        return rec;
    } catch (const std::exception& e) {
        return failed_record(job, std::string("internal error: ") + e.what());
    }
}

}  // namespace

json run_job(const SuiteJob& job, const std::string& out_dir) {
    if (is_check_operation(job.entry->operation)) {
        json rec = run_check_job(job);
        rec["job"] = job.index;
        rec["id"] = job.id;
        rec["manifest_line"] = job.entry->line;
        return rec;
    }
    LoopComparisonRequest req = job.entry->request;
    req.error_field_max_faces = kErrorFieldMaxFaces;
    json rec;
    try {
        const TriMesh mesh = to_tri_mesh(load_input(job.input), "Loop subdivision");
        LoopComparison c;
        bool refused = false;
        std::string why;
        try {
            loop_input_connectivity(mesh);
        } catch (const InputError& e) {
            refused = true;
            why = e.what();
        }
        c = refused ? compare_loop_refused(mesh, job.input, req, why) : compare_loop(mesh, job.input, req);
        rec = to_json(c);
        for (size_t i = 0; i < c.runs.size(); ++i) {
            const auto& field = c.runs[i].error_field;
            if (!field) continue;
            const std::string name = "fields/job" + std::to_string(job.index) + "-" + c.runs[i].reference + ".json";
            json positions = json::array(), faces = json::array(), distance = json::array();
            for (const Vec3& p : field->mesh.positions) positions.push_back({p.x(), p.y(), p.z()});
            for (int f = 0; f < field->mesh.num_faces(); ++f)
                faces.push_back(std::vector<int>(field->mesh.face(f), field->mesh.face(f) + field->mesh.face_size(f)));
            for (double d : field->distance) distance.push_back(std::isfinite(d) ? json(d) : json(nullptr));
            fs::create_directories(fs::path(out_dir) / "fields");
            write_file(fs::path(out_dir) / name,
                       json{{"level", field->level}, {"positions", positions}, {"faces", faces}, {"distance", distance}}.dump());
            rec["runs"][i]["error_field"] = name;
        }
    } catch (const InputError& e) {
        // Not even a triangle mesh core can read: nothing to hand the references either.
        rec = failed_record(job, e.what());
        rec["ours_failed"] = false;
    } catch (const std::exception& e) {
        rec = failed_record(job, std::string("internal error: ") + e.what());
    }
    rec["job"] = job.index;
    rec["id"] = job.id;
    rec["manifest_line"] = job.entry->line;
    return rec;
}

std::vector<json> run_jobs(const std::vector<SuiteJob>& jobs, int workers, const std::string& out_dir,
                           const std::function<void(int, int, const json&)>& progress) {
    workers = std::max(1, std::min<int>(workers, static_cast<int>(jobs.size())));
    fs::create_directories(out_dir);
    int pipe_fd[2];
    if (pipe(pipe_fd) != 0) throw std::runtime_error("pipe failed");
    std::vector<pid_t> pids;
    std::vector<fs::path> parts;
    std::fflush(nullptr);
    for (int w = 0; w < workers; ++w) {
        parts.push_back(fs::path(out_dir) / ("worker" + std::to_string(w) + ".jsonl"));
        const pid_t pid = fork();
        if (pid < 0) throw std::runtime_error("fork failed");
        if (pid == 0) {
            // Worker w: every workers-th job; one JSON line per record, then a line on the
            // pipe with the job index (short writes to a pipe are atomic).
            close(pipe_fd[0]);
            std::ofstream part(parts.back());
            for (size_t i = w; i < jobs.size(); i += workers) {
                part << run_job(jobs[i], out_dir).dump() << "\n" << std::flush;
                const std::string msg = std::to_string(i) + "\n";
                if (write(pipe_fd[1], msg.data(), msg.size()) < 0) _exit(1);
            }
            part.close();
            _exit(0);
        }
        pids.push_back(pid);
    }
    close(pipe_fd[1]);

    // Progress: read finished indices as they come; records are read back at the end.
    std::map<size_t, json> done;
    std::vector<std::streamoff> offsets(workers, 0);
    auto collect = [&](int w) {
        std::ifstream in(parts[w]);
        in.seekg(offsets[w]);
        std::string line;
        while (std::getline(in, line) && !line.empty()) {
            json rec = json::parse(line, nullptr, false);
            if (rec.is_discarded()) break;
            offsets[w] = in.tellg();
            done.emplace(rec["job"].get<int>(), std::move(rec));
        }
    };
    std::string buffer;
    char chunk[256];
    for (ssize_t n; (n = read(pipe_fd[0], chunk, sizeof chunk)) != 0;) {
        if (n < 0) {
            if (errno == EINTR) continue;
            break;
        }
        buffer.append(chunk, static_cast<size_t>(n));
        for (size_t nl; (nl = buffer.find('\n')) != std::string::npos;) {
            const size_t i = std::stoul(buffer.substr(0, nl));
            buffer.erase(0, nl + 1);
            collect(static_cast<int>(i % workers));
            const auto it = done.find(static_cast<size_t>(jobs[i].index));
            if (it != done.end()) progress(static_cast<int>(done.size()), static_cast<int>(jobs.size()), it->second);
        }
    }
    close(pipe_fd[0]);
    std::vector<int> died(workers, 0);
    for (int w = 0; w < workers; ++w) {
        int status = 0;
        waitpid(pids[w], &status, 0);
        if (WIFSIGNALED(status)) died[w] = WTERMSIG(status);
        collect(w);
        std::error_code ec;
        fs::remove(parts[w], ec);
    }
    std::vector<json> out;
    for (size_t i = 0; i < jobs.size(); ++i) {
        auto it = done.find(static_cast<size_t>(jobs[i].index));
        if (it != done.end()) {
            out.push_back(std::move(it->second));
            continue;
        }
        // The worker died in core (a crash of ours, not of a reference: those are isolated).
        const int w = static_cast<int>(i % workers);
        json rec = failed_record(jobs[i], died[w] ? "worker crashed in core: signal " + std::to_string(died[w]) + " (" +
                                                        strsignal(died[w]) + ")"
                                                  : "worker ended without a record");
        rec["job"] = jobs[i].index;
        rec["id"] = jobs[i].id;
        rec["manifest_line"] = jobs[i].entry->line;
        progress(static_cast<int>(out.size() + 1), static_cast<int>(jobs.size()), rec);
        out.push_back(std::move(rec));
    }
    return out;
}

std::string run_outcome(const json& rec, const json& run) {
    if (rec.value("ours_failed", false)) return "ours-failed";
    const std::string verdict = run.value("verdict", std::string());
    const std::string cls = run.value("divergence_class", std::string());
    if (verdict == "diverge" || verdict == "ours-rejected") return cls.empty() ? verdict : verdict + " (" + cls + ")";
    return verdict;
}

std::string describe_record(const json& rec) {
    if (is_check_operation(rec.value("scheme", "")) && !rec["runs"].empty()) {
        int failed = 0, classified = 0;
        std::string which;
        for (const json& run : rec["runs"]) {
            if (run.value("verdict", "") == "agree") continue;
            // A divergence whose cause is measured (a limits run's boundary-rule, say) is a
            // finding, not a failure.
            const std::string cls = run.value("divergence_class", std::string());
            if (!cls.empty() && cls != "unexplained") {
                ++classified;
                continue;
            }
            ++failed;
            if (which.size() < 200) which += " " + run.value("curve", "") + "/" + run.value("check", "");
        }
        const std::string op = rec.value("scheme", "");
        return std::to_string(rec["runs"].size()) +
               (op == "curves" ? " curve checks" : op == "limits" ? " limit checks" : " surface checks") +
               (classified ? ", " + std::to_string(classified) + " classified divergences" : "") +
               (failed ? ", " + std::to_string(failed) + " FAILED:" + which : ", all within tolerance");
    }
    if (rec["runs"].empty())
        return (rec.value("ours_failed", false) ? "ours-failed: " : "ours-rejected: ") + rec.value("core_error", std::string());
    std::string s;
    for (const json& run : rec["runs"])
        s += (s.empty() ? "" : ", ") + run.value("reference", std::string("?")) + " " + run_outcome(rec, run);
    return s;
}

bool run_is_failure(const json& rec, const json& run) {
    if (rec.value("ours_failed", false)) return true;
    return run.value("verdict", std::string()) == "diverge" && run.value("divergence_class", std::string()) == "unexplained";
}

json write_suite_outputs(const std::string& dir, const json& header, const std::vector<json>& cases) {
    fs::create_directories(dir);
    std::map<std::string, int> counts;
    int failures = 0, testcases = 0;
    for (const json& c : cases) {
        if (c["runs"].empty()) {
            ++counts[c.value("ours_failed", false) ? "ours-failed" : "ours-rejected"];
            failures += c.value("ours_failed", false);
            ++testcases;
        }
        for (const json& r : c["runs"]) {
            ++counts[run_outcome(c, r)];
            failures += run_is_failure(c, r);
            ++testcases;
        }
    }
    json results = header;
    results["summary"] = {{"cases", cases.size()}, {"runs", testcases}, {"failures", failures}, {"outcomes", counts}};
    results["cases"] = cases;
    write_file(fs::path(dir) / "results.json", results.dump(1) + "\n");

    std::ostringstream csv;
    csv << "job,input,scheme,weights,boundary,levels,tier,tolerance,reference,status,outcome,max_rel,rms_rel,"
           "hausdorff_rel,worst_valence,worst_boundary,core_seconds,reference_seconds,explanation\n";
    for (const json& c : cases) {
        auto row = [&](const json& r) {
            const json pos = r.value("positions", json::object());
            const json worst = pos.contains("worst") && !pos["worst"].empty() ? pos["worst"][0] : json::object();
            const json options = c.value("options", json::object());
            csv << c["job"] << "," << csv_field(c["input"]) << "," << c.value("scheme", "") << ","
                << options.value("weights", "") << "," << options.value("boundary", "") << ","
                << (c.contains("levels") ? c["levels"].dump() : "") << "," << c.value("tier", "") << ","
                << number_or_empty(c.contains("tolerance_rel") ? c : r, c.contains("tolerance_rel") ? "tolerance_rel" : "tolerance") << ","
                << csv_field(r.contains("check") ? r.value("curve", "") + " " + r.value("check", "") + " vs " + r.value("reference", "")
                                                 : r.value("reference", "")) << "," << r.value("status", "") << ","
                << csv_field(r.is_null() ? (c.value("ours_failed", false) ? "ours-failed" : "ours-rejected") : run_outcome(c, r))
                << "," << number_or_empty(r.contains("check") ? r : pos, r.contains("check") ? "measured" : "max_rel") << ","
                << number_or_empty(pos, "rms_rel") << ","
                << number_or_empty(r, "hausdorff_rel") << "," << (worst.contains("valence") ? worst["valence"].dump() : "")
                << "," << (worst.contains("boundary") ? worst["boundary"].dump() : "") << ","
                << number_or_empty(c, "core_seconds") << "," << number_or_empty(r, "seconds") << ","
                << csv_field(r.is_null() ? c.value("core_error", "") : r.value("explanation", "")) << "\n";
        };
        if (c["runs"].empty()) row(json());
        for (const json& r : c["runs"]) row(r);
    }
    write_file(fs::path(dir) / "results.csv", csv.str());

    std::ostringstream xml;
    const std::string suite = header.value("suite", "suite");
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"crossdiv\" tests=\"" << testcases
        << "\" failures=\"" << failures << "\">\n  <testsuite name=\"" << xml_escape(suite) << "\" tests=\"" << testcases
        << "\" failures=\"" << failures << "\">\n";
    for (const json& c : cases) {
        const std::string classname = "crossdiv." + suite + "." + c.value("scheme", "loop");
        auto testcase = [&](const std::string& who, const std::string& outcome, bool failure, const std::string& text,
                            double seconds) {
            xml << "    <testcase classname=\"" << xml_escape(classname) << "\" name=\""
                << xml_escape(c["id"].get<std::string>() + " vs " + who) << "\" time=\"" << seconds << "\">\n";
            if (failure) xml << "      <failure message=\"" << xml_escape(outcome) << "\">" << xml_escape(text) << "</failure>\n";
            xml << "      <system-out>" << xml_escape(outcome + ": " + text) << "</system-out>\n    </testcase>\n";
        };
        if (c["runs"].empty())
            testcase("core", c.value("ours_failed", false) ? "ours-failed" : "ours-rejected", c.value("ours_failed", false),
                     c.value("core_error", ""), 0.0);
        for (const json& r : c["runs"]) {
            // Curve checks name the curve and the property; Loop runs name the reference.
            const std::string who = r.contains("check") ? r.value("curve", "") + " " + r.value("check", "") + " vs " +
                                                              r.value("reference", "")
                                                        : r.value("reference", "");
            std::string text = r.value("explanation", "");
            if (r.contains("check"))
                text = fmt_measured(r) + "; " + text;
            testcase(who, run_outcome(c, r), run_is_failure(c, r), text, r.value("seconds", 0.0));
        }
    }
    xml << "  </testsuite>\n</testsuites>\n";
    write_file(fs::path(dir) / "junit.xml", xml.str());
    return results["summary"];
}

json merge_suite_outputs(const std::vector<std::string>& dirs, const std::string& out_dir) {
    json header;
    std::map<int, json> cases;
    std::vector<std::string> shards;
    for (const std::string& d : dirs) {
        const fs::path p = fs::path(d) / "results.json";
        std::ifstream in(p);
        if (!in) throw InputError(p.string() + ": no results.json (not a suite output folder)");
        json r = json::parse(in, nullptr, false);
        if (r.is_discarded() || !r.contains("cases")) throw InputError(p.string() + ": not a crossdiv suite results file");
        if (header.is_null()) {
            header = r;
            header.erase("cases");
            header.erase("summary");
        } else if (r.value("suite", "") != header.value("suite", "") || r.value("jobs_total", -1) != header.value("jobs_total", -1)) {
            throw InputError(p.string() + ": suite '" + r.value("suite", "") + "' with " +
                             std::to_string(r.value("jobs_total", -1)) + " jobs does not match '" +
                             header.value("suite", "") + "' with " + std::to_string(header.value("jobs_total", -1)));
        }
        shards.push_back(r.value("shard", "?"));
        for (json& c : r["cases"]) {
            const int job = c["job"].get<int>();
            if (cases.count(job)) throw InputError(p.string() + ": job " + std::to_string(job) + " is in two shards");
            for (json& run : c["runs"])
                if (run.contains("error_field")) {
                    const fs::path src = fs::path(d) / run["error_field"].get<std::string>();
                    fs::create_directories(fs::path(out_dir) / "fields");
                    if (fs::absolute(src) != fs::absolute(fs::path(out_dir) / run["error_field"].get<std::string>()))
                        fs::copy_file(src, fs::path(out_dir) / run["error_field"].get<std::string>(),
                                      fs::copy_options::overwrite_existing);
                }
            cases.emplace(job, std::move(c));
        }
    }
    std::string joined;
    for (const std::string& s : shards) joined += (joined.empty() ? "" : "+") + s;
    header["shard"] = "merged " + joined;
    header["jobs_run"] = cases.size();
    std::vector<json> ordered;
    for (auto& [job, c] : cases) ordered.push_back(std::move(c));
    return write_suite_outputs(out_dir, header, ordered);
}

int render_report(const std::string& dir) {
    // Debian's interpreter has matplotlib; a python3 earlier on PATH may not.
    const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    return run_process({python, CROSSDIV_REPORTS_DIR "/make_report.py", dir});
}

}  // namespace crossdiv::verification
