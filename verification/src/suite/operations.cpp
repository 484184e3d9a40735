#include "crossdiv/verification/suite/operations.h"

#include <filesystem>
#include <fstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/output_size.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/properties/curve_checks.h"
#include "crossdiv/verification/comparisons/halfedge_checks.h"
#include "crossdiv/verification/properties/surface_checks.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/suite/features_under_test.h"
#include "crossdiv/verification/suite/invariance_case.h"
#include "crossdiv/verification/suite/task_cases.h"
#include "crossdiv/verification/studies/curvature_study.h"
#include "crossdiv/verification/studies/fitting_study.h"
#include "crossdiv/verification/studies/isosurface_study.h"
#include "crossdiv/verification/studies/multiresolution_study.h"
#include "crossdiv/verification/studies/pages_study.h"
#include "crossdiv/verification/pages/divergence_view_file.h"
#include "crossdiv/verification/studies/studies.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// The file of a case's minimal input, beside its view.
std::string minimal_obj_name(const SuiteJob& job) { return "views/job" + std::to_string(job.index) + "-minimal.obj"; }

/// Inputs up to this many faces are shrunk for the viewer: every catalog and bundled mesh, where
/// delta debugging takes tens of comparisons of milliseconds each (measured: 1 to 7 comparisons,
/// 0.03 to 0.08 s a case); larger inputs would take seconds each, and `crossdiv diff` is there.
constexpr int kShrinkMaxFaces = 500;

/// The first divergence from a library reference among `runs` (of the positions, or of the
/// texture coordinates) that shrinks, as `crossdiv diff` shrinks it: nothing when core is not
/// what is under test or the input is too large. A reference that is a program is passed over:
/// each comparison would start it again. A symptom that needs the whole input, or is a
/// refusal, does not shrink (shrink_divergence throws InputError): the view stands alone.
std::optional<MinimalDivergence> shrink_for_view(const PolyMesh& mesh, const std::string& input,
                                                 const RefinementRequest& req, const RefinementComparison& c,
                                                 const std::string& obj_name) {
    if (req.subject || mesh.num_faces() > kShrinkMaxFaces) return std::nullopt;
    for (const RefinementRun& run : c.runs) {
        const bool uv_diverges = run.uv && run.uv->compared() && run.uv->outcome.verdict == Verdict::Diverge;
        if ((run.verdict != Verdict::Diverge && !uv_diverges) || find_implementation(run.reference).confines_itself())
            continue;
        try {
            RefinementRequest one = req;
            one.references = {run.reference};
            one.view_max_faces = 0;
            const ShrinkResult r = shrink_divergence(mesh, input, one);
            return MinimalDivergence{run.reference, describe(r.symptom, "core", run.reference), r.minimal, r.tests,
                                     compare_command(req, obj_name, run.reference)};
        } catch (const InputError&) {
            // Nothing to shrink here: the view stands alone.
        }
    }
    return std::nullopt;
}

/// Writes the case's 3D view as views/jobN.js (and its minimal input as views/jobN-minimal.obj)
/// and names it in the case.
void write_view(const DivergenceView& view, const std::string& subject, const SuiteJob& job, const std::string& out_dir,
                CaseRecord& rec) {
    const std::string name = "views/job" + std::to_string(job.index) + ".js";
    create_output_folder((fs::path(out_dir) / "views").string());
    write_divergence_view(view, job.index, subject, (fs::path(out_dir) / name).string());
    rec.detail["view"] = name;
    if (view.minimal) {
        const std::string obj = minimal_obj_name(job);
        write_mesh((fs::path(out_dir) / obj).string(), view.minimal->mesh);
        rec.detail["minimal"] = {{"mesh", obj}, {"reference", view.minimal->reference},
                                 {"faces", view.minimal->mesh.num_faces()}, {"symptom", view.minimal->symptom}};
    }
}

/// A comparison case: the implementation under test (core, or the manifest's subject program or
/// its result file for this input) against every reference of the case, under the rule the
/// case names or, for a scheme other than Loop, the input's tags ask for (what the tags
/// resolved to is noted in the record).
CaseRecord run_refinement(const SuiteJob& job, const std::string& out_dir) {
    const ManifestEntry& entry = *job.entry;
    RefinementRequest req = entry.request;
    req.view_max_faces = kViewMaxFaces;
    std::unique_ptr<Implementation> result_file;
    if (const auto& s = entry.subject) {
        if (s->program) {
            req.subject = s->program.get();
        } else {
            result_file = make_result_file_implementation(s->name, s->result_path(job.input, req.levels), req.scheme);
            req.subject = result_file.get();
        }
    }
    PolyMesh input = load_input(job.input);
    require_refined_size(input, req.scheme, req.levels, entry.max_faces, job.input, "the manifest's max-faces");
    std::vector<std::string> notes;
    if (traits(req.scheme).triangles) {
        // A polygon under a triangle scheme is the input's refusal, by name, tagged or not, as
        // the CLI refuses it: never triangulated (a choice no reference shares).
        PolyMesh faces_only = input;
        faces_only.creases = {};
        (void)to_tri_mesh(faces_only, (std::string(to_string(req.scheme)) + " subdivision").c_str());
    }
    resolve_input_rules(req, entry, input, notes);
    RefinementComparison c = compare_refinement(input, job.input, req);
    if (c.view) c.view->minimal = shrink_for_view(input, job.input, req, c, minimal_obj_name(job));
    CaseRecord rec = case_record(c);
    if (entry.subject && rec.detail.contains("subject")) rec.detail["subject"]["roster"] = entry.subject->roster;
    for (const std::string& note : notes) rec.detail["notes"].push_back(note);
    if (c.view) write_view(*c.view, c.subject, job, out_dir, rec);
    return rec;
}

