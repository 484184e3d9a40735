// The rule oracles (loop_rule_oracle.h, rule_oracle.h): core passes each under every rule it
// has, and implementations with a seeded weight, boundary or parity slip fail, naming the mesh.
#include <gtest/gtest.h>

#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/properties/loop_rule_oracle.h"
#include "crossdiv/verification/properties/rule_oracle.h"
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
            const RuleVerdict v = check_loop_rule(core_implementation(), {w, b}, {16, 64, 360});
            EXPECT_TRUE(v.known);
            EXPECT_TRUE(v.passed) << v.detail;
            // Sums of up to n + 1 terms: rounding, far below kAgreementRelative (measured 7.2e-17).
            EXPECT_LE(v.worst_rel, 1e-14) << v.detail;
            RecordProperty(std::string(to_string(w)) + "_" + std::string(to_string(b)), v.detail);
        }
}

TEST(LoopRuleOracle, TheTunedFamiliesHaveNoClosedFormToCheck) {
    const RuleVerdict v = check_loop_rule(core_implementation(), {LoopWeights::Regularity, LoopBoundary::EdgeOnly});
    EXPECT_FALSE(v.known);
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.detail.find("regularity"), std::string::npos) << v.detail;
}

TEST(LoopRuleOracle, WarrensBetaAsThreeOverNineNFailsAtTheFirstValenceItChanges) {
    const auto slip = make_callback_implementation("warren-slip", {Scheme::Loop}, warren_slip);
    const RuleVerdict warren = check_loop_rule(*slip, {LoopWeights::Warren, LoopBoundary::EdgeOnly});
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
    const RuleVerdict v = check_loop_rule(*slip, {LoopWeights::Loop, LoopBoundary::EdgeAndCorner});
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.detail.find("open fan of 1 faces"), std::string::npos) << v.detail;
}

TEST(LoopRuleOracle, CoresVerdictIsRememberedPerRule) {
    const LoopOptions warren{LoopWeights::Warren, LoopBoundary::EdgeOnly};
    // Valences no other test asks for: the second call refines only the fan of 101.
    const RuleVerdict first = check_core_loop_rule(warren, {97});
    const RuleVerdict again = check_core_loop_rule(warren, {97, 101});
    EXPECT_TRUE(first.passed && again.passed) << first.detail << again.detail;
    EXPECT_EQ(again.meshes, first.meshes + 1);
    EXPECT_NE(again.detail.find(std::to_string(again.meshes) + " fans"), std::string::npos) << again.detail;
}

/// Core's `scheme` under another rule than the one asked for: `change` turns the request's
/// rule into the one applied.
std::unique_ptr<Implementation> core_applying(const std::string& name, Scheme scheme, std::function<void(SchemeRule&)> change) {
    const Implementation& core = core_implementation();
    return make_callback_implementation(name, {scheme}, [&core, change](const PolyMesh& m, const RefineRequest& r) {
        RefineRequest applied = r;
        change(applied.rule);
        return core.refine_last(m, applied);
    });
}

TEST(DooSabinRuleOracle, CorePassesUnderBothBoundaryRules) {
    for (DooSabinBoundary b : {DooSabinBoundary::ChaikinBoundary, DooSabinBoundary::DropBorderFaces}) {
        const RuleVerdict v = check_doo_sabin_rule(core_implementation(), {b});
        EXPECT_TRUE(v.known && v.passed) << v.detail;
        EXPECT_EQ(v.meshes, 2);
        EXPECT_LE(v.worst_rel, 1e-14) << v.detail;  // sums of n terms: rounding
    }
}

TEST(DooSabinRuleOracle, AWeightSlipAndAMissingChaikinBoundaryFail) {
    // Every mask's weights scaled by 0.97 (a normalization slipped, so they sum to 0.97): each
    // point is 0.97 of the rule's.
    const Implementation& core = core_implementation();
    const auto slip = make_callback_implementation("doo-sabin-slip", {Scheme::DooSabin}, [&core](const PolyMesh& m, const RefineRequest& r) {
        PolyMesh out = core.refine_last(m, r);
        for (Vec3& p : out.positions) p *= 0.97;
        return out;
    });
    const RuleVerdict v = check_doo_sabin_rule(*slip, {DooSabinBoundary::ChaikinBoundary});
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.detail.find("open strip"), std::string::npos) << v.detail;
    // Asked for the Chaikin boundary, refining as CGAL does (border faces dropped): the
    // boundary's points are missing.
    const auto drops = core_applying("drops-border-faces", Scheme::DooSabin,
                                     [](SchemeRule& r) { r.doo_sabin.boundary = DooSabinBoundary::DropBorderFaces; });
    const RuleVerdict d = check_doo_sabin_rule(*drops, {DooSabinBoundary::ChaikinBoundary});
    EXPECT_FALSE(d.passed);
    EXPECT_NE(d.detail.find("vertices where the rule makes"), std::string::npos) << d.detail;
    EXPECT_TRUE(check_doo_sabin_rule(*drops, {DooSabinBoundary::DropBorderFaces}).passed);
}

