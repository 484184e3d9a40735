// The mesh subcommands of the crossdiv CLI: subdivide, compare, check, datasets, edgecases, diff.
#include "mesh_commands.h"

#include <fmt/format.h>

#include <fmt/ranges.h>

#include <filesystem>
#include <map>
#include <set>

#include "command.h"
#include "invariance_command.h"
#include "crossdiv/io/output_file.h"
#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "crossdiv/subdiv/loop_split_flip.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/refine_or_throw.h"
#include "crossdiv/verification/implementations/output_size.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "crossdiv/verification/comparisons/input_transformation.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/suite/manifest.h"
#include "edit_commands.h"
#include "subject_report.h"
#include "scheme_commands.h"

namespace crossdiv::cli {
namespace {

using namespace crossdiv::verification;

struct SchemeArgs {
    std::string scheme = "loop";
    std::string weights = "loop";
    std::string boundary;  ///< empty: the scheme's default (edge-only, chaikin-boundary, count-from-input)
    int levels = 1;
    std::string creasing;  ///< empty: the input's t creasemethod tag, else uniform
    long long max_faces = kMaxRefinedFaces;
    bool ignore_unknown_tags = false;
    std::string nonmanifold = "opensubdiv";
    std::string face_varying;  ///< empty: the file's facevaryinginterpolateboundary tag, else all
    std::string triangles;     ///< empty: the file's smoothtriangles tag, else catmark

