// crossdiv curvature IN [--against cgal] [--csv OUT.csv] [--color gaussian|mean|k1|k2 -o OUT.obj]
#include "curvature_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include "command.h"
#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/discrete_curvature.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/isolated_calls.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::cli {
namespace {

struct CurvatureArgs {
    std::string input, against, csv, color, out;
    void add_to(CLI::App& app) {
        app.add_option("input", input, "Triangle mesh: file (.obj, .off, .dae, .ply, .stl) or bundled:NAME")->required();
        app.add_option("--against", against, "Comma-separated curvature estimators to compare with (cgal)");
        app.add_option("--csv", csv, "Write one row per vertex: status, mixed area, angle defect, H, K, k1, k2, "
                                     "the k1 direction and the normal");
        app.add_option("--color", color, "Colour the vertices by this curvature (blue negative, white 0, red positive, "
                                         "scaled to the 95th percentile of |value|, grey where not estimated); needs -o OUT.obj")
            ->check(CLI::IsMember({"gaussian", "mean", "k1", "k2"}));
        app.add_option("-o,--output", out, "Output mesh with vertex colours (OBJ 'v x y z r g b')");
    }
};

/// Blue (-bound) .. white (0) .. red (+bound), the values beyond clamped.
Vec3 diverging_color(double value, double bound) {
    const double t = bound > 0 ? std::clamp(value / bound, -1.0, 1.0) : 0.0;
    return t >= 0 ? Vec3(1.0, 1.0 - t, 1.0 - t) : Vec3(1.0 + t, 1.0 + t, 1.0);
}

const std::vector<double>& picked(const DiscreteCurvature& c, const std::string& name) {
    return name == "gaussian" ? c.gaussian : name == "mean" ? c.mean : name == "k1" ? c.k1 : c.k2;
}

int run_curvature(const CurvatureArgs& a) {
    if (!a.color.empty() && a.out.empty()) throw InputError("--color " + a.color + " needs -o OUT.obj");
    if (!a.out.empty() && a.color.empty()) throw InputError("-o " + a.out + " needs --color: the output is the coloured mesh");
    if (!a.out.empty() && !a.out.ends_with(".obj"))
        throw InputError("--color writes vertex colours as OBJ 'v x y z r g b'; " + a.out + " is not an .obj file");
    const TriMesh mesh = to_tri_mesh(verification::load_input(a.input, verification::UnknownTags::Ignore), "discrete curvature");
    const DiscreteCurvature c = discrete_curvature(mesh);

    int count[4] = {0, 0, 0, 0};
    for (CurvatureStatus s : c.status) ++count[static_cast<int>(s)];
    fmt::print("{}: {} vertices: {} estimated, {} boundary, {} isolated, {} degenerate\n", a.input, mesh.num_vertices(),
               count[0], count[1], count[2], count[3]);
    const int chi = c.euler_characteristic;
    const double total = c.total_angle_defect(), error = std::abs(total - 2 * std::numbers::pi * chi);
    const double bound = tolerances::gauss_bonnet_bound(mesh.num_faces());
    fmt::print("Gauss-Bonnet: sum of angle defects {:.15g} = 2 pi chi (chi = {}) to {:.3e} ({})\n", total, chi, error,
               error <= bound ? "holds to rounding" : fmt::format("beyond the rounding bound {:.3e}", bound));
    for (const char* name : {"mean", "gaussian", "k1", "k2"}) {
        const std::vector<double>& v = picked(c, name);
        double lo = INFINITY, hi = -INFINITY;
        int at_lo = -1, at_hi = -1;
        for (int i = 0; i < mesh.num_vertices(); ++i) {
            if (c.status[i] != CurvatureStatus::Estimated) continue;
            if (v[i] < lo) lo = v[i], at_lo = i;
            if (v[i] > hi) hi = v[i], at_hi = i;
        }
        if (at_lo >= 0) fmt::print("  {:<9} {:.6g} (vertex {}) .. {:.6g} (vertex {})\n", name, lo, at_lo, hi, at_hi);
    }

    const std::vector<std::string> refs = split_commas(a.against);
    if (!refs.empty())
        for (const verification::Implementation* ref :
             verification::select_references(&verification::Capabilities::curvatures, refs, "curvature estimator")) {
            const verification::IsolatedValue<verification::PrincipalCurvatures> run = verification::curvatures_isolated(*ref, mesh);
            if (!run.value) {
                fmt::print("  {} {}: {}\n", ref->name(),
                           run.outcome.status == verification::RunStatus::Rejected ? "refused the mesh" : "failed",
                           run.outcome.failure_explanation());
                continue;
            }
            {
                const verification::PrincipalCurvatures& r = *run.value;
                double dh = 0, dk = 0;
                int both = 0, worst = -1;
                for (int i = 0; i < mesh.num_vertices(); ++i) {
                    if (c.status[i] != CurvatureStatus::Estimated || !r.estimated[i]) continue;
                    ++both;
                    if (std::abs(r.mean[i] - c.mean[i]) > dh) dh = std::abs(r.mean[i] - c.mean[i]), worst = i;
                    dk = std::max(dk, std::abs(r.gaussian[i] - c.gaussian[i]));
                }
                fmt::print("  {} ({}): on {} vertices max |H diff| {:.3e} (vertex {}), max |K diff| {:.3e}\n", ref->name(),
                           r.method, both, dh, worst, dk);
            }
        }

    if (!a.csv.empty()) {
        OutputFile file(a.csv);
        std::ostream& out = file.stream();
        fmt::print(out, "vertex,status,mixed_area,angle_defect,mean,gaussian,k1,k2,d1x,d1y,d1z,nx,ny,nz\n");
        for (int i = 0; i < mesh.num_vertices(); ++i) {
            const Vec3 &d = c.direction1[i], &n = c.normal[i];
            fmt::print(out, "{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", i,
                      to_string(c.status[i]), c.mixed_area[i], c.angle_defect[i], c.mean[i], c.gaussian[i], c.k1[i], c.k2[i],
                      d.x(), d.y(), d.z(), n.x(), n.y(), n.z());
        }
        file.close();
        fmt::print("wrote {}\n", a.csv);
    }
    if (!a.out.empty()) {
        // The scale is the 95th percentile of |value|: a few needle triangles in a scanned mesh
        // reach curvatures 1000 times the rest, and would leave every other vertex white.
        const std::vector<double>& v = picked(c, a.color);
        std::vector<double> magnitude;
        for (int i = 0; i < mesh.num_vertices(); ++i)
            if (c.status[i] == CurvatureStatus::Estimated) magnitude.push_back(std::abs(v[i]));
        double scale = 0;
        if (!magnitude.empty()) {
            const auto at = magnitude.begin() + static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(magnitude.size() - 1));
            std::nth_element(magnitude.begin(), at, magnitude.end());
            scale = *at;
        }
        PolyMesh coloured = to_poly_mesh(mesh);
        coloured.colors.resize(coloured.positions.size());
        for (int i = 0; i < mesh.num_vertices(); ++i)
            coloured.colors[i] = c.status[i] == CurvatureStatus::Estimated ? diverging_color(v[i], scale) : Vec3(0.5, 0.5, 0.5);
        write_mesh(a.out, coloured);
        fmt::print("wrote {} coloured by {} curvature (blue {:.6g} .. red {:.6g}, the 95th percentile of |value|; beyond it clamped)\n", a.out, a.color, -scale, scale);
    }
    return error <= bound ? 0 : 1;
}

}  // namespace

void add_curvature_command(CLI::App& app, int& status) {
    add_command<CurvatureArgs>(app, "curvature",
                               "Discrete mean, Gaussian and principal curvatures (Meyer et al. 2002), Gauss-Bonnet, "
                               "against CGAL's jet fitting",
                               status, run_curvature);
}

}  // namespace crossdiv::cli
