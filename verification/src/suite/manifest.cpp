#include "crossdiv/verification/suite/manifest.h"

#include <fnmatch.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/edit_subject.h"
#include "crossdiv/verification/harness/install_paths.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/suite/operations.h"

namespace crossdiv::verification {
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

/// Runs `parse` and turns its InputError into a ParseError at file:line.
template <class F>
auto at_line(const std::string& file, int line, F&& parse) {
    try {
        return parse();
    } catch (const ParseError&) {
        throw;
    } catch (const InputError& err) {
        throw ParseError(file, line, err.what());
    }
}

/// The keys every comparison case takes: levels, references, tier and tolerance. False for a
/// key that is not one of them.
bool parse_comparison_key(const std::string& file, int line, Scheme scheme, const std::string& key, const std::string& value,
                          RefinementRequest& r) {
    if (key == "levels") {
        const double l = parse_number(file, line, key, value);
        if (l != std::floor(l) || l < 1 || l > 6) throw ParseError(file, line, "levels must be an integer 1..6");
        r.levels = static_cast<int>(l);
    } else if (key == "against") {
        r.references = split(value, ',');
        at_line(file, line, [&] { return select_references(scheme, r.references); });
    } else if (key == "tier") {
        r.tier = at_line(file, line, [&] { return tier_from_string(value); });
    } else if (key == "tolerance") {
        r.tolerance = parse_number(file, line, key, value);
        if (!(r.tolerance >= 0)) throw ParseError(file, line, "tolerance must be >= 0");
    } else if (key == "refuses") {
        for (const std::string& name : split(value, ',')) {
            const DivergenceClass c = at_line(file, line, [&] { return divergence_class_from_string(name); });
            if (c != DivergenceClass::NonManifoldHandling && c != DivergenceClass::OrientationHandling &&
                c != DivergenceClass::DegenerateFaceHandling && c != DivergenceClass::InvalidInputHandling)
                throw ParseError(file, line,
                                 "refuses=" + name + ": a refusal is declared by the input handling it shows "
                                 "(non-manifold-handling, orientation-handling, degenerate-face-handling, invalid-input-handling)");
            r.expected_refusals.push_back(c);
        }
    } else {
        return false;
    }
    return true;
}

/// Splits a case's key=value words, handing each to `parse` (false: an unknown key).
template <class Parse>
void parse_keys(const std::string& file, int line, std::istringstream& words, const std::string& known, Parse&& parse) {
    for (std::string kv; words >> kv;) {
        const size_t eq = kv.find('=');
        if (eq == std::string::npos) throw ParseError(file, line, "expected key=value, got '" + kv + "'");
        const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
        if (!parse(key, value)) throw ParseError(file, line, "unknown key '" + key + "' (known: " + known + ")");
    }
}

/// The keys of a loop case: its rules, levels, references, tier and tolerance.
void parse_loop_keys(const std::string& file, int line, std::istringstream& words, RefinementRequest& r, RuleFlags& flags) {
    r.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    parse_keys(file, line, words, "weights, boundary, fvar, levels, against, tier, tolerance, refuses",
               [&](const std::string& key, const std::string& value) {
                   if (key == "fvar") {
                       flags.face_varying = value;
                       at_line(file, line, [&] { return face_varying_rule_from_string(value); });
                   } else if (key == "weights") {
                       r.rule.loop.weights = at_line(file, line, [&] { return loop_weights_from_string(value); });
                   } else if (key == "boundary") {
                       if (value != "edge-only" && value != "edge-and-corner")
                           throw ParseError(file, line, "boundary must be edge-only or edge-and-corner");
                       r.rule.loop.boundary = loop_boundary_from_string(value);
                   } else {
                       return parse_comparison_key(file, line, Scheme::Loop, key, value, r);
                   }
                   return true;
               });
}

/// The keys of another scheme's case: its boundary rule (and Catmull-Clark's crease decay),
/// levels, references, tier and tolerance. The rule is checked here and resolved per input
/// against the input's tags when the job runs.
void parse_scheme_keys(const std::string& file, int line, std::istringstream& words, Scheme scheme, RefinementRequest& r,
                       RuleFlags& flags) {
    const bool creases = scheme == Scheme::CatmullClark;
    const bool fvar = creases || scheme == Scheme::Bilinear;
    parse_keys(file, line, words,
               std::string("boundary, ") + (creases ? "crease-method, triangles, " : "") + (fvar ? "fvar, " : "") +
                   "levels, against, tier, tolerance, refuses",
               [&](const std::string& key, const std::string& value) {
                   if (key == "fvar" && fvar) {
                       flags.face_varying = value;
                       at_line(file, line, [&] { return face_varying_rule_from_string(value); });
                   } else if (key == "boundary") {
                       // `none` is OpenSubdiv's VTX_BOUNDARY_NONE: edge-only with the boundary
                       // faces made holes, per input (resolve_tag_rules).
                       if (value != "none" || scheme != Scheme::CatmullClark)
                           at_line(file, line, [&] { return rule_from_boundary_name(scheme, value); });
                       flags.boundary = value;
                   } else if (key == "triangles" && creases) {
                       if (value != "catmark" && value != "smooth")
                           throw ParseError(file, line, "triangles must be catmark or smooth");
                       flags.triangles = value;
                   } else if (key == "crease-method" && creases) {
                       at_line(file, line, [&] { return crease_method(value, PolyMesh{}); });
                       flags.creasing = value;
                   } else {
                       return parse_comparison_key(file, line, scheme, key, value, r);
                   }
                   return true;
               });
}

/// A course task's keys: t= (casteljau), res= (patch), frames= (sweep), ops= (flip-split),
/// each only where its task reads it.
void parse_task_keys(const std::string& file, int line, std::istringstream& words, ManifestEntry& e) {
    const std::string& op = e.operation->name;
    std::string rest;
    std::getline(words, rest);
    for (const std::string& word : at_line(file, line, [&] { return statement_words(rest); })) {
        const size_t eq = word.find('=');
        const std::string key = word.substr(0, eq), value = eq == std::string::npos ? "" : word.substr(eq + 1);
        const auto only = [&](const char* task) {
            if (op != task) throw ParseError(file, line, "the " + op + " task takes no " + key + "= key (" + task + " does)");
        };
        if (key == "t") {
            only("casteljau");
            e.task.t = parse_number(file, line, "t", value);
            if (!(e.task.t >= 0 && e.task.t <= 1)) throw ParseError(file, line, "t must be in [0, 1], got " + value);
        } else if (key == "res") {
            only("patch");
            const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), e.task.res);
            if (ec != std::errc() || end != value.data() + value.size() || e.task.res < 1 || e.task.res > 1024)
                throw ParseError(file, line, "res=" + value + " is not a whole number in [1, 1024]");
        } else if (key == "frames") {
            only("sweep");
            if (value != "recursive" && value != "rmf") throw ParseError(file, line, "frames=" + value + ": recursive or rmf");
            e.task.frames = value;
        } else if (key == "ops") {
            only("flip-split");
            at_line(file, line, [&] { return parse_edit_operations(value); });  // checked here, applied per input
            e.task.ops = value;
        } else {
            throw ParseError(file, line, "unknown key '" + word + "' for the " + op + " task (t=, res=, frames=, ops=)");
        }
    }
    if (op == "flip-split" && e.task.ops.empty()) throw ParseError(file, line, "the flip-split task needs ops='flip A B, split C D, ...'");
}

