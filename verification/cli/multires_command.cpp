// crossdiv multires BASE [--levels L] [--fine FINE | --detail A] [--vertex V --move X,Y,Z] [-o OUT]
#include "multires_command.h"

#include <fmt/format.h>

#include "command.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/verification/comparisons/multiresolution_checks.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::cli {
namespace {

struct MultiresArgs {
    std::string base, fine, out;
    int levels = 3, vertex = 0;
    double detail = 0.02, waves = 40;
    std::vector<double> move{0, 0, 0};
    void add_to(CLI::App& app) {
        app.add_option("base", base, "The base triangle mesh (file or bundled:NAME)")->required();
        app.add_option("--levels", levels, "Loop levels of the hierarchy (default 3)")->check(CLI::Range(1, 6));
        app.add_option("--fine", fine, "The finest level's positions: a mesh with the hierarchy's connectivity (its "
                                       "triangles must be those of the base refined --levels times, one level at a time)");
        app.add_option("--detail", detail, "Without --fine: the subdivided base moved along its normals by this times the "
                                           "diagonal times sin(k x) sin(k y) sin(k z) (default 0.02)");
        app.add_option("--waves", waves, "k times the diagonal in that detail (default 40)");
        app.add_option("--vertex", vertex, "The base vertex to edit (default 0)");
        app.add_option("--move", move, "The edit: X,Y,Z added to the base vertex (default 0,0,0)")->delimiter(',')->expected(3);
        app.add_option("-o,--output", out, "Write the finest level after the edit");
    }
};

int run_multires(const MultiresArgs& a) {
    const TriMesh base = to_tri_mesh(verification::load_input(a.base, verification::UnknownTags::Ignore), "multiresolution");
    const LoopMultiresolution m(base, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, a.levels);
    std::vector<Vec3> finest;
    if (!a.fine.empty()) {
        const TriMesh fine = to_tri_mesh(verification::load_input(a.fine, verification::UnknownTags::Ignore), "multiresolution");
        if (fine.triangles != m.triangles(a.levels))
            throw InputError(fmt::format("{}: its {} triangles are not the connectivity of {} refined {} times ({} triangles, "
                                         "vertices numbered one level at a time)",
                                         a.fine, fine.num_faces(), a.base, a.levels, m.triangles(a.levels).size()));
        finest = fine.positions;
    } else {
        finest = verification::detailed_surface(m, base.positions, a.detail, a.waves);
    }
    const Vec3 edit(a.move[0], a.move[1], a.move[2]);
    const verification::MultiresolutionMeasures r = verification::measure_multiresolution(m, finest, a.vertex, edit);
    fmt::print("{}: {} base vertices, {} at level {}\n", a.base, m.num_vertices(0), m.num_vertices(a.levels), a.levels);
    for (size_t l = 0; l < r.detail_rms.size(); ++l) fmt::print("  level {} detail rms {:.4e}\n", l + 1, r.detail_rms[l]);
    const bool round_trip = r.round_trip <= tolerances::kMultiresolutionRoundTrip;
    const bool rigid = r.rigid_motion <= tolerances::kMultiresolutionRigidMotion;
    fmt::print("decompose then recompose: {:.3e} of the diagonal ({})\n", r.round_trip,
               round_trip ? "the input back" : "beyond the tolerance");
    fmt::print("a rigid motion against decompose and recompose: {:.3e} ({})\n", r.rigid_motion, rigid ? "commutes" : "does not commute");
    fmt::print("moving base vertex {} by ({}, {}, {}): {} finest vertices moved; predicted reach {}, subdivision support {}; "
               "{} outside the reach\n", a.vertex, edit.x(), edit.y(), edit.z(), r.moved, r.reach, r.support, r.outside_reach);
    fmt::print("the same edit with zero details: {} moved, {} differ from the subdivision support\n", r.smooth_moved, r.smooth_mismatch);
    if (!a.out.empty()) {
        TriMesh out;
        out.positions = r.edited;
        out.triangles = m.triangles(a.levels);
        write_mesh(a.out, to_poly_mesh(out));
        fmt::print("wrote {}\n", a.out);
    }
    return round_trip && rigid && r.outside_reach == 0 && r.smooth_mismatch == 0 ? 0 : 1;
}

}  // namespace

void add_multires_command(CLI::App& app, int& status) {
    add_command<MultiresArgs>(app, "multires",
                              "Loop multiresolution editing (Zorin et al. 1997): decompose, edit a base vertex, recompose; "
                              "round trip, rigid motion and the edit's reach measured",
                              status, run_multires);
}

}  // namespace crossdiv::cli
