// The multiresolution study: decompose, recompose, move rigidly and edit, on every bundled
// triangle mesh; the torus edited for the figure.
#include "crossdiv/verification/studies/multiresolution_study.h"

#include <fmt/format.h>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/comparisons/multiresolution_checks.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/studies/studies.h"

namespace crossdiv::verification {

CheckReport multiresolution_study() {
    CheckReport out;
    nlohmann::json rows = nlohmann::json::array(), figures = nlohmann::json::array();
    constexpr int kLevels = 3;
    for (const datasets::BundledMesh& b : datasets::bundled_meshes()) {
        const TriMesh base = to_tri_mesh(b.mesh, "multiresolution");
        nlohmann::json row = {{"mesh", b.name}, {"levels", kLevels}, {"base_vertices", base.num_vertices()}};
        try {
            const LoopMultiresolution m(base, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, kLevels);
            const std::vector<Vec3> finest = detailed_surface(m, base.positions, 0.02, 40);
            // Base vertex 0 moved by a fifth of the diagonal, along no axis.
            const double diagonal = bounding_box_diagonal(base.positions);
            const MultiresolutionMeasures r = measure_multiresolution(m, finest, 0, 0.2 * diagonal * Vec3(0.6, 0.0, 0.8));
            row.update({{"finest_vertices", m.num_vertices(kLevels)}, {"round_trip", r.round_trip}, {"rigid_motion", r.rigid_motion},
                        {"detail_rms", r.detail_rms}, {"moved", r.moved}, {"reach", r.reach}, {"support", r.support},
                        {"outside_reach", r.outside_reach}, {"smooth_moved", r.smooth_moved}, {"smooth_mismatch", r.smooth_mismatch}});
            out.checks.push_back({b.name, "round-trip", "exact", r.round_trip, tolerances::kMultiresolutionRoundTrip, "rel",
                                  "recompose(decompose(P)) against P, 3 levels, a detail along the normals"});
            out.checks.push_back({b.name, "rigid-motion-commutes", "exact", r.rigid_motion, tolerances::kMultiresolutionRigidMotion,
                                  "rel", "decompose and recompose of the rotated and shifted surface against the rotated and "
                                         "shifted one; detail coordinates against the unmoved ones"});
            out.checks.push_back(count_check(b.name, "edit-within-reach", "prediction", r.outside_reach,
                                             fmt::format("vertices an edit of base vertex 0 moved beyond its predicted reach "
                                                         "({} moved, reach {}, subdivision support {})", r.moved, r.reach, r.support)));
            out.checks.push_back(count_check(b.name, "smooth-edit-is-the-support", "subdivision support", r.smooth_mismatch,
                                             "with zero details, vertices moved differ from the subdivision support"));
            if (b.name == "torus") {
                TriMesh before, after;
                before.triangles = after.triangles = m.triangles(kLevels);
                before.positions = finest;
                after.positions = r.edited;
                TriMesh smooth = after;
                smooth.positions = m.subdivide(m.decompose(r.edited).base);
                figures.push_back({{"title", "detailed torus, 3 levels"}, {"mesh", mesh_json(to_poly_mesh(before))}});
                figures.push_back({{"title", "base vertex 0 moved: the detail follows"}, {"mesh", mesh_json(to_poly_mesh(after))}});
                figures.push_back({{"title", "its base level subdivided (no detail)"}, {"mesh", mesh_json(to_poly_mesh(smooth))}});
            }
        } catch (const InputError& e) {
            row["error"] = e.what();
            out.checks.push_back(count_check(b.name, "decomposed", "ours", 1, e.what()));
        }
        rows.push_back(row);
        out.subjects.push_back(b.name);
    }
    out.tables["multiresolution"] = rows;
    out.tables["multiresolution_figure"] = figures;
    return out;
}

}  // namespace crossdiv::verification