/// An invariance case's keys: scheme= (required) with that scheme's rule keys, levels= and
/// tolerance=, and impls=, transform=, seed=. A comparison's against= and tier= have no
/// meaning here (the implementations are compared with themselves, within the tolerance or
/// bit for bit as each transformation says).
void parse_invariance_keys(const std::string& file, int line, std::istringstream& words, ManifestEntry& e) {
    std::string scheme, rule_keys;
    for (std::string kv; words >> kv;) {
        const size_t eq = kv.find('=');
        const std::string key = kv.substr(0, eq), value = eq == std::string::npos ? "" : kv.substr(eq + 1);
        if (key == "scheme") {
            scheme = value;
        } else if (key == "impls") {
            e.invariance.implementations = split(value, ',');
        } else if (key == "transform") {
            for (const std::string& t : split(value, ','))
                e.invariance.transformations.push_back(at_line(file, line, [&] { return input_transformation_from_string(t); }));
        } else if (key == "seed") {
            const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), e.invariance.seed);
            if (ec != std::errc() || end != value.data() + value.size())
                throw ParseError(file, line, "seed=" + value + " is not a whole number in [0, 2^64)");
        } else if (key == "against" || key == "tier") {
            throw ParseError(file, line, "the invariance operation takes no " + key +
                                             "= (each implementation is compared with itself; choose them with impls=)");
        } else {
            rule_keys += kv + " ";
        }
    }
    if (scheme.empty()) throw ParseError(file, line, "the invariance operation needs scheme=NAME");
    e.request.scheme = at_line(file, line, [&] { return scheme_from_string(scheme); });
    std::istringstream rest(rule_keys);
    if (e.request.scheme == Scheme::Loop) parse_loop_keys(file, line, rest, e.request, e.rule_flags);
    else parse_scheme_keys(file, line, rest, e.request.scheme, e.request, e.rule_flags);
    for (const std::string& name : e.invariance.implementations)
        at_line(file, line, [&] {
            if (!find_implementation(name).support(e.request.scheme))
                throw InputError("impls=" + name + ": it has no " + std::string(to_string(e.request.scheme)) + " refinement");
            return 0;
        });
    if (e.invariance.implementations.empty()) {
        e.invariance.implementations.push_back(core_implementation().name());
        for (const Implementation* r : references_for(e.request.scheme)) e.invariance.implementations.push_back(r->name());
    }
}

