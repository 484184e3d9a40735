#include "surface_commands.h"

#include <fmt/format.h>

#include "crossdiv/io/output_file.h"
#include "crossdiv/verification/comparisons/surface_subject.h"
#include "crossdiv/verification/harness/temporary_folder.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "command.h"
#include "crossdiv/datasets/bundled_surfaces.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/io/patch_io.h"
#include "crossdiv/surfaces/sweep_surface.h"

namespace crossdiv::cli {
using nlohmann::json;

void SweepArgs::add_to(CLI::App& app) {
    app.add_option("input", input, "SWP file with srev and gcyl records, or surface:NAME (bundled)")->required();
    app.add_option("-o,--output", out, "Output OBJ (v, vn, f a//a); required without --subject");
    app.add_option("--frames", frames, "gcyl frames: recursive (the seed's) or rmf (double reflection)")
        ->check(CLI::IsMember({"recursive", "rmf"}))
        ->capture_default_str();
    app.add_flag("--adaptive", adaptive, "Distance-adaptive curves (and srev slices) instead of each record's STEPS");
    app.add_option("--tolerance", tol, "Adaptive: the largest distance from the exact surface (absolute)");
    app.add_option("--max-faces", max_faces, "Refuse a surface of more triangles than this, before building it")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    subject.add_to(app, "'python3 revolve.py {in} {out}' ({in}: the SWP file; {out}: an OBJ with a vn per v of every "
                        "srev and gcyl record, welded or not); matched to core's surfaces by position both ways, its "
                        "normals named (as core's, or reversed) and its faces checked against them");
}

void PatchArgs::add_to(CLI::App& app) {
    app.add_option("input", input, "BEZ file, or surface:NAME (a bundled BEZ model)")->required();
    app.add_option("-o,--output", out, "Output OBJ (v, vn, f a//a); required without --subject");
    app.add_option("--res", res, "Quads per patch side")->check(CLI::Range(1, 1024))->capture_default_str();
    subject.add_to(app, "'python3 patches.py {in} 8 {out}' ({in}: the BEZ file, the resolution a literal equal to --res; "
                        "{out}: an OBJ with a vn per v, welded or not); matched to core's tessellation by position both ways, "
                        "its normals named (as core's or reversed) and its faces checked against them");
    app.add_option("--max-faces", max_faces, "Refuse a tessellation of more triangles than this, before making it")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
}

namespace {

void require_obj(const std::string& out) {
    if (std::filesystem::path(out).extension() != ".obj") throw InputError(out + ": the output must be an .obj file");
}

void write(const std::string& path, const SurfaceMesh& s) {
    OutputFile f(path);
    write_obj(f.stream(), to_poly_mesh(s.mesh), s.normals);
    f.close();
}

/// Appends b to a, offsetting its indices.
void append(SurfaceMesh& a, const SurfaceMesh& b) {
    const int base = a.mesh.num_vertices();
    a.mesh.positions.insert(a.mesh.positions.end(), b.mesh.positions.begin(), b.mesh.positions.end());
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    for (Triangle t : b.mesh.triangles) a.mesh.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    a.collapsed_triangles += b.collapsed_triangles;
}

std::string bundled_text(const std::string& spec, const char* format) {
    const datasets::BundledCurve& b = datasets::bundled_surface(spec.substr(8));
    if (b.format != format) throw InputError(spec + " is a " + b.format + " model, not " + format);
    return b.text;
}

}  // namespace

namespace {

/// A program's surfaces against core's samples: the input file (a bundled model's text
/// written out as `name` first), each normal rule's fit, and the verdict; exit 1 unless it passes.
int run_surface_subject(const std::string& input, const std::string& bundled_text, const char* name,
                        std::span<const verification::SurfaceSamples> conventions, const TaskSubjectOptions& subject) {
    const verification::TemporaryFolder folder("surface-input");
    std::string path = input;
    if (!bundled_text.empty()) {
        path = (folder.path() / name).string();
        write_text_file(path, bundled_text);
    }
    const auto c = verification::compare_surface_subject(path, conventions, subject.name, subject.command, subject.timeout);
    if (c.conventions.size() > 1)
        for (const auto& f : c.conventions)
            fmt::print("  positions {:<45} {} {:.3g} from core's, core's {:.3g} from its\n", f.convention, f.fits ? "=" : " ",
                       f.subject_to_core, f.core_to_subject);
    for (const auto& n : c.normals)
        fmt::print("  normals {:<10} {} {} vertices off, up to {:.3g} deg\n", n.name, n.fits ? "=" : " ", n.off, n.max_deg);
    fmt::print("{}\n", c.summary());
    return c.passed() ? 0 : 1;
}

}  // namespace

int run_sweep(const SweepArgs& a) {
    if (a.subject.command.empty() && a.out.empty()) throw InputError("sweep needs -o OUT.obj, or --subject CMD");
    if (a.subject.command.empty()) require_obj(a.out);
    std::string text;  // a bundled model's, written out for a subject
    CurveFile file;
    if (a.input.starts_with("surface:")) {
        text = bundled_text(a.input, "swp");
        std::istringstream in(text);
        file = read_swp(in, a.input);
    } else {
        file = read_swp(a.input);
    }
    if (file.sweeps.empty()) throw InputError(a.input + ": no srev or gcyl record");
    if (a.adaptive && !(a.tol > 0 && std::isfinite(a.tol))) throw InputError("--adaptive needs a positive, finite --tolerance");
    if (!a.adaptive && a.tol != 0) throw InputError("--tolerance is for --adaptive sweeps");
    SweepOptions o;
    o.frames = a.frames == "rmf" ? FrameMethod::DoubleReflection : FrameMethod::Recursive;
    o.adaptive = a.adaptive;
    o.tol = a.tol;
    o.max_triangles = a.max_faces;
    SurfaceMesh all;
    for (int k = 0; k < static_cast<int>(file.sweeps.size()); ++k) {
        const SweepSurface s = build_sweep(file, k, o);
        const int boundary = boundary_edge_count(s.surface.mesh);
        fmt::print("{} ({}, line {}): {} vertices, {} triangles, {}{}, signed volume {:.6g}\n", s.name,
                   s.record.kind == SweepRecord::Kind::Revolution ? "srev" : "gcyl", s.record.line, s.surface.mesh.num_vertices(),
                   s.surface.mesh.num_faces(), s.closed ? "closed" : "open",
                   s.closed ? (boundary == 0 ? ", watertight" : fmt::format(", NOT watertight: {} boundary edges", boundary)) : "",
                   signed_volume(s.surface.mesh));
        append(all, s.surface);
    }
    if (!a.subject.command.empty()) {
        const std::vector<verification::SurfaceSamples> conventions = verification::sweep_conventions(file, o);
        return run_surface_subject(a.input, text, "model.swp", conventions, a.subject);
    }
    write(a.out, all);
    fmt::print("wrote {}\n", a.out);
    return 0;
}

int run_patch(const PatchArgs& a) {
    if (a.subject.command.empty() && a.out.empty()) throw InputError("patch needs -o OUT.obj, or --subject CMD");
    if (a.subject.command.empty()) require_obj(a.out);
    std::vector<BezierPatch> patches;
    std::string text;  // a bundled model's, written out for a subject
    if (a.input.starts_with("surface:")) {
        text = bundled_text(a.input, "bez");
        std::istringstream in(text);
        patches = read_bez(in, a.input);
    } else {
        patches = read_bez(a.input);
    }
    SurfaceMesh s;
    try {
        s = tessellate_patches(patches, a.res, a.max_faces);
    } catch (const InputError& e) {
        throw InputError(a.input + ": " + e.what());
    }
    if (!a.subject.command.empty()) {
        // Core's grid of every patch before welding, each point with its own patch's normal.
        const verification::SurfaceSamples samples = verification::patch_samples(patches, a.res, s);
        return run_surface_subject(a.input, text, "model.bez", {&samples, 1}, a.subject);
    }
    const int boundary = boundary_edge_count(s.mesh);
    fmt::print("{}: {} patches, {} vertices, {} triangles ({} collapsed at degenerate patch edges), {}\n", a.input, patches.size(),
               s.mesh.num_vertices(), s.mesh.num_faces(), s.collapsed_triangles,
               boundary == 0 ? "closed (no boundary edge)" : fmt::format("{} boundary edges", boundary));
    write(a.out, s);
    fmt::print("wrote {}\n", a.out);
    return 0;
}

json run_surface_bench() {
    // The seed's comparison: uniform steps (the record's) against adaptive steps, both
    // meshes measured against the exact surface of revolution.
    std::string course;
    for (const std::string& f : datasets::course_surface_files())
        if (std::filesystem::path(f).filename() == "wineglass.swp") course = f;
    CurveFile file;
    std::string input;
    if (!course.empty()) {
        file = read_swp(course);
        input = course;
    } else {
        std::istringstream in(datasets::bundled_surface("vase").text);
        file = read_swp(in, "surface:vase");
        input = "surface:vase (the course wineglass is not present)";
    }
    const SweepRecord& rec = file.sweeps.at(0);
    const ExactSurface exact = exact_revolution(file.curves.at(rec.profile_index));
    const SweepSurface uniform = build_sweep(file, 0, {});
    const double uniform_dev = grid_deviation(uniform.grid, exact);
    // The adaptive sweep with the fewest faces whose measured deviation is within the
    // uniform mesh's: for each split of the budget between profile and slices, the largest
    // tolerance that measures within it, bracketed from twice that deviation shrinking by 5%
    // and then bisected (a 5% step alone leaves up to 5% more faces than needed).
    SweepOptions o;
    SweepSurface adaptive;
    double adaptive_dev = 0;
    const auto consider = [&](const SweepOptions& t) {
        SweepSurface s = build_sweep(file, 0, t);
        const double dev = grid_deviation(s.grid, exact);
        if (dev > uniform_dev) return false;
        if (adaptive.surface.mesh.num_faces() == 0 || s.surface.mesh.num_faces() < adaptive.surface.mesh.num_faces()) {
            adaptive = std::move(s);
            adaptive_dev = dev;
            o = t;
        }
        return true;
    };
    for (double share = 0.3; share < 0.71; share += 0.05) {
        SweepOptions t;
        t.adaptive = true;
        t.curve_share = share;
        t.tol = 2 * uniform_dev;
        double too_far = 0;
        for (int round = 0; round < 60 && !consider(t); ++round) {
            too_far = t.tol;
            t.tol *= 0.95;
        }
        for (double fits = t.tol, round = 0; too_far > 0 && round < 10; ++round) {
            t.tol = 0.5 * (fits + too_far);
            (consider(t) ? fits : too_far) = t.tol;
        }
    }
    const int uf = uniform.surface.mesh.num_faces(), af = adaptive.surface.mesh.num_faces();
    constexpr int kSeedUniform = 33120, kSeedAdaptive = 18540;
    const double ratio = static_cast<double>(uf) / af, seed_ratio = static_cast<double>(kSeedUniform) / kSeedAdaptive;
    fmt::print("\nadaptive sweep: {} ({})\n", input, uniform.name);
    fmt::print("  {:<10} {:>8} {:>8} {:>10} {:>12}\n", "mode", "faces", "slices", "profile", "deviation");
    fmt::print("  {:<10} {:>8} {:>8} {:>10} {:>12.4e}\n", "uniform", uf, uniform.grid.rings, uniform.grid.ring_size, uniform_dev);
    fmt::print("  {:<10} {:>8} {:>8} {:>10} {:>12.4e}   (tol {:.4e}, profile share {:.2f})\n", "adaptive", af,
               adaptive.grid.rings, adaptive.grid.ring_size, adaptive_dev, o.tol, o.curve_share);
    fmt::print("  uniform / adaptive faces: {:.2f} (the seed's: {} / {} = {:.2f}); {}\n", ratio, kSeedUniform, kSeedAdaptive,
               seed_ratio, ratio > seed_ratio && adaptive_dev <= uniform_dev ? "beats the seed's ratio at equal deviation" : "does NOT beat the seed's ratio");
    return {{"input", input},
            {"surface", uniform.name},
            {"uniform", {{"faces", uf}, {"slices", uniform.grid.rings}, {"profile_samples", uniform.grid.ring_size}, {"deviation", uniform_dev}}},
            {"adaptive", {{"faces", af}, {"slices", adaptive.grid.rings}, {"profile_samples", adaptive.grid.ring_size},
                          {"deviation", adaptive_dev}, {"tol", o.tol}, {"curve_share", o.curve_share}}},
            {"ratio", ratio},
            {"seed", {{"uniform_faces", kSeedUniform}, {"adaptive_faces", kSeedAdaptive}, {"ratio", seed_ratio}}},
            {"beats_seed", ratio > seed_ratio && adaptive_dev <= uniform_dev}};
}

void print_surface_tables(const std::vector<verification::CaseRecord>& records) {
    for (const verification::CaseRecord& rec : records) {
        if (rec.operation != "surfaces" || !rec.detail.contains("tables")) continue;
        const json& t = rec.detail["tables"];
        if (t.contains("sphere") || t.contains("torus")) {
            fmt::print("\nsurfaces against exact surfaces (mesh-to-surface distance, normal errors in rad):\n");
            fmt::print("  {:<32} {:>5} {:>8} {:>11} {:>11} {:>11}\n", "surface", "n", "faces", "distance", "vertex-n", "face-n");
            for (const char* key : {"sphere", "torus"})
                for (const json& r : t.value(key, json::array())) {
                    if (r.contains("fitted_order")) {
                        fmt::print("  {:<32} fitted order {:.3f}\n", r.value("surface", ""), r.value("fitted_order", 0.0));
                        continue;
                    }
                    fmt::print("  {:<32} {:>5} {:>8} {:>11.3e} {:>11.3e} {:>11.3e}\n", r.value("surface", ""),
                               r.contains("profile_intervals") ? r["profile_intervals"].get<int>() : r.value("profile_steps", 0),
                               r.value("faces", 0), r.contains("radial_error") ? r["radial_error"].get<double>() : r.value("distance_error", 0.0),
                               r.value("vertex_normal_error_rad", 0.0), r.value("face_normal_error_rad", 0.0));
                }
        }
        if (t.contains("bfr")) {
            fmt::print("\nCatmull-Clark limit of regular grids against OpenSubdiv Bfr:\n");
            for (const json& r : t["bfr"])
                fmt::print("  {:<12} {} faces ({} regular), {} samples: position {:.2e}, derivatives {:.2e} (relative)\n",
                           r.value("grid", ""), r.value("faces", 0), r.value("regular", 0), r.value("samples", 0),
                           r.value("max_position_rel", 0.0), r.value("max_derivative_rel", 0.0));
        }
    }
    bool header = false;
    for (const verification::CaseRecord& rec : records) {
        if (rec.operation != "surfaces" || !rec.detail.contains("tables") || !rec.detail["tables"].contains("surfaces")) continue;
        if (!header) {
            fmt::print("\nsurfaces built (closed ones must be watertight and outward):\n");
            fmt::print("  {:<34} {:>5} {:>8} {:>7} {:>9} {:>12} {:>6}\n", "surface", "kind", "faces", "closed", "boundary", "volume", "folds");
            header = true;
        }
        for (const json& r : rec.detail["tables"]["surfaces"])
            fmt::print("  {:<34} {:>5} {:>8} {:>7} {:>9} {:>12.6g} {:>6}\n", r.value("surface", "").substr(0, 34), r.value("kind", ""),
                       r.value("faces", 0), r.value("closed", false) ? "yes" : "no", r.value("boundary_edges", 0),
                       r.value("signed_volume", 0.0), r.contains("fold") ? r["fold"].value("faces", 0) : 0);
    }
}

void add_surface_commands(CLI::App& app, int& status) {
    add_command<SweepArgs>(app, "sweep", "Build every srev and gcyl record of an SWP file into an OBJ with normals", status,
                           run_sweep);
    add_command<PatchArgs>(app, "patch", "Tessellate the Bezier patches of a BEZ file into one welded OBJ with normals",
                           status, run_patch);
}

}  // namespace crossdiv::cli
