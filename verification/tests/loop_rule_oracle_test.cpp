// The Loop rule oracle (loop_rule_oracle.h): core passes it under every rule it knows, and
// implementations with a seeded weight or boundary slip fail it, naming the fan.
#include <gtest/gtest.h>

#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/properties/loop_rule_oracle.h"
#include "fault_doubles.h"

namespace crossdiv::verification {
namespace {

/// Core's Loop with Warren's beta mistyped as 3 / (9 n), level by level.
PolyMesh warren_slip(const PolyMesh& mesh, const RefineRequest& request) {
    PolyMesh current = mesh;
    for (int l = 0; l < request.levels; ++l) {
        PolyMesh next = loop_subdivide(current, request.rule.loop, 1);
        if (request.rule.loop.weights == LoopWeights::Warren) test::warren_beta_slip(current, next);
        current = std::move(next);
    }
    return current;
}

/// Core's Loop that never applies the corner rule (edge-and-corner refined as edge-only).
PolyMesh no_corner_rule(const PolyMesh& mesh, const RefineRequest& request) {
    LoopOptions o = request.rule.loop;
    o.boundary = LoopBoundary::EdgeOnly;
    return loop_subdivide(mesh, o, request.levels);
}

TEST(LoopRuleOracle, CorePassesUnderLoopsAndWarrensWeightsWithBothBoundaryRules) {
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren})
        for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
            const LoopRuleVerdict v = check_loop_rule(core_implementation(), {w, b}, {16, 64, 360});
            EXPECT_TRUE(v.known);
            EXPECT_TRUE(v.passed) << v.detail;
            // Sums of up to n + 1 terms: rounding, far below kAgreementRelative (measured 7.2e-17).
            EXPECT_LE(v.worst_rel, 1e-14) << v.detail;
            RecordProperty(std::string(to_string(w)) + "_" + std::string(to_string(b)), v.detail);
        }
}

TEST(LoopRuleOracle, TheTunedFamiliesHaveNoClosedFormToCheck) {
    const LoopRuleVerdict v = check_loop_rule(core_implementation(), {LoopWeights::Regularity, LoopBoundary::EdgeOnly});
    EXPECT_FALSE(v.known);
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.detail.find("regularity"), std::string::npos) << v.detail;
}

TEST(LoopRuleOracle, WarrensBetaAsThreeOverNineNFailsAtTheFirstValenceItChanges) {
    const auto slip = make_callback_implementation("warren-slip", {Scheme::Loop}, warren_slip);
    const LoopRuleVerdict warren = check_loop_rule(*slip, {LoopWeights::Warren, LoopBoundary::EdgeOnly});
    EXPECT_TRUE(warren.known);
    EXPECT_FALSE(warren.passed);
    // n = 3 keeps 3/16; n = 4 is the first fan the slip moves (by 1/96 of the ring's offsets).
    EXPECT_NE(warren.detail.find("closed fan of valence 4:"), std::string::npos) << warren.detail;
    EXPECT_GT(warren.worst_rel, 1e-3) << warren.detail;
    RecordProperty("warren_slip", warren.detail);
    // Loop's weights are untouched by the slip.
    EXPECT_TRUE(check_loop_rule(*slip, {LoopWeights::Loop, LoopBoundary::EdgeOnly}).passed);
}

TEST(LoopRuleOracle, AMissingCornerRuleFailsOnTheOneFaceCorners) {
    const auto slip = make_callback_implementation("no-corner-rule", {Scheme::Loop}, no_corner_rule);
    EXPECT_TRUE(check_loop_rule(*slip, {LoopWeights::Loop, LoopBoundary::EdgeOnly}).passed);
    const LoopRuleVerdict v = check_loop_rule(*slip, {LoopWeights::Loop, LoopBoundary::EdgeAndCorner});
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.detail.find("open fan of 1 faces"), std::string::npos) << v.detail;
}

TEST(LoopRuleOracle, CoresVerdictIsRememberedPerRule) {
    const LoopOptions warren{LoopWeights::Warren, LoopBoundary::EdgeOnly};
    // Valences no other test asks for: the second call refines only the fan of 101.
    const LoopRuleVerdict first = check_core_loop_rule(warren, {97});
    const LoopRuleVerdict again = check_core_loop_rule(warren, {97, 101});
    EXPECT_TRUE(first.passed && again.passed) << first.detail << again.detail;
    EXPECT_EQ(again.fans, first.fans + 1);
    EXPECT_NE(again.detail.find(std::to_string(again.fans) + " fans"), std::string::npos) << again.detail;
}

}  // namespace
}  // namespace crossdiv::verification