ManifestEntry parse_case(const std::string& file, int line, std::istringstream& words) {
    ManifestEntry e;
    e.line = line;
    std::string inputs, op;
    if (!(words >> inputs >> op)) throw ParseError(file, line, "expected: case INPUTS OPERATION [key=value ...]");
    e.inputs = split(inputs, ',');
    e.operation = at_line(file, line, [&] { return &find_operation(op); });
    if (e.operation->kind == OperationKind::Task) {
        parse_task_keys(file, line, words, e);
        return e;
    }
    if (e.operation->kind == OperationKind::Invariance) {
        parse_invariance_keys(file, line, words, e);
        return e;
    }
    if (e.operation->kind != OperationKind::Comparison) {
        // The checks and studies carry their own named tolerances (tolerances.h).
        if (std::string extra; words >> extra)
            throw ParseError(file, line, "the " + op + " operation takes no keys, got '" + extra + "'");
        return e;
    }
    const Scheme scheme = e.operation->scheme;
    e.request.scheme = scheme;
    std::vector<std::string>& references = e.request.references;
    if (scheme == Scheme::Loop) parse_loop_keys(file, line, words, e.request, e.rule_flags);
    else parse_scheme_keys(file, line, words, scheme, e.request, e.rule_flags);
    // Without against=, the references registered so far: a `reference` statement joins
    // the cases after it.
    e.references_named = !references.empty();
    if (references.empty())
        for (const Implementation* r : references_for(scheme)) references.push_back(r->name());
    return e;
}

