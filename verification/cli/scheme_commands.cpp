#include "scheme_commands.h"

#include "command.h"
#include "subject_report.h"

#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "crossdiv/subdiv/catmull_clark_streaming.h"
#include "crossdiv/io/output_file.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/verification/properties/butterfly_properties.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/refine_or_throw.h"
#include "crossdiv/verification/implementations/output_size.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/vertex_age.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/comparisons/crease_comparison.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::cli {

using namespace crossdiv::verification;

SchemeRule rule_with_tags(Scheme scheme, const PolySchemeArgs& s, PolyMesh& mesh) {
    std::vector<std::string> notes;
    const SchemeRule rule = verification::rule_with_tags(scheme, {s.boundary, s.creasing, s.nonmanifold, s.face_varying, s.triangles}, mesh, notes);
    for (const std::string& note : notes) fmt::print("note: {}\n", note);
    return rule;
}

std::optional<FaceVaryingRule> face_varying_rule_noted(Scheme scheme, const std::string& flag, const PolyMesh& mesh) {
    std::vector<std::string> notes;
    const std::optional<FaceVaryingRule> rule = verification::face_varying_rule(scheme, flag, mesh, notes);
    for (const std::string& note : notes) fmt::print("note: {}\n", note);
    return rule;
}

void print_uv_runs(const RefinementComparison& c) {
    if (!c.face_varying) return;
    fmt::print("  texture coordinates ({} rule), per face corner:\n", to_string(*c.face_varying));
    for (const RefinementRun& r : c.runs) {
        if (!r.uv) continue;
        if (!r.uv->compared()) {
            fmt::print("    {:<17} not compared: {}\n", r.reference, r.uv->not_compared);
            continue;
        }
        fmt::print("    {:<17} {:<13} {:>10}  {}{}\n", r.reference, to_string(r.uv->outcome.verdict),
                   fmt::format("{:.3g}", r.uv->comparison.max_rel),
                   r.uv->outcome.cls == DivergenceClass::None ? "" : std::string(to_string(r.uv->outcome.cls)) + ": ",
                   r.uv->explanation);
    }
}

PolyMesh write_emitted(const std::string& out, const PolyMesh& result, const std::optional<FaceVaryingRule>& fvar,
                       const std::string& impl) {
    // Hole faces were refined around; they are not emitted (OpenSubdiv's convention).
    const PolyMesh emitted = without_hole_faces(result);
    if (fvar && emitted.face_varying.empty())
        fmt::print("note: {} does not refine texture coordinates; {} has positions only\n", impl, out);
    else if (fvar && !out.ends_with(".obj"))
        fmt::print("note: texture coordinates are written to OBJ only; {} has positions only\n", out);
    write_mesh(out, emitted);
    return emitted;
}

void write_json(const std::string& path, const nlohmann::json& j) {
    const std::filesystem::path p(path);
    if (p.has_parent_path()) create_output_folder(p.parent_path().string());
    write_text_file(path, verification::json_text(j, 2) + "\n");
    fmt::print("results written to {}\n", path);
}


void color_by_age(PolyMesh& result, const std::string& scheme, const std::vector<size_t>& counts) {
    const std::vector<int> born = vertex_birth_levels(counts, scheme_from_string(scheme) == Scheme::DooSabin);
    const int levels = static_cast<int>(counts.size()) - 1;
    result.colors.resize(born.size());
    for (size_t v = 0; v < born.size(); ++v) result.colors[v] = age_color(born[v], levels);
}

std::vector<size_t> vertex_counts(const std::vector<PolyMesh>& levels) {
    std::vector<size_t> counts;
    for (const PolyMesh& m : levels) counts.push_back(m.positions.size());
    return counts;
}