    /// The scheme options; `max_faces_default` is the command's --max-faces default
    /// (implementations/output_size.h: one implementation alone, or several side by side).
    void add_scheme_options(CLI::App& app, long long max_faces_default) {
        std::vector<std::string> schemes;
        for (Scheme s : all_schemes()) schemes.push_back(to_string(s));
        app.add_option("--scheme", scheme, "Subdivision scheme (bilinear: OpenSubdiv's, the 'simple' subdivision of modellers; midpoint: "
                       "triangles into four at their edge midpoints, VTK's and Open3D's linear subdivision)")
            ->check(CLI::IsMember(schemes))
            ->capture_default_str();
        app.add_option("--weights", weights,
                       "Weight family: loop (Loop 1987), warren (3/(8n)), or the Barthe-Kobbelt tunings "
                       "regularity and continuity (MeshLab's)")
            ->check(CLI::IsMember({"loop", "warren", "regularity", "continuity"}))
            ->capture_default_str();
        app.add_option("--boundary", boundary,
                       "Boundary rule. loop: edge-only (default) or edge-and-corner; catmull-clark: those and "
                       "midpoint-average (OpenMesh's); doo-sabin: chaikin-boundary (default) or drop-border-faces "
                       "(CGAL's); sqrt3, when the boundary is refined: count-from-input (default) or "
                       "restart-each-level (a library called once per level); the Butterflies, for a wing point "
                       "beyond the boundary: reflected-wings (default), opposite-vertex-wings (MeshLab's) or other-face-wings "
                       "(VTK's, with its other boundary choices); bilinear and midpoint: linear "
                       "(their one rule); loop and "
                       "catmull-clark also none (OpenSubdiv's VTX_BOUNDARY_NONE: edge-only, the faces at the boundary "
                       "not emitted). Default: the file's 't interpolateboundary' tag, else the scheme's default")
            ->check(CLI::IsMember({"edge-only", "edge-and-corner", "midpoint-average", "chaikin-boundary",
                                   "drop-border-faces", "count-from-input", "restart-each-level", "reflected-wings",
                                   "opposite-vertex-wings", "other-face-wings", "linear", "none"}));
        app.add_option("--levels", levels, "Number of subdivision levels")->check(CLI::Range(0, 12))->capture_default_str();
        app.add_option("--crease-method", creasing,
                       "Decay of semi-sharp crease tags (loop, catmull-clark): uniform (OpenSubdiv's default) or "
                       "chaikin. Default: the input's 't creasemethod' tag, else uniform")
            ->check(CLI::IsMember({"uniform", "chaikin"}));
        app.add_option("--nonmanifold", nonmanifold,
                       "Loop and Catmull-Clark on a mesh that is not a manifold (an edge of 3+ faces, a bowtie "
                       "vertex, two faces traversing an edge the same way): opensubdiv refines it by OpenSubdiv's "
                       "rules, refuse refuses it")
            ->check(CLI::IsMember({"opensubdiv", "refuse"}))
            ->capture_default_str();
        std::vector<std::string> fvar_rules;
        for (FaceVaryingRule r : kFaceVaryingRules) fvar_rules.emplace_back(to_string(r));
        app.add_option("--fvar", face_varying,
                       "How texture coordinates (face-varying data: OBJ vt) are refined, OpenSubdiv's "
                       "FVarLinearInterpolation (loop, catmull-clark, bilinear): none (smooth everywhere), "
                       "corners-only, corners-plus1, corners-plus2, boundaries, all (linear everywhere). Default: the "
                       "file's 't facevaryinginterpolateboundary' tag, else all (OpenSubdiv's default)")
            ->check(CLI::IsMember(fvar_rules));
        app.add_option("--triangles", triangles,
                       "Catmull-Clark's edge weights where an edge has a triangle on a side: catmark (the scheme's "
                       "own, OpenSubdiv's TRI_SUB_CATMARK) or smooth (TRI_SUB_SMOOTH, the weights that keep a "
                       "triangle's surface rounder). Default: the file's 't smoothtriangles' tag, else catmark")
            ->check(CLI::IsMember({"catmark", "smooth"}));
        app.add_flag("--ignore-unknown-tags", ignore_unknown_tags,
                     "Refine a shape file whose tags include one crossdiv does not know, without it (each is noted)");
        max_faces = max_faces_default;
        app.add_option("--max-faces", max_faces,
                       "Refuse, before any work, a refinement whose final level would have more faces than this")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
    }
    PolySchemeArgs poly() const {
        return {scheme,    boundary,     levels, creasing, max_faces, tag_policy(), nonmanifold_rule_from_string(nonmanifold),
                face_varying, triangles};
    }
    UnknownTags tag_policy() const { return ignore_unknown_tags ? UnknownTags::Ignore : UnknownTags::Refuse; }
    /// @throws InputError when `levels` of this scheme on `mesh` pass --max-faces.
    void require_size(const PolyMesh& mesh, const std::string& name) const {
        require_refined_size(mesh, scheme_from_string(scheme), levels, max_faces, name, "--max-faces");
    }
    /// The Loop rule named by --weights and --boundary. @throws InputError for a rule Loop lacks.
    LoopOptions options() const {
        LoopOptions o = rule_from_boundary_name(Scheme::Loop, boundary).loop;
        o.weights = loop_weights_from_string(weights);
        o.nonmanifold = nonmanifold_rule_from_string(nonmanifold);
        return o;
    }
};

/// `o` with the semi-sharp crease rules `impl` applies when it has only its own (Hbr's): on an
/// untagged mesh they decide nothing, and on a tagged one they are what it refines by, so the
/// request names them rather than refusing the implementation.
LoopOptions with_own_crease_rules(const Implementation& impl, LoopOptions o) {
    RefineRequest request{Scheme::Loop, {}, 1};
    request.rule.loop = o;
    o.crease_rules = impl.closest_rule(Scheme::Loop, request.rule).loop.crease_rules;
    return o;
}

/// Loop on a crease-tagged input: core's generic step, or a reference with crease rules
/// (OpenSubdiv, Hbr under its own); the others (and split-and-flip) have none and refuse.
int run_loop_subdivide_creased(const std::string& in, const PolyMesh& input, const SchemeArgs& s,
                               const std::string& impl, const std::string& out, const std::string& color, double timeout) {
    LoopOptions o = s.options();
    o.creasing = crease_method(s.creasing, input);
    s.require_size(input, in);
    PolyMesh result;
    const Implementation& chosen = find_implementation(impl == "split-flip" ? "core" : impl);
    o = with_own_crease_rules(chosen, o);
    RefineRequest request{Scheme::Loop, {}, s.levels};
    request.rule.loop = o;
    const SchemeSupport* support = chosen.support(Scheme::Loop);
    if (impl != "split-flip" && support && support->creases) {
        if (!chosen.applies(Scheme::Loop, request.rule))
            throw InputError(impl + " has no Loop with weights=" + std::string(to_string(o.weights)));
        const adapters::LevelTrace levels = refine_or_throw(chosen, input, request, in, timeout);
        result = levels.back();
        if (color == "age") color_by_age(result, s.scheme, vertex_counts(levels));
    } else {
        throw InputError(in + " has " + input.creases.describe() + "; " + impl +
                         " has no crease or hole rules (core and opensubdiv have; drop the tags to compare the smooth "
                         "scheme)");
    }
    // Hole faces were refined around; they are not emitted (OpenSubdiv's convention).
    const PolyMesh emitted = without_hole_faces(result);
    write_mesh(out, emitted);
    fmt::print("{}: {} vertices, {} faces, {} -> {} ({} vertices, {} faces, {} level(s), {} decay, {})\n", in,
               input.num_vertices(), input.num_faces(), input.creases.describe(), out, emitted.num_vertices(),
               emitted.num_faces(), s.levels, to_string(o.creasing),
               impl + (o.crease_rules == CreaseRules::Hbr ? " under its own crease rules (creases=hbr)" : ""));
    return 0;
}

/// Loop on an input with texture coordinates: core's face-varying refinement
/// (face_varying_refinement.h), or a reference's; the tags are honoured as for
/// run_loop_subdivide_creased.
int run_loop_subdivide_face_varying(const std::string& in, const PolyMesh& input, const SchemeArgs& s,
                                    FaceVaryingRule fvar, const std::string& impl, const std::string& out, double timeout) {
    if (impl == "split-flip") throw InputError("split-flip does not refine texture coordinates; use --impl core");
    LoopOptions o = s.options();
    o.creasing = crease_method(s.creasing, input);
    s.require_size(input, in);
    const Implementation& chosen = find_implementation(impl);
    RefineRequest request{Scheme::Loop, {}, s.levels, fvar};
    request.rule.loop = with_own_crease_rules(chosen, o);
    if (!chosen.applies(Scheme::Loop, request.rule))
        throw InputError(impl + " has no Loop with weights=" + std::string(to_string(o.weights)) +
                         " boundary=" + std::string(to_string(o.boundary)));
    const PolyMesh result = impl == "core" ? chosen.refine(input, request).back()
                                           : refine_last_or_throw(chosen, input, request, in, timeout);
    const PolyMesh emitted = write_emitted(out, result, fvar, impl);
    fmt::print("{}: {} vertices, {} faces -> {} ({} vertices, {} faces, {} level(s), uv {}, {})\n", in,
               input.num_vertices(), input.num_faces(), out, emitted.num_vertices(), emitted.num_faces(), s.levels,
               to_string(fvar), impl);
    return 0;
}

/// `flags` with the boundary rule `input`'s tags ask for (tag_rules.h), the notes printed.
SchemeArgs with_tag_rules(const SchemeArgs& flags, PolyMesh& input) {
    if (!flags.triangles.empty())
        throw InputError("--triangles (catmark or smooth: OpenSubdiv's TRI_SUB_CATMARK or TRI_SUB_SMOOTH) is "
                         "Catmull-Clark's; loop has no triangle rule");
    SchemeArgs s = flags;
    const TagRules tags = resolve_tag_rules(Scheme::Loop, flags.boundary, input);
    for (const std::string& note : tags.notes) fmt::print("note: {}\n", note);
    s.boundary = tags.boundary;
    return s;
}

/// The note a run with more than one thread prints when it takes a driver that runs on one.
void note_one_thread(int threads, const std::string& why) {
    if (threads > 1)
        fmt::print("note: --threads {} is for core's Loop and Catmull-Clark on a manifold mesh; {}: this run used one thread\n",
                   threads, why);
}

int run_subdivide(const std::string& in, const SchemeArgs& flags, const std::string& impl, const std::string& out,
                  const std::string& color, double timeout, int threads) {
    if (flags.scheme != "loop") {
        if (impl == "split-flip") throw InputError("split-flip is Loop's method; " + flags.scheme + " has none");
        if (flags.scheme != "catmull-clark") note_one_thread(threads, "this is " + flags.scheme);
        return run_scheme_subdivide(in, flags.poly(), impl, out, color, timeout, threads);
    }
    if (impl != "core") note_one_thread(threads, "this is " + impl);
    PolyMesh input = load_input(in, flags.tag_policy());
    const SchemeArgs s = with_tag_rules(flags, input);
    if (const std::optional<FaceVaryingRule> fvar = face_varying_rule_noted(Scheme::Loop, s.face_varying, input)) {
        if (impl == "core") note_one_thread(threads, "texture coordinates are refined on one");
        return run_loop_subdivide_face_varying(in, input, s, *fvar, impl, out, timeout);
    }
    if (!input.creases.empty()) {
        if (impl == "core") note_one_thread(threads, "crease and hole tags are refined on one");
        return run_loop_subdivide_creased(in, input, s, impl, out, color, timeout);
    }
    s.require_size(input, in);
    const TriMesh mesh = to_tri_mesh(input, "Loop subdivision");
    PolyMesh result;
    bool threaded = false;  // by the streaming driver, on `threads`
    if (impl == "core") {
        // The streaming driver on a manifold (loop_streaming.h); a mesh that is not one takes
        // the polygon-mesh driver and OpenSubdiv's non-manifold rules (or the refusal that
        // --nonmanifold refuse asks for).
        try {
            result = to_poly_mesh(loop_subdivide_streaming(mesh, s.options(), s.levels, threads));
            threaded = threads > 1;
        } catch (const NonManifoldInput&) {
            note_one_thread(threads, "this mesh is not one");
            result = loop_subdivide(input, s.options(), s.levels);
        }
    } else if (impl == "split-flip") {
        TriMesh level = mesh;
        for (int l = 0; l < s.levels; ++l) level = loop_by_split_and_flip(level, s.options());
        result = to_poly_mesh(level);
    } else {
        const Implementation& ref = *select_references(Scheme::Loop, {impl}).front();
        RefineRequest request{Scheme::Loop, {}, s.levels};
        request.rule.loop = with_own_crease_rules(ref, s.options());
        if (!ref.applies(Scheme::Loop, request.rule))
            throw InputError(impl + " has no Loop with weights=" + s.weights + " boundary=" + std::string(to_string(s.options().boundary)));
        result = refine_last_or_throw(ref, input, request, in, timeout);
    }
    if (color == "age") {
        // The fast Loop driver returns the last level only: the earlier levels' vertex counts
        // come from running it again to each (at most a third of the work again).
        std::vector<size_t> counts;
        for (int l = 0; l < s.levels; ++l) counts.push_back(loop_subdivide(input, s.options(), l).positions.size());
        counts.push_back(result.positions.size());
        color_by_age(result, s.scheme, counts);
    }
    write_mesh(out, result);
    fmt::print("{}: {} vertices, {} faces -> {} ({} vertices, {} faces, {} level(s), {}{})\n", in, mesh.num_vertices(),
               mesh.num_faces(), out, result.num_vertices(), result.num_faces(), s.levels, impl,
               threaded ? fmt::format(" on {} threads", threads) : "");
    return 0;
}

void print_table(const RefinementComparison& c) {
    fmt::print("\n{} ({} vertices, {} faces) loop weights={} boundary={} levels={} (core {:.3f} s)\n", c.input,
               c.input_vertices, c.input_faces, to_string(c.rule.loop.weights), to_string(c.rule.loop.boundary), c.levels,
               c.core_seconds);
    if (!c.core_error.empty()) fmt::print("  core refuses the input: {}\n", c.core_error);
    if (c.subject != "core") print_subject(c);
    fmt::print("  {:<11} {:<9} {:<13} {:<9} {:<8} {:>10} {:>10}  {}\n", "reference", "status", "verdict", "match",
               "topology", "max rel", "rms rel", "class / explanation");
    for (const RefinementRun& r : c.runs) {
        // Measured columns only where both refined: not when core refused the input.
        const bool ok = r.outcome.status == RunStatus::Ok && r.verdict != Verdict::OursRejected;
        fmt::print("  {:<11} {:<9} {:<13} {:<9} {:<8} {:>10} {:>10}  {}{}\n", r.reference,
                   to_string(r.outcome.status), to_string(r.verdict),
                   ok ? to_string(r.correspondence.method) : "-",
                   ok ? (r.comparison.topology_equal() ? "equal" : "differs") : "-",
                   ok ? fmt::format("{:.3g}", r.comparison.max_rel) : "-",
                   ok ? fmt::format("{:.3g}", r.comparison.rms_rel) : "-",
                   r.divergence_class == DivergenceClass::None ? "" : std::string(to_string(r.divergence_class)) + ": ",
                   r.explanation);
        if (ok && r.verdict == Verdict::Diverge)
            for (const WorstVertex& w : r.comparison.worst)
                fmt::print("      vertex {:>6} valence {:>2} {:<8} dist {:.3g}  {} ({:.6g}, {:.6g}, {:.6g})  "
                           "{} ({:.6g}, {:.6g}, {:.6g})\n",
                           w.ours_index, w.valence, w.boundary ? "boundary" : "interior", w.distance, c.subject, w.ours.x(),
                           w.ours.y(), w.ours.z(), r.reference, w.ref.x(), w.ref.y(), w.ref.z());
    }
}

/// `subject_command`: the subject's command template, for the `crossdiv diff` line that shrinks
/// what no named rule explains (empty for result files, which cannot be rerun).
int run_compare(const std::vector<std::string>& specs, const SchemeArgs& s, const std::string& against,
                const std::string& json_path, double timeout, bool no_isolate, const Implementation* subject,
                const std::string& subject_command) {
    if (s.scheme != "loop") return run_scheme_compare(specs, s.poly(), against, json_path, timeout, no_isolate, subject, subject_command);
    RefinementRequest req;
    req.subject = subject;
    req.rule.loop = s.options();
    req.levels = s.levels;
    req.timeout_seconds = timeout;
    req.isolate = !no_isolate;
    req.references = split_commas(against);
    select_references(Scheme::Loop, req.references);  // fail early on a typo

    const std::vector<std::string> inputs = expand_inputs(specs);
    if (inputs.empty()) throw InputError("no inputs (a collection folder may be absent)");
    // Load every input before running anything: a file that cannot be read, or is not a
    // triangle mesh, is bad input (exit 2). A triangle mesh whose topology core refuses
    // (non-manifold, degenerate) is a recorded outcome, as in the suite: the references still
    // run on it and the batch goes on. A crease-tagged input is compared with the references
    // that have crease rules (OpenSubdiv), under the tags' creasing method.
    std::vector<PolyMesh> meshes;
    std::vector<std::string> refused(inputs.size());
    std::vector<LoopOptions> rules;  // each input's, its tags resolved
    std::vector<std::optional<FaceVaryingRule>> fvars;  // each input's face-varying rule, when it has channels
    for (size_t i = 0; i < inputs.size(); ++i) {
        PolyMesh m = load_input(inputs[i], s.tag_policy());
        s.require_size(m, inputs[i]);
        LoopOptions rule = with_tag_rules(s, m).options();
        rule.creasing = crease_method(s.creasing, m);
        if (!m.creases.empty() && rule.weights != LoopWeights::Loop)
            throw InputError(inputs[i] + ": crease and hole tags are compared with Loop's weights (OpenSubdiv's)");
        PolyMesh faces_only = m;  // a polygon is refused by name, tagged or not
        faces_only.creases = {};
        const TriMesh triangles = to_tri_mesh(faces_only, "Loop subdivision");
        if (m.creases.empty()) try {
                check_loop_input(triangles, rule);
            } catch (const InputError& e) {
                refused[i] = e.what();
            }
        fvars.push_back(face_varying_rule_noted(Scheme::Loop, s.face_varying, m));
        meshes.push_back(std::move(m));
        rules.push_back(rule);
    }
    nlohmann::json results = nlohmann::json::array();
    bool all_agree = true;
    SubjectVerdict verdict(Scheme::Loop);
    for (size_t i = 0; i < inputs.size(); ++i) {
        if (subject && !meshes[i].creases.empty()) {
            fmt::print("\n{}: {}; a subject is compared on untagged meshes so far (skipped)\n", inputs[i],
                       meshes[i].creases.describe());
            continue;
        }
        if (subject && !refused[i].empty()) {
            fmt::print("\n{}: core refuses it ({}); a subject is measured where core refines (skipped)\n", inputs[i],
                       refused[i]);
            continue;
        }
        RefinementRequest this_req = req;
        this_req.rule.loop = rules[i];
        this_req.face_varying = fvars[i];
        const RefinementComparison c = compare_refinement(meshes[i], inputs[i], this_req);
        for (const std::string& note : c.notes) fmt::print("\nnote: {}\n", note);
        print_table(c);
        print_uv_runs(c);
        if (!meshes[i].creases.empty())
            fmt::print("  tags: {}, {} decay\n", meshes[i].creases.describe(), to_string(rules[i].creasing));
        if (!subject_command.empty() && symptom_of_subject(c))
            fmt::print("  shrink it:   crossdiv diff {} --levels {} --weights {} --boundary {} --subject-name {} --subject '{}'\n",
                       inputs[i], s.levels, s.weights, to_string(this_req.rule.loop.boundary), subject->name(), subject_command);
        all_agree &= c.all_agree();
        if (subject) verdict.add(c);
        results.push_back(to_json(c));
    }
    if (!json_path.empty()) write_json(json_path, {{"tool", "crossdiv compare"}, {"comparisons", results}});
    if (subject) {
        // A subject fails when it fails to run or diverges unexplained; a named rule it follows
        // that a reference lacks is a diagnosis, not a failure.
        fmt::print("\n{}\n", verdict.line(subject->name()));
        return verdict.failed() ? 1 : 0;
    }
    fmt::print("\n{}\n", all_agree ? "every reference agrees" : "some references disagree (see above)");
    return all_agree ? 0 : 1;
}

int run_check(const std::string& in) {
    // Every problem is listed, an unknown tag among them (as a note), rather than stopping at it.
    const PolyMesh mesh = load_input(in, UnknownTags::Ignore);
    const auto issues = check_mesh(mesh);
    int errors = 0;
    for (const std::string& note : mesh.source.notes) fmt::print("note: {}\n", note);
    for (const MeshIssue& i : issues) {
        errors += i.severity == Severity::Error;
        fmt::print("{} [{}] {}\n", i.severity == Severity::Error ? "error" : "warning", to_string(i.kind), i.message);
    }
    if (errors == 0) errors += print_halfedge_report(mesh);
    fmt::print("{}: {} vertices, {} faces, {} error(s), {} warning(s)\n", in, mesh.num_vertices(), mesh.num_faces(),
               errors, issues.size() - errors);
    return errors ? 2 : 0;
}

int run_datasets(const std::string& dir) {
    create_output_folder(dir);
    for (const auto& b : datasets::bundled_meshes()) {
        const std::string path = (std::filesystem::path(dir) / (b.name + ".obj")).string();
        write_mesh(path, b.mesh);
        fmt::print("{:<48} {}\n", path, b.description);
    }
    return 0;
}

int run_edgecases(const std::string& dir) {
    create_output_folder(dir);
    for (const bool polygons : {false, true})
        for (const auto& c : polygons ? datasets::polygon_edge_cases() : datasets::edge_cases()) {
            const std::string path = (std::filesystem::path(dir) / (c.name + ".obj")).string();
            write_mesh(path, c.mesh);
            fmt::print("{:<48} {}{}{}\n", path, c.description, c.valid_loop_input ? "" : " [not a manifold]",
                       polygons ? " [polygons: Catmull-Clark]" : "");
        }
    return 0;
}

int run_diff(const std::string& in, const SchemeArgs& flags, const std::string& against, const std::string& out_dir,
             const Implementation* subject, double timeout, const std::string& subject_command) {
    if (flags.scheme != "loop") return run_scheme_diff(in, flags.poly(), against, out_dir, timeout, subject, subject_command);
    PolyMesh input = load_input(in, flags.tag_policy());
    const SchemeArgs s = with_tag_rules(flags, input);
    s.require_size(input, in);
    const TriMesh mesh = to_tri_mesh(input, "Loop subdivision");
    check_loop_input(mesh, s.options());
    RefinementRequest req;
    req.rule.loop = s.options();
    req.levels = s.levels;
    req.subject = subject;
    req.timeout_seconds = timeout;
    req.face_varying = face_varying_rule_noted(Scheme::Loop, s.face_varying, input);
    if (against.empty()) {
        if (!subject) throw InputError("diff: name the diverging reference (--against) or a subject (--subject)");
        req.without_references = true;
    } else {
        req.references = {against};
        select_references(Scheme::Loop, {against});
    }
    const ShrinkResult r = shrink_divergence(input, in, req);
    const std::string under_test = subject ? "subject '" + subject->name() + "'" : std::string("core");
    if (r.symptom.kind == ShrinkSymptom::Kind::SubjectFails)
        fmt::print("{} ({} faces): {} failed: {}\n", in, mesh.num_faces(), under_test, r.original.subject_outcome.summary());
    else
        fmt::print("{} ({} faces): {}{}\n", in, mesh.num_faces(), describe(r.symptom, under_test, against),
                   r.original.runs.empty() ? "" : ": " + symptom_explanation(r.original));
    const std::optional<ShrinkSymptom> minimal_symptom = symptom_of(r.minimal_comparison);
    const std::string minimal =
        write_shrunk(out_dir, r.neighbourhood, r.k, "the worst vertex's coarse ancestors", r.minimal,
                     r.tests, minimal_symptom ? describe(*minimal_symptom, under_test, against) : std::string("no symptom"),
                     symptom_explanation(r.minimal_comparison));
    if (r.minimal_comparison.subject != "core") print_subject(r.minimal_comparison);
    const std::string subject_args =
        subject ? fmt::format(" --subject-name {} --subject '{}'", subject->name(), subject_command) : std::string();
    const std::string fvar = req.face_varying ? fmt::format(" --fvar {}", to_string(*req.face_varying)) : "";
    fmt::print("reproduce:     crossdiv compare {} --weights {} --boundary {} --levels {}{}{}{}\n", minimal, s.weights,
               to_string(s.options().boundary), r.levels, fvar, against.empty() ? "" : " --against " + against,
               subject_args);
    return 0;
}

struct SubdivideArgs {
    std::string input, impl = "core", out, color = "none";
    double timeout = 120;
    int threads = 1;
    SchemeArgs scheme;
    void add_to(CLI::App& app) {
        app.add_option("input", input, "Mesh file (.obj, .off) or bundled:NAME")->required();
        scheme.add_scheme_options(app, kMaxRefinedFaces);
        // Any implementation of the registry (the references built in and the programs found),
        // checked when the option is read, so that the list cannot fall behind the registry.
        app.add_option("--impl", impl,
                       "Implementation: core, split-flip (our Loop by edge splits and flips), or any reference "
                       "built in (crossdiv --version lists them)")
            ->check(CLI::Validator(
                [](std::string& name) {
                    if (name == "split-flip") return std::string();
                    try {
                        find_implementation(name);
                    } catch (const InputError& e) {
                        return std::string(e.what());
                    }
                    return std::string();
                },
                "IMPL"))
            ->capture_default_str();
        app.add_option("-o,--output", out, "Output mesh (.obj, .off)")->required();
        app.add_option("--color", color,
                       "age: colour each vertex by the level it was born at (viridis, the input's dark blue, the "
                       "newest yellow; OBJ 'v x y z r g b'), core and split-flip only")
            ->check(CLI::IsMember({"none", "age"}))
            ->capture_default_str();
        app.add_option("--timeout", timeout,
                       "Seconds a reference library may run (in a child process, so that its crash or hang is "
                       "an error naming it) before it counts as hung")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
        app.add_option("--threads", threads,
                       "Threads for core's Loop and Catmull-Clark on a manifold mesh without tags or texture "
                       "coordinates (the same result, bit for bit, on any number); other runs use one")
            ->check(CLI::Range(1, 256))
            ->capture_default_str();
    }
};
int subdivide_command(const SubdivideArgs& a) {
    if (a.color == "age" && a.impl != "core" && a.impl != "split-flip")
        throw InputError("--color age needs --impl core: the age is read off core's numbering (old vertices first); " +
                         a.impl + " numbers its vertices its own way");
    if (a.color == "age" && !a.out.ends_with(".obj"))
        throw InputError("--color age writes vertex colours as OBJ 'v x y z r g b'; " + a.out + " is not an .obj file");
    return run_subdivide(a.input, a.scheme, a.impl, a.out, a.color, a.timeout, a.threads);
}

/// The programs of a run: a subject in core's place and references added to the registry.
struct ProgramArgs {
    double timeout = 120;
    std::string subject, subject_name = "subject", subject_levels = "each";
    std::vector<std::string> references;
    void add_to(CLI::App& app) {
        app.add_option("--timeout", timeout, "Seconds a reference or subject may run before it counts as hung")
            ->capture_default_str();
        app.add_option("--subject", subject,
                       "Put a program under test in core's place: a command template such as "
                       "'python3 loop.py {in} {levels} {out}' ({in}: OBJ with its 't' tag lines, {in.untagged}, "
                       "{in.off}, {in.ply}: without; {out} {out.off} {out.ply} {levels} {scheme} {weights} {boundary}); "
                       "run without a shell, in a temporary folder, with --timeout per run")
            ->check(kNotBlank);
        app.add_option("--subject-name", subject_name, "The subject's name in the results")->check(kSubjectName)->capture_default_str();
        app.add_option("--subject-levels", subject_levels,
                       "each: run the subject once per level 1..N and compare every level; final: once, for level N")
            ->check(CLI::IsMember({"each", "final"}))
            ->capture_default_str();
        app.add_option("--reference", references,
                       "Add a program as a reference: NAME=CMD, CMD a command template as for --subject; or "
                       "NAME=command='CMD' [serve='CMD'] [setup='CMD'] [schemes=..] [precision=float] [weights=..] [boundary=..] "
                       "[levels=final] [timeout=S] [rejects=..] as a suite manifest's reference statement. Repeatable");
    }

