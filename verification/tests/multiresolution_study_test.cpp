// The multiresolution study: every check holds on the bundled meshes, and the measures of one
// mesh against hand-countable facts.
#include <gtest/gtest.h>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/comparisons/multiresolution_checks.h"
#include "crossdiv/verification/studies/multiresolution_study.h"

namespace crossdiv::verification {
namespace {

TEST(MultiresolutionStudy, EveryCheckHolds) {
    const CheckReport r = multiresolution_study();
    ASSERT_GE(r.checks.size(), 4u * 18);
    for (const Check& c : r.checks) EXPECT_TRUE(c.pass()) << c.subject << " " << c.check << ": " << c.measured << " " << c.note;
    EXPECT_EQ(r.tables["multiresolution_figure"].size(), 3u);
}

TEST(MultiresolutionMeasures, TheTetrahedronMovesEverythingAndRefusesAWrongVertex) {
    // Three levels of a tetrahedron: every finest vertex lies in the support of every base
    // vertex (each base vertex's stencils reach all of its 1-ring, which is the whole mesh).
    const TriMesh tet = to_tri_mesh(datasets::bundled_mesh("tetrahedron"));
    const LoopMultiresolution m(tet, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 3);
    const MultiresolutionMeasures r = measure_multiresolution(m, detailed_surface(m, tet.positions, 0.02, 40), 1, Vec3(0, 0, 0.3));
    EXPECT_EQ(m.num_vertices(3), 130);  // 4 + 6 = 10, + 24 = 34, + 96 = 130
    EXPECT_EQ(r.support, 130);
    EXPECT_EQ(r.moved, 130);
    EXPECT_THROW(measure_multiresolution(m, detailed_surface(m, tet.positions, 0.02, 40), 4, Vec3::Zero()), InputError);
}

}  // namespace
}  // namespace crossdiv::verification