int run_scheme_subdivide(const std::string& in, const PolySchemeArgs& s, const std::string& impl, const std::string& out,
                         const std::string& color, double timeout, int threads) {
    const Scheme scheme = scheme_from_string(s.scheme);
    PolyMesh mesh = load_input(in, s.unknown_tags);
    const SchemeRule rule_asked = rule_with_tags(scheme, s, mesh);
    const std::string asked = rule_name(scheme, rule_asked);
    require_refined_size(mesh, scheme, s.levels, s.max_faces, in, "--max-faces");
    const std::optional<FaceVaryingRule> fvar = face_varying_rule_noted(scheme, s.face_varying, mesh);
    PolyMesh result;
    bool threaded = false;  // by the streaming driver, on `threads`
    if (impl == "core" && scheme == Scheme::CatmullClark && threads > 1 && !fvar && color != "age") {
        // Core's streaming driver (catmull_clark_streaming.h), the same bits on any number of
        // threads; a mesh it hands to the stencil driver (tags, not a manifold) runs on one.
        result = catmull_clark_subdivide_streaming(mesh, rule_asked.catmull_clark, s.levels, threads, &threaded);
        if (!threaded) fmt::print("note: --threads {}: {} takes catmull-clark's stencil driver (tags, or not a manifold), on one thread\n", threads, in);
    } else if (impl == "core") {
        if (threads > 1)
            fmt::print("note: --threads {} is for core's Loop and Catmull-Clark without texture coordinates or --color; this run used one thread\n",
                       threads);
        const adapters::LevelTrace levels = core_implementation().refine(mesh, {scheme, rule_asked, s.levels, fvar});
        result = levels.back();
        if (color == "age") color_by_age(result, s.scheme, vertex_counts(levels));
    } else {
        if (threads > 1) fmt::print("note: --threads {} is for core; {} runs on its own threads\n", threads, impl);
        const Implementation& ref = *select_references(scheme, {impl}).front();
        const std::string rule = rule_name(scheme, ref.closest_rule(scheme, rule_asked));
        result = refine_last_or_throw(ref, mesh, {scheme, rule_asked, s.levels, fvar}, in, timeout);
        if (rule != asked) fmt::print("note: {} applies the {} boundary rule, not {}\n", impl, rule, asked);
    }
    const PolyMesh emitted = write_emitted(out, result, fvar, impl);
    const std::string tags = mesh.creases.empty() ? "" : ", " + mesh.creases.describe();
    const std::string decay =
        mesh.creases.empty() ? "" : fmt::format(", {} decay", to_string(rule_asked.catmull_clark.creasing));
    const std::string uv = fvar && !emitted.face_varying.empty() ? fmt::format(", uv {}", to_string(*fvar)) : "";
    fmt::print("{}: {} vertices, {} faces{} -> {} ({} vertices, {} faces, {} level(s){}, {} {}{} {}{})\n", in,
               mesh.num_vertices(), mesh.num_faces(), tags, out, emitted.num_vertices(), emitted.num_faces(), s.levels,
               decay, s.scheme, asked, uv, impl, threaded ? fmt::format(" on {} threads", threads) : "");
    return 0;
}

