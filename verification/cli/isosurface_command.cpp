// crossdiv isosurface IN [--isovalue L] [--res N] [--inside below|above] [--rule decider|minority]
//                       [--against skimage,skimage-lorensen] [--write-volume V] [-o OUT]
#include "isosurface_command.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "command.h"
#include "crossdiv/datasets/implicit_surfaces.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/io/volume_io.h"
#include "crossdiv/verification/comparisons/isosurface_comparison.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::cli {
namespace {

struct IsosurfaceArgs {
    std::string input, inside = "below", rule = "decider", against, volume_out, out;
    std::optional<double> level;
    std::optional<int> resolution;
    void add_to(CLI::App& app) {
        app.add_option("input", input, "implicit:sphere|torus|genus2|gyroid|ambiguous, or a volume file "
                                       "(MetaImage .mhd/.mha, NRRD .nrrd/.nhdr with raw samples)")->required();
        app.add_option("--isovalue", level, "The isovalue (default 0 for implicit inputs; required for a volume file)");
        app.add_option("--res", resolution, "Samples along the longest side of an implicit surface's box (default 65)");
        app.add_option("--inside", inside, "Where the solid is: below the level (distances) or above (densities)")
            ->check(CLI::IsMember({"below", "above"}));
        app.add_option("--rule", rule, "Ambiguous faces: decider (asymptotic decider) or minority (the 1987 table's "
                                       "folding, which leaves holes)")->check(CLI::IsMember({"decider", "minority"}));
        app.add_option("--against", against, "Compare with scikit-image's marching cubes: skimage (Lewiner's MC33), "
                                             "skimage-lorensen (the 1987 table)");
        app.add_option("--write-volume", volume_out, "Write the sampled grid as a volume file (.mhd or .nrrd)");
        app.add_option("-o,--output", out, "Output mesh (.obj, .off, .ply)");
    }
};

int run_isosurface(const IsosurfaceArgs& a) {
    const std::vector<std::string> references = split_commas(a.against);
    for (const std::string& ref : references)
        if (ref != "skimage" && ref != "skimage-lorensen")
            throw InputError("--against " + ref + ": the isosurface references are skimage and skimage-lorensen");
    const datasets::ImplicitSurface* surface = nullptr;
    ScalarGrid grid;
    if (a.input.starts_with("implicit:")) {
        const std::string name = a.input.substr(9);
        const int res = a.resolution.value_or(65);
        if (name == "ambiguous") {
            grid = datasets::ambiguous_field(res);
        } else {
            surface = &datasets::implicit_surface(name);
            grid = datasets::sample(*surface, res);
        }
    } else {
        if (a.resolution) throw InputError("--res samples an implicit surface; " + a.input + " has its own grid");
        if (!a.level) throw InputError("--isovalue is needed for a volume file: the isovalue depends on what its samples measure");
        grid = read_volume(a.input);
    }
    IsosurfaceOptions options{a.level.value_or(0), a.inside == "below" ? InsideIs::Below : InsideIs::Above,
                              ambiguous_face_rule_from_string(a.rule)};
    const Isosurface iso = marching_cubes(grid, options);
    const verification::IsosurfaceMeasures m = verification::measure_isosurface(iso.mesh);

    fmt::print("{}: {} x {} x {} samples, spacing {:.6g} {:.6g} {:.6g}, level {:.17g} ({} inside)\n", a.input, grid.size[0],
               grid.size[1], grid.size[2], grid.spacing.x(), grid.spacing.y(), grid.spacing.z(), options.level, a.inside);
    fmt::print("marching cubes ({}): {} vertices, {} triangles; {} ambiguous faces ({} joined), {} polygons centred\n", a.rule,
               m.vertices, m.faces, iso.ambiguous_faces, iso.joined_faces, iso.centred_polygons);
    fmt::print("  Euler characteristic {}, {} boundary edges in {} loops, {} mesh errors{}\n", m.euler, m.boundary_edges,
               m.boundary_loops, m.mesh_errors, m.first_error.empty() ? "" : " (first: " + m.first_error + ")");
    if (m.boundary_edges == 0) fmt::print("  enclosed volume {:.15g}\n", m.volume);
    bool failed = m.mesh_errors > 0 && options.rule == AmbiguousFaceRule::AsymptoticDecider;
    if (surface) {
        double worst = 0;
        for (const Vec3& p : iso.mesh.positions) worst = std::max(worst, datasets::distance_to(*surface, p));
        fmt::print("  {}: largest vertex distance to the surface {:.3e} ({:.3g} cells)\n", surface->description, worst,
                   worst / grid.spacing.maxCoeff());
        if (surface->euler_characteristic) {
            const bool right = m.euler == *surface->euler_characteristic && m.boundary_edges == 0;
            fmt::print("  closed surface of Euler characteristic {}: {}\n", *surface->euler_characteristic,
                       right ? "matched" : "NOT matched (the grid may not resolve it, or the rule left holes)");
            failed |= !right && options.rule == AmbiguousFaceRule::AsymptoticDecider;
        }
        if (surface->volume && m.boundary_edges == 0)
            fmt::print("  exact volume {:.15g}: relative error {:.3e}\n", *surface->volume,
                       std::abs(m.volume - *surface->volume) / *surface->volume);
    }
    for (const std::string& ref : references) {
        const std::string method = ref == "skimage" ? "lewiner" : "lorensen";
        const verification::IsosurfaceRun run =
            verification::run_isosurface(verification::find_implementation("skimage"), grid, options, method);
        if (run.outcome.status != verification::RunStatus::Ok) {
            fmt::print("  {}: {}\n", ref, run.outcome.summary());
            continue;
        }
        const verification::IsosurfaceComparison c =
            verification::compare_isosurfaces(iso.mesh, run.mesh, grid);
        fmt::print("  {} ({:.2f} s): {}: {}\n", ref, run.outcome.seconds, to_string(c.agreement), c.explanation);
    }
    if (!a.volume_out.empty()) {
        if (a.volume_out.ends_with(".nrrd")) write_nrrd(a.volume_out, grid);
        else if (a.volume_out.ends_with(".mhd")) write_metaimage(a.volume_out, grid);
        else throw InputError("--write-volume " + a.volume_out + ": write .mhd (MetaImage) or .nrrd");
        fmt::print("wrote {}\n", a.volume_out);
    }
    if (!a.out.empty()) {
        write_mesh(a.out, to_poly_mesh(iso.mesh));
        fmt::print("wrote {}\n", a.out);
    }
    return failed ? 1 : 0;
}

}  // namespace

void add_isosurface_command(CLI::App& app, int& status) {
    add_command<IsosurfaceArgs>(app, "isosurface",
                                "Marching cubes with the asymptotic decider over an implicit surface or a volume file; "
                                "watertightness, topology, distance to the exact surface, scikit-image compared",
                                status, run_isosurface);
}

}  // namespace crossdiv::cli