/// The id's description of an entry: the operation, and a comparison's keys.
std::string describe_entry(const ManifestEntry& e) {
    if (e.operation->kind == OperationKind::Task) {
        const std::string& op = e.operation->name;
        char t[32];
        std::snprintf(t, sizeof t, "%g", e.task.t);
        return op + (op == "casteljau" ? std::string(" t=") + t : "") + (op == "patch" ? " res=" + std::to_string(e.task.res) : "") +
               (op == "sweep" ? " frames=" + e.task.frames : "") + (op == "flip-split" ? " ops=" + e.task.ops : "") +
               (e.subject ? " subject=" + e.subject->name : "");
    }
    const bool invariance = e.operation->kind == OperationKind::Invariance;
    if (e.operation->kind != OperationKind::Comparison && !invariance) return e.operation->name;
    const bool loop = e.request.scheme == Scheme::Loop;
    const Tier tier = invariance ? Tier::Weak : e.request.tier;
    const double tolerance = e.request.tolerance;
    std::string s = e.operation->name + (invariance ? " " + std::string(to_string(e.request.scheme)) : "");
    if (loop) {
        s += " " + rule_name(Scheme::Loop, e.request.rule);
    } else {
        // The rule the case names; an input's tags may still choose where it names none.
        s += " boundary=" + (e.rule_flags.boundary.empty() ? std::string("default") : e.rule_flags.boundary);
        if (!e.rule_flags.creasing.empty()) s += " crease-method=" + e.rule_flags.creasing;
    }
    if (!e.rule_flags.face_varying.empty()) s += " fvar=" + e.rule_flags.face_varying;
    if (!e.rule_flags.triangles.empty()) s += " triangles=" + e.rule_flags.triangles;
    s += " L" + std::to_string(e.request.levels) + (invariance ? "" : " " + std::string(to_string(tier)));
    if (tier != Tier::Strict) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", tolerance);
        s += std::string(" tol=") + buf;
    }
    for (size_t k = 0; k < e.request.expected_refusals.size(); ++k)
        s += (k == 0 ? std::string(" refuses=") : std::string(",")) + to_string(e.request.expected_refusals[k]);
    // Two cases that differ only in the references they name (the libraries, and Blender apart)
    // are two cases: their ids say so.
    for (size_t k = 0; e.references_named && k < e.request.references.size(); ++k)
        s += (k == 0 ? std::string(" against=") : std::string(",")) + e.request.references[k];
    if (invariance) {
        if (!e.subject) {
            s += " impls=";
            for (size_t k = 0; k < e.invariance.implementations.size(); ++k)
                s += (k ? "," : "") + e.invariance.implementations[k];
        }
        for (size_t k = 0; k < e.invariance.transformations.size(); ++k)
            s += (k == 0 ? std::string(" transform=") : std::string(",")) + to_string(e.invariance.transformations[k]);
        s += " seed=" + std::to_string(e.invariance.seed);
    }
    if (e.subject) s += " subject=" + e.subject->name;
    return s;
}

/// A subject's program spec: a refusal status is a reference's (`rejects=`); a subject that
/// refuses an input fails on it. @throws InputError.
void check_subject_spec(const ProgramSpec& spec) {
    if (!spec.refusal_exit_codes.empty()) throw InputError("rejects= is for references: a subject that refuses an input fails on it");
}

/// The subjects of a `subjects NAME dir=PATTERN command='..{dir}..' | result='{dir}/..'
/// [key=value ...]` statement: one per submission folder, named after it.
std::vector<std::shared_ptr<const ManifestSubject>> roster_subjects(const std::vector<std::string>& words,
                                                                    const std::string& base_dir, double timeout,
                                                                    ProgramStatements programs) {
    if (words.size() < 4) throw InputError("expected: subjects NAME dir='FOLDERS/*' command='...' (or result='{dir}/...')");
    std::string pattern, result;
    std::vector<std::string> keys;
    for (size_t k = 2; k < words.size(); ++k) {
        if (words[k].starts_with("dir=")) pattern = words[k].substr(4);
        else if (words[k].starts_with("result=")) result = words[k].substr(7);
        else keys.push_back(words[k]);
    }
    if (pattern.empty()) throw InputError("subjects " + words[1] + ": no dir='FOLDERS/*' naming the submissions");
    if (result.empty() == keys.empty())
        throw InputError("subjects " + words[1] + ": give command='...' (with its keys) or result='{dir}/...', one of them");
    std::vector<std::shared_ptr<const ManifestSubject>> out;
    for (const std::string& folder : submission_folders(pattern, base_dir)) {
        auto s = std::make_shared<ManifestSubject>();
        s->name = std::filesystem::path(folder).filename().string();
        check_subject_name(s->name);  // a folder named core or opensubdiv would be taken for it
        s->roster = words[1];
        s->dir = folder;
        if (!result.empty()) {
            // {dir} is a path here, put in the pattern as it is; {input} and {levels} stay.
            std::string pattern_in_folder = result;
            for (size_t at; (at = pattern_in_folder.find("{dir}")) != std::string::npos;) pattern_in_folder.replace(at, 5, folder);
            s->result_pattern = pattern_in_folder[0] == '/' ? pattern_in_folder : base_dir + "/" + pattern_in_folder;
        } else {
            ProgramSpec spec = program_spec(s->name, keys, base_dir, timeout);
            check_subject_spec(spec);
            spec.dir = folder;
            s->task = TaskCommand(spec.command, base_dir, folder);
            s->timeout_seconds = spec.timeout_seconds;
            if (programs == ProgramStatements::CheckOnly) check_program_spec(spec);
            else s->program = std::shared_ptr<const Implementation>(make_program_implementation(spec));
        }
        out.push_back(std::move(s));
    }
    return out;
}

}  // namespace