int run_scheme_compare(const std::vector<std::string>& specs, const PolySchemeArgs& s, const std::string& against,
                       const std::string& json_path, double timeout, bool no_isolate, const Implementation* subject,
                       const std::string& subject_command) {
    RefinementRequest req;
    req.subject = subject;
    req.scheme = scheme_from_string(s.scheme);
    req.rule = rule_from_boundary_name(req.scheme, s.boundary);
    req.levels = s.levels;
    req.timeout_seconds = timeout;
    req.isolate = !no_isolate;
    // compare_refinement refuses a name that lacks the scheme, naming those that have it.
    req.references = split_commas(against);

    const std::vector<std::string> inputs = expand_inputs(specs);
    if (inputs.empty()) throw InputError("no inputs (a collection folder may be absent)");
    std::vector<PolyMesh> meshes;
    std::vector<SchemeRule> rules;  // each input's, its tags resolved
    std::vector<std::optional<FaceVaryingRule>> fvars;  // each input's face-varying rule, when it has channels
    for (const std::string& in : inputs) {
        meshes.push_back(load_input(in, s.unknown_tags));
        require_refined_size(meshes.back(), req.scheme, s.levels, s.max_faces, in, "--max-faces");
        rules.push_back(rule_with_tags(req.scheme, s, meshes.back()));
        fvars.push_back(face_varying_rule_noted(req.scheme, s.face_varying, meshes.back()));
    }
    nlohmann::json results = nlohmann::json::array();
    bool all_agree = true;
    SubjectVerdict verdict(req.scheme);
    for (size_t i = 0; i < inputs.size(); ++i) {
        RefinementRequest this_req = req;
        this_req.rule = rules[i];
        this_req.face_varying = fvars[i];
        const RefinementComparison c = compare_refinement(meshes[i], inputs[i], this_req);
        for (const std::string& note : c.notes) fmt::print("\nnote: {}\n", note);
        fmt::print("\n{} ({} vertices, {} faces) {} boundary={} levels={} (core {:.3f} s)\n", c.input, c.input_vertices,
                   c.input_faces, to_string(c.scheme), c.rule_name, c.levels, c.core_seconds);
        if (!c.core_error.empty()) fmt::print("  core refused: {}\n", c.core_error);
        if (subject) {
            print_subject(c);
            verdict.add(c);
            if (!subject_command.empty() && symptom_of_subject(c))
                fmt::print("  shrink it:   crossdiv diff {} --scheme {} --levels {} --boundary {} --subject-name {} --subject '{}'\n",
                           inputs[i], s.scheme, s.levels, boundary_name(req.scheme, rules[i]), subject->name(), subject_command);
        }
        fmt::print("  {:<17} {:<21} {:<13} {:>10}  {}\n", "reference", "rule", "verdict", "max rel", "class / explanation");
        for (const RefinementRun& r : c.runs)
            fmt::print("  {:<17} {:<21} {:<13} {:>10}  {}{}\n", r.reference, r.rule, to_string(r.verdict),
                       !std::isfinite(r.comparison.max_rel) || r.correspondence.method == MatchMethod::None
                           ? "-"
                           : fmt::format("{:.3g}", r.comparison.max_rel),
                       r.divergence_class == DivergenceClass::None ? "" : std::string(to_string(r.divergence_class)) + ": ",
                       r.explanation);
        print_uv_runs(c);
        nlohmann::json record = to_json(c);
        if (req.scheme == Scheme::Butterfly || req.scheme == Scheme::ModifiedButterfly) {
            // The classic scheme has no reference: its verdict is its properties.
            const ButterflyVariant v = req.scheme == Scheme::Butterfly ? ButterflyVariant::Classic : ButterflyVariant::Modified;
            const ButterflyProperties p = check_butterfly_properties(meshes[i], inputs[i], v, s.levels);
            const bool holds = p.hold();
            if (!p.core_error.empty())
                fmt::print("  properties: not measured (core refused the input)\n");
            else
                fmt::print("  properties: old vertices move by {:.3g}, plane residual {:.3g} (<= {:.0e}), {} of {} "
                           "regular edges have the published stencil: {}\n",
                           p.max_interpolation_move, p.max_plane_residual, tolerances::kPlaneReproduction,
                           p.regular_edges_published, p.regular_edges, holds ? "hold" : "VIOLATED");
            record["properties"] = to_json(p);
            all_agree &= holds && (c.runs.empty() ? c.core_error.empty() : c.all_agree());
        } else {
            all_agree &= c.all_agree();
        }
        results.push_back(record);
    }
    if (!json_path.empty()) write_json(json_path, {{"tool", "crossdiv compare"}, {"comparisons", results}});
    if (subject) {
        fmt::print("\n{}\n", verdict.line(subject->name()));
        return verdict.failed() ? 1 : 0;
    }
    fmt::print("\n{}\n", all_agree ? "every reference agrees (and every property holds)"
                                    : "some references disagree or a property fails (see above)");
    return all_agree ? 0 : 1;
}

