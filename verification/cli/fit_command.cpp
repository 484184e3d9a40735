// crossdiv fit TARGET (--control MESH | --edges N) [--scheme loop|catmull-clark] [--levels L]
//                     [--iterations K] [--against cgal] [-o CONTROL] [--surface SURFACE]
#include "fit_command.h"

#include <fmt/format.h>

#include <optional>

#include "command.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/verification/comparisons/limit_fitting_run.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::cli {
namespace {

struct FitArgs {
    std::string target, control, scheme = "loop", against, out, surface;
    std::optional<int> edges;
    int levels = 2, iterations = 8;
    void add_to(CLI::App& app) {
        app.add_option("target", target, "The dense triangle mesh to approximate: file or bundled:NAME")->required();
        app.add_option("--control", control, "The coarse control mesh (triangles, the target's topology type)");
        app.add_option("--edges", edges, "Make the control mesh by simplifying the target (CGAL's edge collapse) to fewer "
                                         "than N edges");
        app.add_option("--scheme", scheme, "loop or catmull-clark")->check(CLI::IsMember({"loop", "catmull-clark"}));
        app.add_option("--levels", levels, "Sample the limit surface at the vertices of this level (default 2)")
            ->check(CLI::Range(0, 6));
        app.add_option("--iterations", iterations, "Correspondence-and-solve rounds (default 8)")->check(CLI::Range(0, 1000));
        app.add_option("--against", against, "Measure each iteration's two-sided Hausdorff distance with this reference (cgal)");
        app.add_option("-o,--output", out, "Write the fitted control mesh");
        app.add_option("--surface", surface, "Write the fitted limit surface (the samples' mesh)");
    }
};

int run_fit(const FitArgs& a) {
    if (a.control.empty() == !a.edges)
        throw InputError("give the control mesh (--control MESH) or how coarse to make it from the target (--edges N), one of them");
    const verification::Scheme scheme = verification::scheme_from_string(a.scheme);
    const std::vector<std::string> refs = split_commas(a.against);
    if (refs.size() > 1) throw InputError("--against takes one Hausdorff reference");
    const verification::Implementation* hausdorff =
        refs.empty() ? nullptr
                     : verification::select_references(&verification::Capabilities::hausdorff_distance, refs, "Hausdorff distance")[0];
    const TriMesh target = to_tri_mesh(verification::load_input(a.target, verification::UnknownTags::Ignore), "fitting");
    TriMesh control;
    if (a.edges) {
        const std::vector<const verification::Implementation*> simplifiers =
            verification::references_with(&verification::Capabilities::simplification);
        if (simplifiers.empty()) throw InputError("--edges needs a simplifying reference (CGAL), and this build has none");
        control = verification::coarse_control(target, *a.edges, *simplifiers[0]);
        fmt::print("control: {}'s edge collapse of the target to {} vertices, {} triangles\n", simplifiers[0]->name(),
                   control.num_vertices(), control.num_faces());
    } else {
        control = to_tri_mesh(verification::load_input(a.control, verification::UnknownTags::Ignore), "fitting");
    }
    const verification::TopologyType type = verification::topology_type(target);
    fmt::print("target {}: {} vertices, {} triangles, Euler characteristic {}, {} boundary loops\n", a.target,
               target.num_vertices(), target.num_faces(), type.euler, type.boundary_loops);

    const verification::FittingRun run = verification::run_fitting(scheme, control, target, a.levels, a.iterations, hausdorff);
    const double diagonal = bounding_box_diagonal(target.positions);
    fmt::print("{} limit surface sampled at level {} ({} samples of {} control points); distances relative to the target's "
               "diagonal {:.6g}\n", a.scheme, a.levels, run.sampling.num_samples(), control.num_vertices(), diagonal);
    fmt::print("{:>5} {:>13} {:>12} {:>12} {:>12} {:>12}{}\n", "step", "energy", "rms s->t", "max s->t", "rms t->s", "max t->s",
               run.hausdorff.empty() ? "" : fmt::format(" {:>14}", "hausdorff(" + run.hausdorff_by + ")"));
    for (size_t k = 0; k < run.result.steps.size(); ++k) {
        const FittingStep& s = run.result.steps[k];
        fmt::print("{:>5} {:>13.6e} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e}{}\n", k, s.energy, s.rms_sample_to_target / diagonal,
                   s.max_sample_to_target / diagonal, s.rms_target_to_surface / diagonal, s.max_target_to_surface / diagonal,
                   run.hausdorff.empty() ? "" : fmt::format(" {:>14.4e}", run.hausdorff[k] / diagonal));
    }
    if (!run.hausdorff_error.empty()) fmt::print("{} refused: {}\n", run.hausdorff_by, run.hausdorff_error);
    const int increases = verification::energy_increases(run.result, target, run.sampling.num_samples());
    if (increases > 0) fmt::print("the distance energy increased at {} step(s): each step must not increase it\n", increases);
    if (!a.out.empty()) {
        TriMesh fitted = control;
        fitted.positions = run.result.steps.back().control;
        write_mesh(a.out, to_poly_mesh(fitted));
        fmt::print("wrote {} (the fitted control mesh)\n", a.out);
    }
    if (!a.surface.empty()) {
        write_mesh(a.surface, to_poly_mesh(run.fitted_surface()));
        fmt::print("wrote {} (its limit surface at level {})\n", a.surface, a.levels);
    }
    return increases > 0 ? 1 : 0;
}

}  // namespace

void add_fit_command(CLI::App& app, int& status) {
    add_command<FitArgs>(app, "fit",
                         "Fit a Loop or Catmull-Clark limit surface to a target mesh (least squares on the limit stencils, "
                         "closest-point iterations), with each iteration's distances and CGAL's Hausdorff distance",
                         status, run_fit);
}

}  // namespace crossdiv::cli
