// Re-evaluation at fixed topology: core's composed stencils and its level stencils give the
// level-by-level refinement of any frame, and OpenSubdiv's stencil table the same points.
#include <gtest/gtest.h>

#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/subdiv/composed_stencils.h"
#include "crossdiv/subdiv/level_stencils.h"
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

/// Every triangle mesh of the catalog under three Loop rules at 1..3 levels: `table(base,
/// options, levels)` builds a table, and `frame(table, moved base, out)` evaluates a frame,
/// which must be the level-by-level refinement of the moved base to rounding
/// (tolerances::kAgreementRelative of the diagonal; measured below 1e-15: the tables sum each
/// row in their own order, loop_refine_once in its own), with its triangles.
template <class Build, class Frame>
void expect_refinement_on_catalog(const Build& table, const Frame& frame) {
    for (const datasets::BundledMesh& b : datasets::catalog_meshes()) {
        if (!b.mesh.all_triangles()) continue;
        const TriMesh base = to_tri_mesh(b.mesh, "test");
        for (const LoopOptions o : {LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeOnly},
                                    LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeAndCorner},
                                    LoopOptions{LoopWeights::Warren, LoopBoundary::EdgeOnly}})
            for (int levels = 1; levels <= 3; ++levels) {
                const auto s = table(base, o, levels);
                TriMesh moved = base;
                moved.positions = frame_of(base.positions);
                const TriMesh expected = loop_subdivide(moved, o, levels);
                EXPECT_EQ(s.triangles(), expected.triangles) << b.name;
                std::vector<Vec3> out;
                frame(s, moved.positions, out);
                ASSERT_EQ(out.size(), expected.positions.size()) << b.name;
                EXPECT_LE(max_relative_distance(expected.positions, out, identity_map(out.size())), tolerances::kAgreementRelative)
                    << b.name << " levels " << levels;
            }
    }
}

TEST(ComposedStencils, EveryFrameIsTheLevelByLevelRefinementOnTheCatalog) {
    expect_refinement_on_catalog(ComposedStencils::loop,
                                 [](const ComposedStencils& s, const std::vector<Vec3>& base, std::vector<Vec3>& out) {
                                     s.apply(base, out);
                                 });
}

/// `frame(base)` evaluates a frame of one vertex more than the tetrahedron's 4: refused,
/// naming both counts.
template <class Frame>
void expect_wrong_size_refused(const Frame& frame) {
    try {
        frame(std::vector<Vec3>(5, Vec3::Zero()));
        FAIL() << "a frame of the wrong size was applied";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("4 base vertices, given 5"), std::string::npos) << e.what();
    }
}

TEST(ComposedStencils, AFrameOfTheWrongSizeIsRefusedNamingBothCounts) {
    const TriMesh base = to_tri_mesh(datasets::bundled_mesh("tetrahedron"), "test");
    const ComposedStencils s = ComposedStencils::loop(base, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    std::vector<Vec3> out;
    expect_wrong_size_refused([&](const std::vector<Vec3>& frame) { s.apply(frame, out); });
}

TEST(LevelStencils, EveryFrameIsTheLevelByLevelRefinementOnTheCatalog) {
    expect_refinement_on_catalog(LevelStencils::loop,
                                 [](const LevelStencils& s, const std::vector<Vec3>& base, std::vector<Vec3>& out) {
                                     // Twice with the same buffers: a frame must not read what
                                     // the last one left.
                                     std::vector<Vec3> scratch;
                                     s.apply(base, out, scratch);
                                     for (Vec3& p : out) p = Vec3::Constant(1e300);
                                     s.apply(base, out, scratch);
                                 });
}

TEST(LevelStencils, RowsShareTheirWeightsByValenceAndKind) {
    // The regular torus, one level under Loop's weights. A row's terms are in the order of
    // their sources' indices, so a pattern is a weight sequence in that order: a vertex point
    // (5/8 at the centre, 1/16 for each of its 6 neighbours) has one pattern per rank of the
    // centre among its 7 sources, at most 7; an edge point (3/8, 3/8, 1/8, 1/8) one per place of
    // its two ends among its 4 sources, at most C(4, 2) = 6. The torus is closed and of genus 1:
    // E = 3V, so 7V + 4E terms.
    const TriMesh torus = to_tri_mesh(datasets::bundled_mesh("torus"), "test");
    const LevelStencils s = LevelStencils::loop(torus, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
    EXPECT_GE(s.num_patterns(), 2u);
    EXPECT_LE(s.num_patterns(), 7u + 6u);
    const size_t v = static_cast<size_t>(torus.num_vertices());
    EXPECT_EQ(s.num_terms(), 7 * v + 4 * (3 * v));
}

TEST(LevelStencils, AFrameOfTheWrongSizeIsRefusedNamingBothCounts) {
    const TriMesh base = to_tri_mesh(datasets::bundled_mesh("tetrahedron"), "test");
    const LevelStencils s = LevelStencils::loop(base, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2);
    std::vector<Vec3> out, scratch;
    expect_wrong_size_refused([&](const std::vector<Vec3>& frame) { s.apply(frame, out, scratch); });
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