std::string write_shrunk(const std::string& out_dir, const PolyMesh& neighbourhood, int k, const std::string& seed,
                         const PolyMesh& minimal, int tests, const std::string& minimal_shows, const std::string& explanation) {
    create_output_folder(out_dir);
    const std::string ring = (std::filesystem::path(out_dir) / "neighbourhood.obj").string();
    const std::string minimal_file = (std::filesystem::path(out_dir) / "minimal.obj").string();
    write_mesh(ring, neighbourhood);
    write_mesh(minimal_file, minimal);
    fmt::print("neighbourhood: {} ({} faces, {})\n", ring, neighbourhood.num_faces(),
               k ? fmt::format("{}-ring of {}", k, seed) : std::string("the whole mesh"));
    fmt::print("minimal:       {} ({} faces, {} vertices) after {} comparisons: {}\n", minimal_file, minimal.num_faces(),
               minimal.num_vertices(), tests, minimal_shows);
    if (!explanation.empty()) fmt::print("               {}\n", explanation);
    return minimal_file;
}

int run_scheme_diff(const std::string& in, const PolySchemeArgs& s, const std::string& against, const std::string& out_dir,
                    double timeout, const Implementation* subject, const std::string& subject_command) {
    if (against.empty() && !subject)
        throw InputError("diff: name the diverging reference (--against) or a subject (--subject)");
    RefinementRequest req;
    req.scheme = scheme_from_string(s.scheme);
    req.levels = s.levels;
    req.timeout_seconds = timeout;
    req.subject = subject;
    if (against.empty()) req.without_references = true;
    else req.references = {against};
    PolyMesh mesh = load_input(in, s.unknown_tags);  // boundary none tags holes on it
    require_refined_size(mesh, req.scheme, s.levels, s.max_faces, in, "--max-faces");
    req.rule = rule_with_tags(req.scheme, s, mesh);
    req.face_varying = face_varying_rule_noted(req.scheme, s.face_varying, mesh);
    const ShrinkResult r = shrink_divergence(mesh, in, req);
    const std::string under_test = subject ? "subject '" + subject->name() + "'" : std::string("core");
    const std::string why = symptom_explanation(r.original);
    fmt::print("{} ({} faces): {}{}\n", in, mesh.num_faces(), describe(r.symptom, under_test, against),
               why.empty() ? "" : ": " + why);
    const std::optional<ShrinkSymptom> minimal_symptom = symptom_of(r.minimal_comparison);
    const std::string minimal =
        write_shrunk(out_dir, r.neighbourhood, r.k, "the symptom's coarse vertices", r.minimal, r.tests,
                     minimal_symptom ? describe(*minimal_symptom, under_test, against) : std::string("no symptom"),
                     symptom_explanation(r.minimal_comparison));
    if (subject) print_subject(r.minimal_comparison);
    const std::string subject_args =
        subject ? " --subject-name " + subject->name() + " --subject '" + subject_command + "'" : std::string();
    const std::string fvar = req.face_varying ? fmt::format(" --fvar {}", to_string(*req.face_varying)) : "";
    fmt::print("reproduce:     crossdiv compare {} --scheme {} --boundary {} --levels {}{}{}{}\n", minimal, s.scheme,
               boundary_name(req.scheme, req.rule), r.levels, fvar, against.empty() ? "" : " --against " + against,
               subject_args);
    return 0;
}

namespace {

/// What `crossdiv limit` asks for: the scheme, its weights (Loop) and boundary rule, the levels.
RefineRequest limit_request(const LimitArgs& a) {
    const Scheme scheme = scheme_from_string(a.scheme);
    RefineRequest r{scheme, rule_from_boundary_name(scheme, a.boundary), a.levels};
    if (scheme == Scheme::Loop) r.rule.loop.weights = loop_weights_from_string(a.weights);
    return r;
}

/// "3..20" or "7".
std::pair<int, int> valence_range(const std::string& s) {
    const size_t dots = s.find("..");
    try {
        const int a = std::stoi(s.substr(0, dots)), b = dots == std::string::npos ? a : std::stoi(s.substr(dots + 2));
        if (a < 3 || b < a || b > 64) throw InputError("");
        return {a, b};
    } catch (const std::exception&) {
        throw InputError("--valences wants N or A..B with 3 <= A <= B <= 64, got '" + s + "'");
    }
}

}  // namespace

