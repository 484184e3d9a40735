// Subdivision surface fitting as the harness runs it: the checkerboard prediction by hand, the
// control mesh CGAL's edge collapse makes, CGAL's Hausdorff distance against our own distances,
// and the fitting study's checks and tables on a small target.
#include <gtest/gtest.h>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/comparisons/limit_fitting_run.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/studies/fitting_study.h"

namespace crossdiv::verification {
namespace {

TEST(CheckerboardKernel, OnlyClosedValenceThreeBipartiteMeshes) {
    EXPECT_TRUE(has_checkerboard_kernel(datasets::bundled_mesh("quad-cube")));
    // Refined, the cube has valence-4 vertices; the prism's pentagons are odd cycles; the
    // tetrahedron's triangles too; a grid has a boundary.
    EXPECT_FALSE(has_checkerboard_kernel(catmull_clark_subdivide(datasets::bundled_mesh("quad-cube"), {}, 1)));
    EXPECT_FALSE(has_checkerboard_kernel(datasets::bundled_mesh("prism-5")));
    EXPECT_FALSE(has_checkerboard_kernel(datasets::bundled_mesh("tetrahedron")));
    EXPECT_FALSE(has_checkerboard_kernel(datasets::bundled_mesh("quad-grid")));
}

#ifdef CROSSDIV_HAS_CGAL
TEST(FittingRun, CgalControlMeshAndHausdorffAgreeWithOurDistances) {
    const std::vector<const Implementation*> cgal = references_with(&Capabilities::hausdorff_distance);
    ASSERT_EQ(cgal.size(), 1u);
    EXPECT_EQ(references_with(&Capabilities::simplification), cgal);
    const TriMesh target = loop_subdivide(to_tri_mesh(datasets::bundled_mesh("torus")), {}, 1);
    const TriMesh control = coarse_control(target, 200, *cgal[0]);
    EXPECT_LT(control.num_faces() * 3 / 2, 200);
    EXPECT_EQ(topology_type(control), topology_type(target));
    // Asked for less than a torus can have, the edge collapse stops where every further
    // collapse would change the topology: still a torus, of at least 7 vertices (the fewest a
    // triangulated torus has, Moebius 1861 / Csaszar 1949).
    const TriMesh smallest = coarse_control(target, 3, *cgal[0]);
    EXPECT_EQ(topology_type(smallest), topology_type(target));
    EXPECT_GE(smallest.num_vertices(), 7);

    const FittingRun run = run_fitting(Scheme::Loop, control, target, 2, 4, cgal[0]);
    ASSERT_EQ(run.hausdorff.size(), 5u);
    EXPECT_EQ(energy_increases(run.result, target, run.sampling.num_samples()), 0);
    const double diagonal = bounding_box_diagonal(target.positions);
    for (size_t k = 0; k < run.hausdorff.size(); ++k) {
        const FittingStep& s = run.result.steps[k];
        // CGAL samples both meshes' vertices (and more), so it is at least our largest vertex distance.
        EXPECT_GE(run.hausdorff[k], std::max(s.max_sample_to_target, s.max_target_to_surface) -
                                        tolerances::kPointMeshDistanceAgreement * diagonal) << k;
    }
    EXPECT_LT(run.hausdorff.back(), run.hausdorff.front());
    // A target and control of different topology types are refused, naming both.
    EXPECT_THROW(run_fitting(Scheme::Loop, to_tri_mesh(datasets::bundled_mesh("icosahedron")), target, 2, 1, nullptr), InputError);
    EXPECT_THROW(fitting_sampling(Scheme::DooSabin, control, 1), InputError);
}
#else
TEST(FittingRun, WithoutCgalNoReferenceMeasuresOrSimplifies) {
    EXPECT_TRUE(references_with(&Capabilities::hausdorff_distance).empty());
    EXPECT_TRUE(references_with(&Capabilities::simplification).empty());
}
#endif

TEST(FittingStudy, ChecksAndTablesOnASmallTarget) {
    const TriMesh torus = loop_subdivide(to_tri_mesh(datasets::bundled_mesh("torus")), {}, 1);
    const CheckReport r = fitting_study({{"torus", torus}}, {150, 100000}, 3);
    for (const Check& c : r.checks) EXPECT_TRUE(c.pass() || c.decided) << c.subject << " " << c.check << ": " << c.note;
    const nlohmann::json& recovery = r.tables["fitting_recovery"];
    ASSERT_GT(recovery.size(), 40u);
    for (const nlohmann::json& row : recovery) {
        if (!row.contains("singular")) {
            EXPECT_LE(row["error"].get<double>(), tolerances::kFittingRecovery) << row["mesh"];
        }
    }
    const nlohmann::json& rows = r.tables["fitting_iterations"];
#ifndef CROSSDIV_HAS_CGAL
    // Without a simplifying reference nothing is fitted, and the study says why.
    EXPECT_TRUE(rows.empty());
    ASSERT_FALSE(r.checks.empty());
    EXPECT_EQ(r.checks.back().outcome().verdict, Verdict::RefUnavailable);
    return;
#endif
    // The budget above half the target's edges is skipped: one control mesh, two schemes.
    ASSERT_EQ(rows.size(), 2u);
    for (const nlohmann::json& row : rows) {
        EXPECT_EQ(row["steps"].size(), 4u);
        EXPECT_LT(row["steps"].back()["rms_target_to_surface"].get<double>(), row["steps"][0]["rms_target_to_surface"].get<double>());
    }
}

}  // namespace
}  // namespace crossdiv::verification