std::vector<std::string> statement_words(const std::string& text) {
    std::vector<std::string> out;
    std::string word;
    bool in_word = false;
    char quote = 0;
    for (char c : text) {
        if (quote) {
            if (c == quote) quote = 0;
            else word += c;
        } else if (c == '\'' || c == '"') {
            quote = c;
            in_word = true;
        } else if (c == ' ' || c == '\t' || c == '\r') {
            if (in_word) out.push_back(word);
            word.clear();
            in_word = false;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (quote) throw InputError(std::string("unclosed ") + quote);
    if (in_word) out.push_back(word);
    return out;
}

ProgramSpec program_spec(const std::string& name, const std::vector<std::string>& key_values, const std::string& base_dir,
                         double default_timeout) {
    ProgramSpec spec;
    spec.name = name;
    spec.base_dir = base_dir;
    spec.timeout_seconds = default_timeout;
    for (const std::string& kv : key_values) {
        const size_t eq = kv.find('=');
        if (eq == std::string::npos) throw InputError("expected key=value, got '" + kv + "'");
        const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
        if (key == "command") spec.command = value;
        else if (key == "setup") spec.setup = value;
        else if (key == "serve") spec.serve = value;
        else if (key == "schemes")
            for (const std::string& s : split(value, ',')) spec.schemes.push_back(scheme_from_string(s));
        else if (key == "precision") {
            if (value != "double" && value != "float") throw InputError("precision must be double or float, got '" + value + "'");
            spec.precision = value == "float" ? Precision::Float : Precision::Double;
        } else if (key == "weights") spec.weights = split(value, ',');
        else if (key == "boundary") spec.boundaries = split(value, ',');
        else if (key == "levels") spec.levels = level_mode_from_string(value);
        else if (key == "rejects") {
            for (const std::string& code : split(value, ',')) {
                size_t used = 0;
                int c = 0;
                try {
                    c = std::stoi(code, &used);
                } catch (const std::exception&) {
                }
                if (used != code.size() || c < 1 || c > 255) throw InputError("rejects takes exit statuses 1..255, got '" + code + "'");
                spec.refusal_exit_codes.push_back(c);
            }
        } else if (key == "timeout") {
            size_t used = 0;
            double t = 0;
            try {
                t = std::stod(value, &used);
            } catch (const std::exception&) {
            }
            if (used != value.size() || !(t > 0) || !std::isfinite(t)) throw InputError("timeout must be a positive number of seconds");
            spec.timeout_seconds = t;
        } else
            throw InputError("unknown key '" + key + "' (known: command, serve, schemes, precision, weights, boundary, levels, timeout, setup, rejects)");
    }
    if (spec.command.empty()) throw InputError("program '" + name + "' has no command='...'");
    return spec;
}

std::vector<std::string> submission_folders(const std::string& pattern, const std::string& base_dir) {
    namespace fs = std::filesystem;
    const fs::path full = fs::path(pattern).is_absolute() || base_dir.empty() ? fs::path(pattern) : fs::path(base_dir) / pattern;
    const fs::path parent = full.parent_path().empty() ? fs::path(".") : full.parent_path();
    const std::string glob = full.filename().string();
    std::error_code ec;
    if (!fs::is_directory(parent, ec)) throw InputError("dir='" + pattern + "': no folder " + parent.string());
    std::vector<std::string> out;
    for (const fs::directory_entry& e : fs::directory_iterator(parent, ec)) {
        const std::string name = e.path().filename().string();
        if (e.is_directory(ec) && ::fnmatch(glob.c_str(), name.c_str(), FNM_PERIOD) == 0)
            out.push_back(fs::absolute(e.path(), ec).lexically_normal().string());
    }
    if (out.empty()) throw InputError("dir='" + pattern + "' matches no folder in " + parent.string());
    std::sort(out.begin(), out.end());
    return out;
}

std::string ManifestSubject::result_path(const std::string& input, int levels) const {
    std::string stem = input;
    if (const size_t colon = stem.find(':'); colon != std::string::npos && stem.find('/') == std::string::npos)
        stem = stem.substr(colon + 1);
    stem = std::filesystem::path(stem).stem().string();
    std::string out;
    for (size_t i = 0; i < result_pattern.size(); ++i) {
        if (result_pattern.compare(i, 7, "{input}") == 0) {
            out += stem;
            i += 6;
        } else if (result_pattern.compare(i, 8, "{levels}") == 0) {
            out += std::to_string(levels);
            i += 7;
        } else {
            out += result_pattern[i];
        }
    }
    return out;
}

Manifest read_manifest(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open manifest");
    return read_manifest(in, path, std::filesystem::absolute(path).parent_path().string(), ProgramStatements::Register);
}

Manifest read_manifest(std::istream& in, const std::string& path, const std::string& base_dir, ProgramStatements programs) {
    Manifest m;
    m.file = path;
    // The implementations under test of the cases that follow: one (`subject`), one per
    // submission folder (`subjects`), or none (core).
    std::vector<std::shared_ptr<const ManifestSubject>> subjects;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (const size_t hash = text.find('#'); hash != std::string::npos) text.resize(hash);
        const std::vector<std::string> all = at_line(path, line, [&] { return statement_words(text); });
        if (all.empty()) continue;
        const std::string& keyword = all[0];
        if (keyword == "subjects") {
            subjects = at_line(path, line, [&] { return roster_subjects(all, base_dir, m.timeout_seconds, programs); });
            continue;
        }
        if (keyword == "reference" || keyword == "subject") {
            if (all.size() < 3) throw ParseError(path, line, "expected: " + keyword + " NAME key=value ...");
            const std::vector<std::string> keys(all.begin() + 2, all.end());
            if (keyword == "subject")
                at_line(path, line, [&] {
                    check_subject_name(all[1]);
                    return 0;
                });
            if (keyword == "subject" && keys.size() == 1 && keys[0].starts_with("result=")) {
                auto s = std::make_shared<ManifestSubject>();
                s->name = all[1];
                s->result_pattern = keys[0].substr(7);
                if (!s->result_pattern.empty() && s->result_pattern[0] != '/') s->result_pattern = base_dir + "/" + s->result_pattern;
                subjects = {s};
                continue;
            }
            const ProgramSpec spec = at_line(path, line, [&] {
                ProgramSpec s = program_spec(all[1], keys, base_dir, m.timeout_seconds);
                if (keyword != "reference") check_subject_spec(s);
                return s;
            });
            if (programs == ProgramStatements::CheckOnly) {
                at_line(path, line, [&] {
                    check_program_spec(spec);
                    return 0;
                });
                if (keyword == "reference") {
                    m.references.push_back(all[1]);
                } else {
                    auto s = std::make_shared<ManifestSubject>();
                    s->name = all[1];
                    s->task = TaskCommand(spec.command, base_dir);
                    s->timeout_seconds = spec.timeout_seconds;
                    subjects = {s};
                }
                continue;
            }
            std::unique_ptr<Implementation> program = at_line(path, line, [&] { return make_program_implementation(spec); });
            if (keyword == "reference") {
                at_line(path, line, [&] {
                    register_reference(std::move(program));
                    return 0;
                });
                m.references.push_back(all[1]);
            } else {
                auto s = std::make_shared<ManifestSubject>();
                s->name = all[1];
                s->program = std::shared_ptr<const Implementation>(std::move(program));
                s->task = TaskCommand(spec.command, base_dir);
                s->timeout_seconds = spec.timeout_seconds;
                subjects = {s};
            }
            continue;
        }
        std::istringstream words(text);
        words >> std::ws;
        {
            std::string skip;
            words >> skip;  // the keyword, read above
        }
        if (keyword == "suite") {
            if (!(words >> m.name)) throw ParseError(path, line, "expected: suite NAME");
        } else if (keyword == "timeout") {
            std::string v;
            if (!(words >> v)) throw ParseError(path, line, "expected: timeout SECONDS");
            m.timeout_seconds = parse_number(path, line, "timeout", v);
            if (m.timeout_seconds <= 0) throw ParseError(path, line, "timeout must be positive");
        } else if (keyword == "max-faces") {
            std::string v;
            if (!(words >> v)) throw ParseError(path, line, "expected: max-faces N");
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), m.max_faces);
            if (ec != std::errc() || end != v.data() + v.size() || m.max_faces <= 0)
                throw ParseError(path, line, "max-faces " + v + " is not a positive integer below 2^63");
        } else if (keyword == "case") {
            const ManifestEntry entry = parse_case(path, line, words);
            const bool task = entry.operation->kind == OperationKind::Task;
            const bool invariance = entry.operation->kind == OperationKind::Invariance;
            if (!subjects.empty() && entry.operation->kind != OperationKind::Comparison && !task && !invariance)
                throw ParseError(path, line, "a subject is compared in the scheme comparisons, the invariance checks and the "
                                             "course tasks only (loop, catmull-clark, ..., invariance, tessellate, sweep, ...); "
                                             "put the " + entry.operation->name + " cases before the subject statement");
            if (invariance && std::any_of(subjects.begin(), subjects.end(), [](const auto& s) { return !s->result_pattern.empty(); }))
                throw ParseError(path, line, "the invariance operation runs the subject on inputs it writes itself: it needs a "
                                             "program (command=), not result files");
            if (task && subjects.empty())
                throw ParseError(path, line, "the " + entry.operation->name + " task puts a subject in core's place: give a "
                                             "subject or subjects statement before it");
            if (task && std::any_of(subjects.begin(), subjects.end(), [](const auto& s) { return !s->result_pattern.empty(); }))
                throw ParseError(path, line, "the " + entry.operation->name + " task runs a program (command=), not result files");
            if (subjects.empty()) m.entries.push_back(entry);
            for (const auto& s : subjects) {
                m.entries.push_back(entry);
                m.entries.back().subject = s;
            }
        } else {
            throw ParseError(path, line, "unknown statement '" + keyword + "' (known: suite, timeout, max-faces, reference, subject, subjects, case)");
        }
        if (std::string extra; keyword != "case" && (words >> extra))
            throw ParseError(path, line, "unexpected '" + extra + "'");
    }
    if (m.name.empty()) throw ParseError(path, 1, "the manifest has no 'suite NAME' line");
    for (ManifestEntry& e : m.entries) {
        e.request.timeout_seconds = m.timeout_seconds;
        e.max_faces = m.max_faces;
    }
    return m;
}

std::string default_manifest_path() { return suites_dir() + "/default.suite"; }

std::vector<SuiteJob> expand_jobs(const Manifest& manifest) {
    std::vector<SuiteJob> jobs;
    for (const ManifestEntry& e : manifest.entries) {
        const std::vector<std::string> inputs = at_line(manifest.file, e.line, [&] { return e.operation->expand(e.inputs); });
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

}  // namespace crossdiv::verification
