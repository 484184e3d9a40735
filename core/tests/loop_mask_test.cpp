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

// The Barthe-Kobbelt families, against the table values (VCG's five decimals) by hand.
TEST(LoopMask, TunedFamiliesVertexWeightsFromTheTables) {
    // Regularity, valence 5: 1 - 5 beta = .59549; continuity, valence 8: .67821.
    EXPECT_NEAR(interior_vertex_mask(LoopWeights::Regularity, 5).self, 0.59549, 1e-15);
    EXPECT_NEAR(loop_beta(LoopWeights::Regularity, 5), (1 - 0.59549) / 5, 1e-17);
    EXPECT_NEAR(interior_vertex_mask(LoopWeights::Continuity, 8).self, 0.67821, 1e-15);
    // Valence 6 is Loop's in every table; outside 3..12 the tuned families take Loop's beta.
    for (LoopWeights w : {LoopWeights::Regularity, LoopWeights::Continuity}) {
        EXPECT_NEAR(loop_beta(w, 6), 1.0 / 16.0, 1e-17);
        EXPECT_EQ(loop_beta(w, 13), loop_beta(LoopWeights::Loop, 13));
        EXPECT_EQ(loop_beta(w, 64), loop_beta(LoopWeights::Loop, 64));
    }
}

TEST(LoopMask, TunedEdgeMaskNextToOneExtraordinaryEnd) {
    // Regularity, an edge from a valence-4 vertex to a regular one: .25029 on the valence-4
    // end, .12524 on each opposite vertex, 1 - .25029 - 2 (.12524) = .49923 on the regular end.
    const TunedEdgeMask m = tuned_edge_mask(LoopWeights::Regularity, 6, 4);
    EXPECT_NEAR(m.end_a, 0.49923, 1e-15);
    EXPECT_NEAR(m.end_b, 0.25029, 1e-15);
    EXPECT_NEAR(m.opposite, 0.12524, 1e-15);
    const TunedEdgeMask swapped = tuned_edge_mask(LoopWeights::Regularity, 4, 6);
    EXPECT_EQ(swapped.end_a, m.end_b);
    EXPECT_EQ(swapped.end_b, m.end_a);
    // Neither end regular, or the irregular end beyond the table: Loop's 3/8, 1/8.
    for (auto [a, b] : {std::pair{5, 7}, std::pair{6, 13}, std::pair{4, 4}}) {
        const TunedEdgeMask p = tuned_edge_mask(LoopWeights::Continuity, a, b);
        EXPECT_EQ(p.end_a, 0.375);
        EXPECT_EQ(p.end_b, 0.375);
        EXPECT_EQ(p.opposite, 0.125);
    }
    // Loop's and Warren's families never tune the edge.
    EXPECT_EQ(tuned_edge_mask(LoopWeights::Warren, 6, 4).end_b, 0.375);
}

TEST(LoopMask, TunedEdgeValenceOfBoundaryVerticesCountsFaces) {
    // VCG reads a boundary vertex of f faces as max(2 (f - 1), 3): 1 and 2 faces read 3, a
    // regular boundary vertex (3 faces) reads 4, 4 faces read 6.
    EXPECT_EQ(tuned_edge_valence(1, true), 3);
    EXPECT_EQ(tuned_edge_valence(2, true), 3);
    EXPECT_EQ(tuned_edge_valence(3, true), 4);
    EXPECT_EQ(tuned_edge_valence(4, true), 6);
    EXPECT_EQ(tuned_edge_valence(7, false), 7);
}

}  // namespace
}  // namespace crossdiv