CaseRecord run_curves(const SuiteJob& job, const std::string&) {
    return case_record(job.input == "curves:synthetic" ? check_synthetic()
                                                       : check_curve_file(load_curve_input(job.input), job.input));
}

CaseRecord run_surfaces(const SuiteJob& job, const std::string&) {
    return case_record(check_surface_input(job.input, features_under_test().sweep));
}

CaseRecord run_edits(const SuiteJob& job, const std::string&) {
    return case_record(check_edits(job.input, features_under_test().edits));
}

CaseRecord run_normals(const SuiteJob& job, const std::string&) {
    return case_record(check_normals(job.input, features_under_test().normals));
}

template <const char* Collection>
std::vector<std::string> one_collection(const std::vector<std::string>& specs) {
    for (const std::string& s : specs)
        if (s != Collection) throw InputError("'" + s + "' is not what this operation runs over (it takes '" + Collection + "')");
    return specs;
}

constexpr char kCatalog[] = "catalog";
constexpr char kCreases[] = "creases";
constexpr char kFans[] = "fans";

template <CheckReport (*Study)()>
CaseRecord run_study(const SuiteJob& job, const std::string&) {
    CheckReport r = Study();
    r.input = job.input;
    r.operation = job.entry->operation->name;
    return case_record(r);
}

/// The pages study writes its pages beside the results, so it takes the output folder.
CaseRecord run_pages(const SuiteJob& job, const std::string& out_dir) {
    CheckReport r = pages_study(out_dir);
    r.input = job.input;
    r.operation = job.entry->operation->name;
    return case_record(r);
}

}  // namespace

void resolve_input_rules(RefinementRequest& req, const ManifestEntry& entry, PolyMesh& input, std::vector<std::string>& notes) {
    if (req.scheme != Scheme::Loop) req.rule = rule_with_tags(req.scheme, entry.rule_flags, input, notes);
    // Texture coordinates, where the input has them: the case's fvar=, the file's tag, or all.
    req.face_varying = face_varying_rule(req.scheme, entry.rule_flags.face_varying, input, notes);
}

std::string compare_command(const RefinementRequest& req, const std::string& mesh_file, const std::string& reference) {
    const std::string rule = req.scheme == Scheme::Loop
                                 ? " --weights " + std::string(to_string(req.rule.loop.weights)) + " --boundary " +
                                       std::string(to_string(req.rule.loop.boundary))
                                 : " --scheme " + std::string(to_string(req.scheme)) + " --boundary " +
                                       boundary_name(req.scheme, req.rule);
    const std::string fvar = req.face_varying ? " --fvar " + std::string(to_string(*req.face_varying)) : "";
    // A program reference is not built in: the line registers it as the manifest did.
    const std::string program = find_implementation(reference).reference_option();
    return "crossdiv compare " + mesh_file + rule + fvar + " --levels " + std::to_string(req.levels) + " --against " + reference +
           (program.empty() ? "" : " --reference \"" + program + "\"");
}