TEST(DooSabinRuleOracle, ChaikinPointsSwappedNearForFarFailOnTheBoundaryPolyline) {
    // Core's Doo-Sabin with each boundary edge's two Chaikin points exchanged (core numbers a
    // corner point per input corner, then each boundary edge's near and far point): the same
    // vertex set, so only the boundary's connectivity can tell.
    const Implementation& core = core_implementation();
    const auto swapped = make_callback_implementation("chaikin-swapped", {Scheme::DooSabin}, [&core](const PolyMesh& m, const RefineRequest& r) {
        PolyMesh out = core.refine_last(m, r);
        for (size_t i = m.face_vertices.size(); i + 1 < out.positions.size(); i += 2) std::swap(out.positions[i], out.positions[i + 1]);
        return out;
    });
    const RuleVerdict v = check_doo_sabin_rule(*swapped, {DooSabinBoundary::ChaikinBoundary});
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.detail.find("open strip of a triangle, quads and a pentagon (its boundary polyline)"), std::string::npos) << v.detail;
    EXPECT_NE(v.detail.find("joins points Chaikin's boundary does not join"), std::string::npos) << v.detail;
    EXPECT_TRUE(check_doo_sabin_rule(core, {DooSabinBoundary::ChaikinBoundary}).passed);
}

TEST(RuleOracleCheck, AStructuralMismatchFailsTheStudyCheckThoughItHasNoDistance) {
    // Border faces dropped where the Chaikin boundary is asked: the vertex count is not the
    // rule's, so there is no distance (worst_rel stays 0). The study's check fails all the same,
    // measured as infinite; it was once built from worst_rel alone and recorded "agree, 0".
    const auto drops = core_applying("drops-border-faces", Scheme::DooSabin,
                                     [](SchemeRule& r) { r.doo_sabin.boundary = DooSabinBoundary::DropBorderFaces; });
    const RuleVerdict v = check_doo_sabin_rule(*drops, {DooSabinBoundary::ChaikinBoundary});
    ASSERT_FALSE(v.passed);
    EXPECT_EQ(v.worst_rel, 0.0);
    const Check c = oracle_check("published points", "doo-sabin rule oracle", "chaikin-boundary", v);
    EXPECT_TRUE(c.outcome().is_failure());
    EXPECT_EQ(c.measured, INFINITY);
    EXPECT_NE(c.note.find("vertices where the rule makes"), std::string::npos) << c.note;
    // A measured failure keeps its distance; a pass is an agreement at its distance.
    const RuleVerdict core_v = check_doo_sabin_rule(core_implementation(), {DooSabinBoundary::ChaikinBoundary});
    const Check passed = oracle_check("published points", "doo-sabin rule oracle", "chaikin-boundary", core_v);
    EXPECT_EQ(passed.outcome(), (Outcome{Verdict::Agree, DivergenceClass::None}));
    EXPECT_EQ(passed.measured, core_v.worst_rel);
}

TEST(Sqrt3RuleOracle, CorePassesUnderBothParitiesAndCountingPerCallFailsCountFromInput) {
    for (Sqrt3Parity p : {Sqrt3Parity::CountFromInput, Sqrt3Parity::RestartEachLevel}) {
        const RuleVerdict v = check_sqrt3_rule(core_implementation(), {p});
        EXPECT_TRUE(v.known && v.passed) << v.detail;
        EXPECT_LE(v.worst_rel, 1e-14) << v.detail;
    }
    // An implementation that counts generations per call, asked to count from the input,
    // never trisects the boundary: 6 boundary vertices at level 2 where the rule makes 18.
    const auto per_call =
        core_applying("per-call", Scheme::Sqrt3, [](SchemeRule& r) { r.sqrt3.parity = Sqrt3Parity::RestartEachLevel; });
    const RuleVerdict v = check_sqrt3_rule(*per_call, {Sqrt3Parity::CountFromInput});
    EXPECT_FALSE(v.passed);
    EXPECT_NE(v.detail.find("boundary: 6 vertices where the rule makes 18"), std::string::npos) << v.detail;
}

TEST(ButterflyRuleOracle, CorePassesUnderBothWingRulesAndEachFailsAsTheOther) {
    for (ButterflyWings w : kAllButterflyWings) {
        const RuleVerdict v = check_butterfly_rule(core_implementation(), w);
        EXPECT_TRUE(v.known && v.passed) << v.detail;
        EXPECT_LE(v.worst_rel, 1e-14) << v.detail;
        // Asked for one wing rule, applying the other: the spokes' points move.
        const ButterflyWings other = w == ButterflyWings::Reflected ? ButterflyWings::OppositeVertex : ButterflyWings::Reflected;
        const auto swapped = core_applying("other-wings", Scheme::Butterfly, [other](SchemeRule& r) { r.butterfly_wings = other; });
        const RuleVerdict s = check_butterfly_rule(*swapped, w);
        EXPECT_FALSE(s.passed) << s.detail;
        EXPECT_GT(s.worst_rel, 1e-3) << s.detail;
    }
}

}  // namespace
}  // namespace crossdiv::verification
