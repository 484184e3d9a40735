// Re-evaluation at fixed topology: core's composed stencils give the level-by-level
// refinement of any frame, and OpenSubdiv's stencil table the same points.
#include <gtest/gtest.h>

#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/subdiv/composed_stencils.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"
#ifdef CROSSDIV_HAS_OPENSUBDIV
#include "crossdiv/adapters/opensubdiv.h"
#endif

namespace crossdiv::verification {
namespace {

/// The base vertices moved by a smooth field: a frame the topology was not built from.
std::vector<Vec3> frame_of(const std::vector<Vec3>& p) {
    std::vector<Vec3> out = p;
    for (Vec3& q : out) q += 0.1 * Vec3(std::sin(2 * q.y()), q.x() * q.z(), std::cos(q.x()));
    return out;
}

TEST(ComposedStencils, EveryFrameIsTheLevelByLevelRefinementOnTheCatalog) {
    // Composing the levels reorders the sums, so the points agree to rounding, not in bits:
    // tolerances::kAgreementRelative of the diagonal (measured: below 1e-15).
    for (const datasets::BundledMesh& b : datasets::catalog_meshes()) {
        if (!b.mesh.all_triangles()) continue;
        const TriMesh base = to_tri_mesh(b.mesh, "test");
        for (const LoopOptions o : {LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeOnly},
                                    LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeAndCorner},
                                    LoopOptions{LoopWeights::Warren, LoopBoundary::EdgeOnly}})
            for (int levels = 1; levels <= 3; ++levels) {
                const ComposedStencils s = ComposedStencils::loop(base, o, levels);
                TriMesh moved = base;
                moved.positions = frame_of(base.positions);
                const TriMesh expected = loop_subdivide(moved, o, levels);
                EXPECT_EQ(s.triangles(), expected.triangles) << b.name;
                std::vector<Vec3> out;
                s.apply(moved.positions, out);
                ASSERT_EQ(out.size(), expected.positions.size()) << b.name;
                EXPECT_LE(max_relative_distance(expected.positions, out, identity_map(out.size())), tolerances::kAgreementRelative)
                    << b.name << " levels " << levels;
            }
    }
}

TEST(ComposedStencils, AFrameOfTheWrongSizeIsRefusedNamingBothCounts) {
    const TriMesh base = to_tri_mesh(datasets::bundled_mesh("tetrahedron"), "test");
    const ComposedStencils s = ComposedStencils::loop(base, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    std::vector<Vec3> out;
    try {
        s.apply(std::vector<Vec3>(base.positions.size() + 1, Vec3::Zero()), out);
        FAIL() << "a frame of the wrong size was applied";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(std::to_string(base.num_vertices()) + " base vertices, given " +
                                             std::to_string(base.num_vertices() + 1)),
                  std::string::npos)
            << e.what();
    }
}

#ifdef CROSSDIV_HAS_OPENSUBDIV
TEST(ComposedStencils, OpenSubdivsStencilTableGivesTheSamePoints) {
    // Far numbers the refined edges its own way: matched by position, then within
    // tolerances::kAgreementRelative; its PrimvarRefiner levels give its stencils' points too.
    for (const datasets::BundledMesh& b : datasets::catalog_meshes()) {
        if (!b.mesh.all_triangles()) continue;
        const TriMesh base = to_tri_mesh(b.mesh, "test");
        const LoopOptions o{LoopWeights::Loop, LoopBoundary::EdgeOnly};
        const ComposedStencils s = ComposedStencils::loop(base, o, 2);
        const adapters::opensubdiv::LoopFrames far(base, o, 2);
        const std::vector<Vec3> frame = frame_of(base.positions);
        std::vector<Vec3> ours, theirs, levels;
        s.apply(frame, ours);
        far.by_stencils(frame, theirs);
        far.by_levels(frame, levels);
        ASSERT_EQ(theirs.size(), ours.size()) << b.name;
        const Correspondence c = match_nearest(ours, theirs);
        ASSERT_NE(c.method, MatchMethod::None) << b.name << ": " << c.note;
        EXPECT_LE(max_relative_distance(ours, theirs, c.ref_to_ours), tolerances::kAgreementRelative) << b.name;
        EXPECT_LE(max_relative_distance(theirs, levels, identity_map(levels.size())), tolerances::kAgreementRelative) << b.name;
    }
}
#endif

}  // namespace
}  // namespace crossdiv::verification
