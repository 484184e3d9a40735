// Isosurfaces compared and studied: the classification of two meshes of the same samples on
// hand-made differences, the outcome each scikit-image run counts as, scikit-image itself on a
// sphere, and the isosurface study's checks and tables.

#include <gtest/gtest.h>

#include <algorithm>

#include "crossdiv/datasets/implicit_surfaces.h"
#include "crossdiv/verification/comparisons/isosurface_comparison.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/studies/isosurface_study.h"

namespace crossdiv::verification {
namespace {

ScalarGrid sphere_grid(int res) { return datasets::sample(datasets::implicit_surface("sphere"), res); }

TEST(CompareIsosurfaces, ClassifiesHandMadeDifferences) {
    const ScalarGrid grid = sphere_grid(9);
    const TriMesh m = marching_cubes(grid, {}).mesh;
    const IsosurfaceComparison same = compare_isosurfaces(m, m, grid);
    EXPECT_EQ(same.agreement, IsosurfaceAgreement::Identical);
    EXPECT_EQ(same.max_vertex_distance, 0);
    EXPECT_EQ(same.ours.euler, 2);

    // The same triangles listed from another corner and in another order are identical.
    TriMesh rotated = m;
    for (Triangle& t : rotated.triangles) t = {t[1], t[2], t[0]};
    std::reverse(rotated.triangles.begin(), rotated.triangles.end());
    EXPECT_EQ(compare_isosurfaces(m, rotated, grid).agreement, IsosurfaceAgreement::Identical);

    // Every triangle reversed: the same vertices and topology, each face the other way.
    TriMesh reversed = m;
    for (Triangle& t : reversed.triangles) std::swap(t[1], t[2]);
    const IsosurfaceComparison r = compare_isosurfaces(m, reversed, grid);
    EXPECT_EQ(r.agreement, IsosurfaceAgreement::OtherTriangulation);
    EXPECT_EQ(r.reversed_faces, m.num_faces());

    // One vertex moved along its grid edge by more than float32 rounding: another crossing.
    TriMesh moved = m;
    moved.positions[5] += 1e-4 * (moved.positions[5] - moved.positions[moved.triangles[0][0]]).normalized();
    const IsosurfaceComparison v = compare_isosurfaces(m, moved, grid);
    EXPECT_EQ(v.agreement, IsosurfaceAgreement::OtherVertices);
    EXPECT_EQ(v.ours_unmatched, 1);
}

TEST(CompareIsosurfaces, AQuadSplitTheOtherWayIsAnotherTriangulation) {
    // Corners 0 and 1 of one cube inside: a quad round their edge, two triangles either way.
    ScalarGrid grid;
    grid.size = {2, 2, 2};
    grid.values = {-1, -1, 1, 1, 1, 1, 1, 1};
    const TriMesh m = marching_cubes(grid, {}).mesh;
    ASSERT_EQ(m.num_faces(), 2);
    // A fan from a: triangles a b c and a d b round the quad a d b c; the other diagonal, d c,
    // makes d b c and d c a.
    const Triangle t0 = m.triangles[0], t1 = m.triangles[1];
    ASSERT_EQ(t0[0], t1[0]);
    ASSERT_EQ(t0[1], t1[2]);
    const int a = t0[0], b = t0[1], c = t0[2], d = t1[1];
    TriMesh other = m;
    other.triangles = {{d, b, c}, {d, c, a}};
    const IsosurfaceComparison x = compare_isosurfaces(m, other, grid);
    EXPECT_EQ(x.agreement, IsosurfaceAgreement::OtherTriangulation);
    EXPECT_EQ(x.faces_only_ours, 2);
    EXPECT_EQ(x.faces_only_theirs, 2);
}

TEST(SkimageOutcome, FailuresAreTheReferencesAndVerticesDecide) {
    IsosurfaceRun run;
    run.outcome.status = RunStatus::Unavailable;
    EXPECT_EQ(skimage_outcome(run, nullptr).verdict, Verdict::RefUnavailable);
    run.outcome.status = RunStatus::Timeout;
    EXPECT_EQ(skimage_outcome(run, nullptr).verdict, Verdict::RefCrashed);
    run.outcome.status = RunStatus::NonFiniteOutput;
    EXPECT_EQ(skimage_outcome(run, nullptr).verdict, Verdict::RefInvalidOutput);
    run.outcome.status = RunStatus::Ok;
    IsosurfaceComparison c;
    c.agreement = IsosurfaceAgreement::OtherTriangulation;
    EXPECT_EQ(skimage_outcome(run, &c).cls, DivergenceClass::Triangulation);
    c.agreement = IsosurfaceAgreement::OtherVertices;
    EXPECT_EQ(skimage_outcome(run, &c).cls, DivergenceClass::Unexplained);
}

TEST(IsosurfaceImplementations, ScikitImageIsOneAndTheOthersRefuse) {
    // scikit-image is reached as every implementation is: through the registry, by capability.
    const std::vector<const Implementation*> have = references_with(&Capabilities::isosurface);
    ASSERT_EQ(have.size(), 1u);
    EXPECT_EQ(have[0]->name(), "skimage");
    EXPECT_EQ(have[0]->kind(), ImplementationKind::Program);
    EXPECT_TRUE(have[0]->confines_itself());
    const ScalarGrid grid = sphere_grid(5);
    // A method it lacks, and an implementation without marching cubes: refusals, recorded.
    EXPECT_EQ(run_isosurface(*have[0], grid, {}, "dual-contouring").outcome.status, RunStatus::Rejected);
    const IsosurfaceRun core = run_isosurface(core_implementation(), grid, {}, "lewiner");
    EXPECT_EQ(core.outcome.status, RunStatus::Rejected);
    EXPECT_NE(core.outcome.message.find("core has no isosurfaces"), std::string::npos) << core.outcome.message;
}

// scikit-image (installed by run.sh) on the same samples: every crossing matches to float32
// rounding, and its faces are oriented as ours.
TEST(SkimageMarchingCubes, MatchesEveryCrossingOfASphere) {
    const ScalarGrid grid = sphere_grid(21);
    const IsosurfaceRun run = run_isosurface(find_implementation("skimage"), grid, {}, "lewiner");
    ASSERT_EQ(run.outcome.status, RunStatus::Ok) << run.outcome.summary();
    const IsosurfaceComparison c = compare_isosurfaces(marching_cubes(grid, {}).mesh, run.mesh, grid);
    EXPECT_EQ(c.ours_unmatched + c.theirs_unmatched, 0) << c.explanation;
    EXPECT_GT(c.max_vertex_distance, 0);  // float32 is not double
    EXPECT_EQ(c.reversed_faces, 0) << c.explanation;
    EXPECT_EQ(c.theirs.euler, 2);
    EXPECT_NE(c.agreement, IsosurfaceAgreement::OtherTopology);
}

TEST(IsosurfaceStudy, EveryCheckHoldsAndTheMinorityRuleLeavesHoles) {
    const CheckReport r = isosurface_study();
    int euler = 0, skimage = 0;
    for (const Check& c : r.checks) {
        if (c.decided) {
            EXPECT_NE(c.decided->cls, DivergenceClass::Unexplained) << c.subject << ": " << c.note;
            EXPECT_NE(c.decided->verdict, Verdict::RefUnavailable) << c.subject << ": " << c.note;
            ++skimage;
        } else {
            EXPECT_TRUE(c.pass()) << c.subject << " " << c.check << " " << c.measured << " > " << c.tolerance << ": " << c.note;
        }
        euler += c.check == "euler-characteristic";
    }
    EXPECT_EQ(euler, 12);  // sphere, torus, genus 2 at 4 resolutions
    EXPECT_EQ(skimage, 5);
    for (const auto& row : r.tables.at("isosurface_ambiguity")) {
        EXPECT_EQ(row.at("decider").at("boundary_edges"), 0);
        EXPECT_GT(row.at("minority").at("boundary_edges").get<int>(), 0);
        EXPECT_GT(row.at("decider").at("ambiguous_faces").get<int>(), 0);
    }
}

}  // namespace
}  // namespace crossdiv::verification