    /// Registers each --reference NAME=CMD (or NAME=command='CMD' key=value ...) as a
    /// reference and returns the subject program, if any, an implementation of `scheme`.
    std::unique_ptr<Implementation> setup(Scheme scheme) const {
        for (const std::string& s : references) {
            const size_t eq = s.find('=');
            if (eq == std::string::npos || eq == 0) throw InputError("--reference '" + s + "': expected NAME=CMD");
            const std::string name = s.substr(0, eq), rest = s.substr(eq + 1);
            const std::vector<std::string> keys = rest.starts_with("command=") ? statement_words(rest)
                                                                                : std::vector<std::string>{"command=" + rest};
            register_reference(make_program_implementation(program_spec(name, keys, "", timeout)));
        }
        if (subject.empty()) return nullptr;
        check_subject_name(subject_name);  // against the references just registered too
        ProgramSpec spec;
        spec.name = subject_name;
        spec.command = subject;
        spec.schemes = {scheme};
        spec.levels = level_mode_from_string(subject_levels);
        spec.timeout_seconds = timeout;
        return make_program_implementation(spec);
    }
};

struct CompareArgs {
    std::vector<std::string> inputs;
    SchemeArgs scheme;
    std::string against, json;  // against empty: every reference that has the scheme
    bool no_isolate = false;
    ProgramArgs programs;
    std::string subject_result;
    void add_to(CLI::App& app) {
        app.add_option("inputs", inputs, "Mesh files, bundled:NAME, edgecase:NAME, dir:FOLDER (every mesh file in it), dir:FOLDER/*.obj, bundled:all, edgecases:all, polygons:all, course:all, cgal:all")->required();
        scheme.add_scheme_options(app, kMaxComparedFaces);
        app.add_option("--against", against,
                       "Comma-separated references (default: every one that has the scheme; sqrt3 also has "
                       "openmesh-one-call and cgal-one-call, all levels in one call)");
        app.add_option("--json", json, "Write the results as JSON to this file");
        app.add_flag("--no-isolate", no_isolate, "Run references in this process (debugging; a crash ends the run)");
        programs.add_to(app);
        app.add_option("--subject-result", subject_result,
                       "Put a result file under test (OBJ, OFF or PLY a program already wrote), compared at --levels")
            ->check(kNotBlank)
            ->excludes("--subject");
    }
};

int compare_command(const CompareArgs& a) {
    std::unique_ptr<Implementation> subject = a.programs.setup(scheme_from_string(a.scheme.scheme));
    if (!a.subject_result.empty()) {
        if (a.inputs.size() != 1) throw InputError("--subject-result compares one result file with one input");
        subject = make_result_file_implementation(a.programs.subject_name, a.subject_result, scheme_from_string(a.scheme.scheme));
    }
    return run_compare(a.inputs, a.scheme, a.against, a.json, a.programs.timeout, a.no_isolate, subject.get(),
                       a.subject_result.empty() ? a.programs.subject : std::string());
}

struct CheckArgs {
    std::string input;
    void add_to(CLI::App& app) { app.add_option("input", input, "Mesh file or bundled:NAME")->required(); }
};
int check_command(const CheckArgs& a) { return run_check(a.input); }

struct FolderArgs {
    std::string out;
    void add_to(CLI::App& app) { app.add_option("--out", out, "Output folder")->required(); }
};
int datasets_command(const FolderArgs& a) { return run_datasets(a.out); }
int edgecases_command(const FolderArgs& a) { return run_edgecases(a.out); }

struct DiffArgs {
    std::string input, against, out = "diff-out";
    SchemeArgs scheme;
    ProgramArgs programs;
    void add_to(CLI::App& app) {
        app.add_option("input", input, "Mesh file, bundled:NAME or edgecase:NAME")->required();
        scheme.add_scheme_options(app, kMaxComparedFaces);
        app.add_option("--against", against,
                       "The reference that diverges (with --subject and no --against: shrink what the subject does "
                       "that no named rule explains, or its failure)");
        programs.add_to(app);
        app.add_option("--out", out, "Output folder")->capture_default_str();
    }
};
int diff_command(const DiffArgs& a) {
    const std::unique_ptr<Implementation> subject = a.programs.setup(scheme_from_string(a.scheme.scheme));
    return run_diff(a.input, a.scheme, a.against, a.out, subject.get(), a.programs.timeout, a.programs.subject);
}

struct InvarianceArgs {
    std::vector<std::string> inputs;
    SchemeArgs scheme;
    ProgramArgs programs;
    std::string impls, transforms, json, out = "invariance-out";
    std::uint64_t seed = 1;
    double tolerance = 1e-12;
    bool no_isolate = false;
    void add_to(CLI::App& app) {
        app.add_option("inputs", inputs, "Mesh files, bundled:NAME, edgecase:NAME, collections (bundled:all, ...)")->required();
        scheme.add_scheme_options(app, kMaxComparedFaces);
        app.add_option("--impl", impls,
                       "Implementations to check, comma-separated (core, a reference's name); default: core and every "
                       "reference that has the scheme");
        std::string names;
        for (InputTransformation t : kInputTransformations) names += (names.empty() ? "" : ", ") + std::string(to_string(t));
        app.add_option("--transform", transforms, "Transformations, comma-separated (default: all): " + names);
        app.add_option("--seed", seed, "Seed of the random transformations (the same seed, the same inputs)")->capture_default_str();
        app.add_option("--tolerance", tolerance,
                       "Largest difference, relative to the diagonal, of a transformation floating point does not keep exact")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
        app.add_option("--json", json, "Write the results as JSON to this file");
        app.add_option("--out", out, "Folder for the minimal inputs of the findings")->capture_default_str();
        app.add_flag("--no-isolate", no_isolate, "Run implementations in this process (debugging; a crash ends the run)");
        programs.add_to(app);
    }
};
int invariance_command(const InvarianceArgs& a) {
    if (!a.programs.subject.empty() && !a.impls.empty()) throw InputError("--impl and --subject exclude each other");
    const std::unique_ptr<Implementation> subject = a.programs.setup(scheme_from_string(a.scheme.scheme));
    InvarianceOptions o;
    o.inputs = a.inputs;
    o.scheme = a.scheme.poly();
    o.weights = a.scheme.weights;
    o.impls = split_commas(a.impls);
    o.transforms = split_commas(a.transforms);
    o.seed = a.seed;
    o.tolerance = a.tolerance;
    o.timeout = a.programs.timeout;
    o.isolate = !a.no_isolate;
    o.json = a.json;
    o.out = a.out;
    return run_invariance(o, subject.get());
}

}  // namespace

void add_mesh_commands(CLI::App& app, int& status) {
    add_command<SubdivideArgs>(app, "subdivide", "Subdivide a mesh with core or a reference", status, subdivide_command);
    add_command<CompareArgs>(app, "compare", "Compare core with reference libraries", status, compare_command);
    add_command<CheckArgs>(app, "check", "Report every problem of a mesh, by element", status, check_command);
    add_command<FolderArgs>(app, "datasets", "Write the bundled meshes as OBJ files", status, datasets_command);
    add_command<FolderArgs>(app, "edgecases", "Write the edge-case catalog as OBJ files (one line each: what it tests)",
                            status, edgecases_command);
    add_command<DiffArgs>(app, "diff", "Shrink a divergence to the worst vertex's neighbourhood and a minimal mesh", status,
                          diff_command);
    add_command<InvarianceArgs>(app, "invariance",
                                "Check that each implementation's refinement does not depend on how the input is written "
                                "(faces rotated, reordered, relabelled, reversed; the mesh scaled, mirrored, rotated; run again)",
                                status, invariance_command);
}

}  // namespace crossdiv::cli
