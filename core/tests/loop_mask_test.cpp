// Loop masks against values computed by hand from the papers' closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv {
namespace {

TEST(LoopMask, OddWeightsAreThreeEighthsAndOneEighth) {
    EXPECT_EQ(interior_edge_mask().end, 3.0 / 8.0);
    EXPECT_EQ(interior_edge_mask().opposite, 1.0 / 8.0);
    EXPECT_EQ(boundary_edge_mask().end, 0.5);
    EXPECT_EQ(boundary_edge_mask().opposite, 0.0);
}

TEST(LoopMask, LoopFamilyBetaForValences3To6) {
    // beta(n) = (1/n)(5/8 - (3/8 + cos(2 pi/n)/4)^2)
    EXPECT_EQ(loop_beta(LoopWeights::Loop, 3), 3.0 / 16.0);   // cos = -1/2: (1/3)(5/8 - 1/16)
    EXPECT_EQ(loop_beta(LoopWeights::Loop, 4), 31.0 / 256.0);  // cos = 0: (1/4)(5/8 - 9/64)
    const double cos72 = (std::sqrt(5.0) - 1.0) / 4.0;        // exact cos(2 pi / 5)
    const double t5 = 3.0 / 8.0 + cos72 / 4.0;
    // Two ulps at 0.084 (1.4e-17 each): std::cos(2 pi / 5) and (sqrt 5 - 1)/4 round apart.
    constexpr double kTwoUlps = 2.8e-17;
    EXPECT_NEAR(loop_beta(LoopWeights::Loop, 5), (5.0 / 8.0 - t5 * t5) / 5.0, kTwoUlps);
    EXPECT_NEAR(loop_beta(LoopWeights::Loop, 5), 0.084093218925782893, kTwoUlps);  // 40-digit decimal evaluation
    EXPECT_EQ(loop_beta(LoopWeights::Loop, 6), 1.0 / 16.0);  // cos = 1/2: (1/6)(5/8 - 1/4)
}

TEST(LoopMask, WarrenFamilyBetaForValences3To6) {
    EXPECT_EQ(loop_beta(LoopWeights::Warren, 3), 3.0 / 16.0);
    EXPECT_EQ(loop_beta(LoopWeights::Warren, 4), 3.0 / 32.0);
    EXPECT_EQ(loop_beta(LoopWeights::Warren, 5), 3.0 / 40.0);
    EXPECT_EQ(loop_beta(LoopWeights::Warren, 6), 1.0 / 16.0);
}

TEST(LoopMask, FamiliesAgreeAtValence3And6AndDifferElsewhere) {
    for (int n = 3; n <= 12; ++n) {
        const bool same = loop_beta(LoopWeights::Loop, n) == loop_beta(LoopWeights::Warren, n);
        EXPECT_EQ(same, n == 3 || n == 6) << "valence " << n;
    }
}

TEST(LoopMask, InteriorVertexMaskIsAffine) {
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren})
        for (int n = 3; n <= 64; ++n) {
            const VertexMask m = interior_vertex_mask(w, n);
            EXPECT_NEAR(m.self + n * m.neighbor, 1.0, 4e-16) << to_string(w) << " valence " << n;
        }
    EXPECT_EQ(interior_vertex_mask(LoopWeights::Loop, 6).self, 5.0 / 8.0);
}

TEST(LoopMask, BoundaryVertexMasks) {
    for (int faces : {1, 2, 5}) {
        EXPECT_EQ(boundary_vertex_mask(LoopBoundary::EdgeOnly, faces).self, 0.75);
        EXPECT_EQ(boundary_vertex_mask(LoopBoundary::EdgeOnly, faces).neighbor, 0.125);
    }
    EXPECT_EQ(boundary_vertex_mask(LoopBoundary::EdgeAndCorner, 1).self, 1.0);  // corner: fixed
    EXPECT_EQ(boundary_vertex_mask(LoopBoundary::EdgeAndCorner, 1).neighbor, 0.0);
    EXPECT_EQ(boundary_vertex_mask(LoopBoundary::EdgeAndCorner, 2).self, 0.75);
}

}  // namespace
}  // namespace crossdiv