int run_limit(const LimitArgs& a) {
    const PolyMesh mesh = load_input(a.input);
    if (a.levels < 0 || a.levels > 8) throw InputError("--levels must be in 0..8");
    require_refined_size(mesh, Scheme::CatmullClark, a.levels, kMaxRefinedFaces, a.input,
                         "the limit command's fixed bound");  // Loop grows as fast
    if (!mesh.creases.empty())
        throw InputError(a.input + " has crease or corner tags; limit positions under creases are not implemented "
                         "(the limit masks here are the smooth and boundary ones); use subdivide");
    RefineRequest request = limit_request(a);
    request.face_varying = face_varying_rule_noted(request.scheme, a.face_varying, mesh);
    const adapters::LimitPoints limit = core_implementation().limit_points(mesh, request);
    PolyMesh level = limit.level;
    const double diagonal = bounding_box_diagonal(level.positions);
    double moved = 0;
    for (int v = 0; v < level.num_vertices(); ++v)
        moved = std::max(moved, (limit.position[v] - level.positions[v]).norm() / diagonal);
    fmt::print("{}: level {} has {} vertices; the largest move to the limit is {:.3g} of the diagonal\n", a.input,
               a.levels, level.num_vertices(), moved);
    nlohmann::json j{{"tool", "crossdiv limit"}, {"input", a.input}, {"scheme", a.scheme}, {"levels", a.levels},
                     {"max_move_rel", moved}};
    if (limit.uv) {
        // How far the texture coordinates move to their limits, relative to the UV box.
        const FaceVaryingChannel& refined = level.face_varying.front();
        const double box = verification::uv_box_diagonal(refined);
        double uv_moved = 0;
        for (size_t i = 0; i < refined.values.size(); ++i)
            uv_moved = std::max(uv_moved, std::abs(limit.uv->values[i] - refined.values[i]));
        uv_moved = box > 0 ? uv_moved / box : uv_moved;
        fmt::print("texture coordinates ({} rule): {} values; the largest move to the limit is {:.3g} of the UV box\n",
                   to_string(*request.face_varying), refined.num_values(), uv_moved);
        j["face_varying"] = to_string(*request.face_varying);
        j["uv_max_move_rel"] = uv_moved;
    }
    if (!a.out.empty()) {
        level.positions = limit.position;
        if (limit.uv) level.face_varying = {*limit.uv};
        write_mesh(a.out, level);
        fmt::print("limit mesh written to {}\n", a.out);
    }
    bool ok = true;
    if (!a.against.empty()) {
        if (a.against != "opensubdiv") throw InputError("limit: only opensubdiv has limit positions, not '" + a.against + "'");
        const LimitComparison c = compare_limit(mesh, a.input, request);
        fmt::print("against opensubdiv: {} ({})\n", to_string(c.verdict), c.explanation);
        ok = c.verdict == Verdict::Agree;
        j["comparison"] = to_json(c);
    }
    if (!a.json.empty()) write_json(a.json, j);
    return ok ? 0 : 1;
}