const std::vector<SuiteOperation>& suite_operations() {
    static const std::vector<SuiteOperation> ops = {
        {"loop", OperationKind::Comparison, "core against every reference on a mesh, under the case's rules and tier",
         expand_inputs, run_refinement},
        {"catmull-clark", OperationKind::Comparison, "core's Catmull-Clark against every reference that has it, under the case's rule and tier",
         expand_inputs, run_refinement, Scheme::CatmullClark},
        {"doo-sabin", OperationKind::Comparison, "core's Doo-Sabin against every reference that has it", expand_inputs,
         run_refinement, Scheme::DooSabin},
        {"sqrt3", OperationKind::Comparison, "core's sqrt3 against every reference that has it", expand_inputs, run_refinement,
         Scheme::Sqrt3},
        {"butterfly", OperationKind::Comparison, "core's classic Butterfly against every reference that has it",
         expand_inputs, run_refinement, Scheme::Butterfly},
        {"modified-butterfly", OperationKind::Comparison, "core's modified Butterfly against every reference that has it",
         expand_inputs, run_refinement, Scheme::ModifiedButterfly},
        {"bilinear", OperationKind::Comparison, "core's bilinear subdivision against every reference that has it (OpenSubdiv)",
         expand_inputs, run_refinement, Scheme::Bilinear},
        {"midpoint", OperationKind::Comparison, "core's midpoint triangle subdivision against every reference that has it (VTK, Open3D)",
         expand_inputs, run_refinement, Scheme::Midpoint},
        {"curves", OperationKind::Checks, "curve files against Eigen and exact properties", expand_curve_inputs, run_curves},
        {"surfaces", OperationKind::Checks, "surface files built and checked as closed surfaces", expand_surface_inputs,
         run_surfaces},
        {"edits", OperationKind::Checks, "seeded flip and split sequences against OpenMesh and CGAL, valid after each",
         expand_inputs, run_edits},
        {"normals", OperationKind::Checks, "vertex normals against OpenMesh's and CGAL's calls and the angle oracle",
         expand_inputs, run_normals},
        {"schemes", OperationKind::Study, "the Butterfly properties on the bundled meshes; the rule oracles of Doo-Sabin, sqrt3 and the classic Butterfly",
         one_collection<kCatalog>, run_study<schemes_study>},
        {"creases", OperationKind::Study, "the crease catalog against OpenSubdiv", one_collection<kCreases>,
         run_study<creases_study>},
        {"limit-positions", OperationKind::Study, "limit positions and normals against OpenSubdiv, Bfr at (u, v)",
         one_collection<kCatalog>, run_study<limit_positions_study>},
        {"face-varying", OperationKind::Study, "texture coordinates from x and y refine, under the smooth rule, as the positions do: core and each reference with face-varying rules",
         one_collection<kCatalog>, run_study<face_varying_study>},
        {"vertex-age", OperationKind::Study, "the level each vertex was born at, every scheme, against the topology",
         one_collection<kCatalog>, run_study<vertex_age_study>},
        {"curvature", OperationKind::Study, "discrete curvature against the analytic sphere and torus and CGAL's jet fitting, Gauss-Bonnet, Loop's curvature at extraordinary vertices",
         one_collection<kCatalog>, run_study<curvature_study>},
        {"isosurface", OperationKind::Study, "marching cubes against exact implicit surfaces (distance, Euler characteristic, watertight, volume), ambiguous faces, scikit-image's marching cubes",
         one_collection<kCatalog>, run_study<isosurface_study>},
        {"fitting", OperationKind::Study, "subdivision surface fitting: exact recovery on the catalog; Loop and Catmull-Clark fitted to the CGAL meshes and the bunny, CGAL's Hausdorff distance per iteration",
         one_collection<kCatalog>, run_study<static_cast<CheckReport (*)()>(fitting_study)>},
        {"multiresolution", OperationKind::Study, "Loop multiresolution editing: round trip, rigid motion, an edit's reach against the prediction and the subdivision support",
         one_collection<kCatalog>, run_study<multiresolution_study>},
        {"pages", OperationKind::Study, "the report's curve editor page (bundled curves, core's tessellations and frames) and subdivision-levels page, and the checks of what they show",
         one_collection<kCatalog>, run_pages},
        {"spectrum", OperationKind::Study, "eigen table of the local subdivision matrices; the Loop rule oracle", one_collection<kFans>,
         run_study<spectrum_study>},
        {"convergence", OperationKind::Study, "convergence of extraordinary vertices to their limit",
         one_collection<kFans>, run_study<convergence_study>},
        {"invariance", OperationKind::Invariance, "each implementation of the case's scheme on a mesh and on the mesh written otherwise (corners rotated, faces reordered, vertices relabelled, moved, run again): the same surface, no reference needed",
         expand_inputs, run_invariance_case},
        {"tessellate", OperationKind::Task, "a subject's uniform tessellation and frames of every curve record, named",
         expand_curve_inputs, run_task_case},
        {"casteljau", OperationKind::Task, "a subject's de Casteljau levels of a Bezier curve at t", expand_curve_inputs,
         run_task_case},
        {"patch", OperationKind::Task, "a subject's Bezier patch tessellation: positions, normals, faces", expand_surface_inputs,
         run_task_case},
        {"sweep", OperationKind::Task, "a subject's surfaces of revolution and generalized cylinders: positions, normals, faces, watertightness",
         expand_surface_inputs, run_task_case},
        {"vertex-normals", OperationKind::Task, "a subject's vertex normals, their weighting named", expand_inputs, run_task_case},
        {"flip-split", OperationKind::Task, "a subject's edge flips and splits, the mesh after each compared", expand_inputs,
         run_task_case},
    };
    return ops;
}

const char* to_string(OperationKind kind) {
    switch (kind) {
        case OperationKind::Comparison: return "comparison";
        case OperationKind::Checks: return "checks";
        case OperationKind::Study: return "study";
        case OperationKind::Task: return "task";
        case OperationKind::Invariance: return "invariance";
    }
    return "unknown";
}

nlohmann::json operations_json() {
    json out = json::array();
    for (const SuiteOperation& op : suite_operations()) {
        json o = {{"name", op.name}, {"kind", to_string(op.kind)}};
        if (op.kind == OperationKind::Comparison) o["scheme"] = to_string(op.scheme);
        out.push_back(std::move(o));
    }
    return out;
}

const SuiteOperation& find_operation(std::string_view name) {
    std::string known;
    for (const SuiteOperation& op : suite_operations()) {
        if (op.name == name) return op;
        known += (known.empty() ? "" : ", ") + op.name;
    }
    throw InputError("unknown operation '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace crossdiv::verification