int run_spectrum(const SpectrumArgs& a) {
    const auto [lo, hi] = valence_range(a.valence);
    std::vector<std::string> schemes;
    if (a.scheme == "all") schemes = {"loop", "warren", "catmull-clark"};
    else schemes = {a.scheme};
    nlohmann::json spectra = nlohmann::json::array(), conv = nlohmann::json::array();
    bool ok = true;
    fmt::print("{:<14} {:>3} {:>10} {:>5} {:>10} {:>10} {:>10} {:>9}  {}\n", "scheme", "n", "lambda_1", "mult",
               "next", "vertex", "|core-cf|", "imag", "regular characteristic map");
    for (const std::string& s : schemes)
        for (int n = lo; n <= hi; ++n) {
            const SpectrumRow r = local_spectrum(s, n);
            ok &= r.max_difference <= tolerances::kSpectrumAgreement;
            fmt::print("{:<14} {:>3} {:>10.6f} {:>5} {:>10.6f} {:>10.6f} {:>10.2e} {:>9.1e}  {}\n", s, n, r.subdominant,
                       r.subdominant_multiplicity, r.next, r.vertex_rate, r.max_difference, r.max_imaginary,
                       r.regular_characteristic_map ? "yes" : "NO");
            spectra.push_back(to_json(r));
        }
    fmt::print("\nconvergence of the centre of a fan to its limit (distance / diagonal at levels 1, {}):\n", a.levels);
    fmt::print("{:<14} {:>3} {:>10} {:>10} {:>10} {:>10} {:>10}\n", "scheme", "n", "d_1", "d_last", "fitted", "vertex",
               "lambda_1");
    for (const std::string& s : schemes)
        for (int n = lo; n <= std::min(hi, 12); ++n) {
            const ConvergenceRow r = convergence(s, n, a.levels);
            fmt::print("{:<14} {:>3} {:>10.3e} {:>10.3e} {:>10.6f} {:>10.6f} {:>10.6f}\n", s, n, r.distance.front(),
                       r.distance.back(), r.fitted_rate, r.vertex_rate, r.subdominant);
            conv.push_back(to_json(r));
        }
    if (!a.json.empty())
        write_json(a.json, {{"tool", "crossdiv spectrum"}, {"spectra", spectra}, {"convergence", conv}});
    return ok ? 0 : 1;
}

void LimitArgs::add_to(CLI::App& app) {
    app.add_option("input", input, "Mesh file or bundled:NAME")->required();
    app.add_option("--scheme", scheme, "loop or catmull-clark")->check(CLI::IsMember({"loop", "catmull-clark"}))->capture_default_str();
    app.add_option("--weights", weights, "Loop weight family: loop or warren")->capture_default_str();
    app.add_option("--boundary", boundary, "edge-only or edge-and-corner")->capture_default_str();
    app.add_option("--levels", levels, "Level whose vertices are moved (0: the input)")->check(CLI::Range(0, 12))->capture_default_str();
    app.add_option("--against", against, "opensubdiv: compare with PrimvarRefiner::Limit");
    app.add_option("--json", json, "Write the results as JSON");
    app.add_option("-o,--output", out,
                   "Write the level with every vertex at its limit position (and, with texture coordinates, each "
                   "value at its limit, as OBJ vt)");
    std::vector<std::string> fvar_rules;
    for (FaceVaryingRule r : kFaceVaryingRules) fvar_rules.emplace_back(to_string(r));
    app.add_option("--fvar", face_varying,
                   "The rule the input's texture coordinates are refined by before their limit values are taken "
                   "(none, corners-only, corners-plus1, corners-plus2, boundaries, all). Default: the file's "
                   "'t facevaryinginterpolateboundary' tag, else all")
        ->check(CLI::IsMember(fvar_rules));
}

void SpectrumArgs::add_to(CLI::App& app) {
    app.add_option("--scheme", scheme, "loop, warren, catmull-clark or all")
        ->check(CLI::IsMember({"loop", "warren", "catmull-clark", "all"}))
        ->capture_default_str();
    app.add_option("--valences", valence, "The valences of the eigen table: N or A..B (3..64)")->capture_default_str();
    app.add_option("--levels", levels, "Levels of the convergence table")->check(CLI::Range(2, 8))->capture_default_str();
    app.add_option("--json", json, "Write both tables as JSON");
}

void add_scheme_commands(CLI::App& app, int& status) {
    add_command<LimitArgs>(app, "limit", "Limit positions of a level's vertices (Loop, Catmull-Clark), against OpenSubdiv",
                           status, run_limit);
    add_command<SpectrumArgs>(app, "spectrum", "Eigen table of the local subdivision matrices and the convergence table",
                              status, run_spectrum);
}

}  // namespace crossdiv::cli
