// The implementation interface and its registry: declared rules and the closest rule each
// library applies, refinement through the interface equal to core's own calls bit for bit,
// refusals naming what is lacking; the typed verdicts and the classification ladder.
#include <gtest/gtest.h>

#include "library_guard.h"

#include <set>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/sqrt3.h"
#include "crossdiv/verification/comparisons/classification.h"
#include "crossdiv/verification/harness/verdict.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

SchemeRule loop(LoopWeights w, LoopBoundary b) {
    SchemeRule r;
    r.loop = {w, b};
    return r;
}

SchemeRule catmull_clark(CatmullClarkBoundary b, CreaseMethod m = CreaseMethod::Uniform) {
    SchemeRule r;
    r.catmull_clark = {b, m};
    return r;
}

TEST(Registry, CoreFirstNamesUniqueEveryReferenceALibrary) {
    const auto& all = implementations();
    ASSERT_FALSE(all.empty());
    EXPECT_EQ(all.front()->name(), "core");
    EXPECT_EQ(&core_implementation(), all.front());
    std::set<std::string> names;
    for (const Implementation* i : all) EXPECT_TRUE(names.insert(i->name()).second) << i->name();
    for (const Implementation* i : references_for(Scheme::Loop)) EXPECT_EQ(i->kind(), ImplementationKind::Library);
    EXPECT_THROW(find_implementation("blender"), InputError);
    // Core has every scheme under every rule.
    for (Scheme s : all_schemes()) EXPECT_TRUE(core_implementation().has(s)) << to_string(s);
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Warren})
        for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner})
            EXPECT_TRUE(core_implementation().applies(Scheme::Loop, loop(w, b)));
}

TEST(Registry, LibrariesApplyTheirClosestRule) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv", "openmesh", "cgal");
    const Implementation &osd = find_implementation("opensubdiv"), &om = find_implementation("openmesh"),
                         &cg = find_implementation("cgal");
    // Loop: OpenSubdiv has both boundary rules, the others edge-only; nobody has Warren.
    EXPECT_TRUE(osd.applies(Scheme::Loop, loop(LoopWeights::Loop, LoopBoundary::EdgeAndCorner)));
    EXPECT_FALSE(om.applies(Scheme::Loop, loop(LoopWeights::Loop, LoopBoundary::EdgeAndCorner)));
    const SchemeRule warren_corner = loop(LoopWeights::Warren, LoopBoundary::EdgeAndCorner);
    EXPECT_EQ(osd.closest_rule(Scheme::Loop, warren_corner).loop, (LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeAndCorner}));
    EXPECT_EQ(cg.closest_rule(Scheme::Loop, warren_corner).loop, (LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeOnly}));
    // Catmull-Clark: OpenMesh always averages midpoints, CGAL has no corner rule; the creasing
    // method of the request is kept.
    const SchemeRule corner = catmull_clark(CatmullClarkBoundary::EdgeAndCorner, CreaseMethod::Chaikin);
    EXPECT_EQ(om.closest_rule(Scheme::CatmullClark, corner).catmull_clark.boundary, CatmullClarkBoundary::MidpointAverage);
    EXPECT_EQ(cg.closest_rule(Scheme::CatmullClark, corner).catmull_clark.boundary, CatmullClarkBoundary::EdgeOnly);
    EXPECT_EQ(osd.closest_rule(Scheme::CatmullClark, catmull_clark(CatmullClarkBoundary::MidpointAverage)).catmull_clark.boundary,
              CatmullClarkBoundary::EdgeOnly);
    EXPECT_EQ(om.closest_rule(Scheme::CatmullClark, corner).catmull_clark.creasing, CreaseMethod::Chaikin);
    // sqrt3: called per level neither library refines the boundary; in one call both do.
    SchemeRule kobbelt;
    EXPECT_EQ(om.closest_rule(Scheme::Sqrt3, kobbelt).sqrt3.parity, Sqrt3Parity::RestartEachLevel);
    EXPECT_EQ(find_implementation("cgal-one-call").closest_rule(Scheme::Sqrt3, kobbelt).sqrt3.parity,
              Sqrt3Parity::CountFromInput);
    EXPECT_EQ(om.support(Scheme::Sqrt3)->max_valence, 49);
    // Only OpenSubdiv has crease rules and limit evaluation.
    EXPECT_TRUE(osd.support(Scheme::CatmullClark)->creases);
    EXPECT_FALSE(om.support(Scheme::CatmullClark)->creases);
    EXPECT_EQ(references_with(&Capabilities::limit_positions).size(), 1u);
}

TEST(Implementation, CoreRefinesThroughTheInterfaceAsItsOwnCallsBitForBit) {
    const PolyMesh cube = datasets::bundled_mesh("quad-cube");
    const Implementation& core = core_implementation();
    const adapters::LevelTrace trace = core.refine(cube, {Scheme::CatmullClark, {}, 2});
    ASSERT_EQ(trace.size(), 3u);
    EXPECT_EQ(trace[0].positions, cube.positions);
    EXPECT_EQ(trace[2].positions, catmull_clark_subdivide(cube, {CatmullClarkBoundary::EdgeOnly}, 2).positions);
    EXPECT_EQ(trace[2].face_vertices, core.refine_last(cube, {Scheme::CatmullClark, {}, 2}).face_vertices);
    // sqrt3 counts its boundary generations from the input: level l is l steps from the input.
    const PolyMesh patch = datasets::bundled_mesh("open-patch");
    const adapters::LevelTrace s = core.refine(patch, {Scheme::Sqrt3, {}, 3});
    for (int l = 1; l <= 3; ++l)
        EXPECT_EQ(s[l].positions, sqrt3_subdivide(patch, {Sqrt3Parity::CountFromInput}, l).positions) << "level " << l;
}

TEST(Implementation, AnOperationItLacksIsARefusalNamingIt) {
    CROSSDIV_REQUIRE_LIBRARIES("eigen");
    const Implementation& eigen = find_implementation("eigen");
    try {
        eigen.refine(datasets::bundled_mesh("tetrahedron"), {Scheme::Loop, {}, 1});
        ADD_FAILURE() << "eigen refined a mesh";
    } catch (const adapters::Rejected& e) {
        EXPECT_EQ(std::string(e.what()), "eigen has no loop");
    }
    EXPECT_THROW(eigen.open_edit(to_tri_mesh(datasets::bundled_mesh("tetrahedron"), "test")), adapters::Rejected);
}

TEST(Verdicts, EveryNameParsesBackAndUnknownNamesAreRefused) {
    for (Verdict v : {Verdict::Agree, Verdict::Diverge, Verdict::RefRejected, Verdict::RefCrashed, Verdict::OursRejected})
        EXPECT_EQ(verdict_from_string(to_string(v)), v);
    for (int c = 0; c <= static_cast<int>(DivergenceClass::InvalidInputHandling); ++c)
        EXPECT_EQ(static_cast<int>(divergence_class_from_string(to_string(static_cast<DivergenceClass>(c)))), c);
    EXPECT_THROW(verdict_from_string("maybe"), InputError);
    EXPECT_THROW(divergence_class_from_string("cosmic-ray"), InputError);
    EXPECT_EQ(to_string(Outcome{Verdict::Diverge, DivergenceClass::CornerRule}), "diverge (corner-rule)");
    EXPECT_EQ(to_string(Outcome{Verdict::RefCrashed, DivergenceClass::None}), "ref-crashed");
    EXPECT_TRUE((Outcome{Verdict::Diverge, DivergenceClass::Unexplained}).is_failure());
    EXPECT_FALSE((Outcome{Verdict::Diverge, DivergenceClass::Rounding}).is_failure());
    // Every rule parses back from its name, and a wrong name lists the right ones.
    EXPECT_EQ(loop_weights_from_string("warren"), LoopWeights::Warren);
    EXPECT_EQ(catmull_clark_boundary_from_string("midpoint-average"), CatmullClarkBoundary::MidpointAverage);
    EXPECT_EQ(sqrt3_parity_from_string("restart-each-level"), Sqrt3Parity::RestartEachLevel);
    EXPECT_EQ(crease_method_from_string("chaikin"), CreaseMethod::Chaikin);
    try {
        doo_sabin_boundary_from_string("edge-only");
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("known: chaikin-boundary, drop-border-faces"), std::string::npos) << e.what();
    }
}

TEST(Classification, TheLadderTakesTheFirstTestThatHoldsAndRunsNoneAfterIt) {
    int later_runs = 0;
    const auto holds = [](DivergenceClass c) {
        return [c]() -> std::optional<Classification> { return Classification{c, "measured"}; };
    };
    const auto counted = [&]() -> std::optional<Classification> {
        ++later_runs;
        return std::nullopt;
    };
    DivergenceTests t;
    t.rounding = holds(DivergenceClass::Rounding);
    t.reference_rule = counted;
    t.topology = holds(DivergenceClass::Topology);
    EXPECT_EQ(classify_divergence(t).cls, DivergenceClass::Rounding);
    EXPECT_EQ(later_runs, 0);  // core is not re-run once rounding explains the difference
    t.rounding = counted;
    EXPECT_EQ(classify_divergence(t).cls, DivergenceClass::Topology);
    EXPECT_EQ(later_runs, 2);
    t.isolated_vertices = holds(DivergenceClass::IsolatedVertexHandling);
    EXPECT_EQ(classify_divergence(t).cls, DivergenceClass::IsolatedVertexHandling);
    DivergenceTests none;
    none.unexplained = [] { return std::string("differs by 1e-3"); };
    const Classification u = classify_divergence(none);
    EXPECT_EQ(u.cls, DivergenceClass::Unexplained);
    EXPECT_EQ(u.explanation, "differs by 1e-3");
    // The rule classes.
    EXPECT_EQ(rule_difference_class(Scheme::Loop, loop(LoopWeights::Loop, LoopBoundary::EdgeOnly),
                                    loop(LoopWeights::Warren, LoopBoundary::EdgeAndCorner)),
              DivergenceClass::WeightFamilyAndCornerRule);
    EXPECT_EQ(rule_difference_class(Scheme::CatmullClark, catmull_clark(CatmullClarkBoundary::MidpointAverage),
                                    catmull_clark(CatmullClarkBoundary::EdgeOnly)),
              DivergenceClass::BoundaryRule);
    // Catmull-Clark's interior vertex rule and Doo-Sabin's corner weights are weight families.
    SchemeRule edge_points = catmull_clark(CatmullClarkBoundary::EdgeOnly);
    edge_points.catmull_clark.vertex = CatmullClarkVertexRule::EdgePointAverage;
    EXPECT_EQ(rule_difference_class(Scheme::CatmullClark, catmull_clark(CatmullClarkBoundary::EdgeOnly), edge_points),
              DivergenceClass::WeightFamily);
    EXPECT_EQ(rule_difference_class(Scheme::CatmullClark, catmull_clark(CatmullClarkBoundary::EdgeAndCorner), edge_points),
              DivergenceClass::WeightFamilyAndCornerRule);
    SchemeRule dropped, averaged;
    dropped.doo_sabin = {DooSabinBoundary::DropBorderFaces};
    averaged.doo_sabin = {DooSabinBoundary::DropBorderFaces, DooSabinWeights::CatmullClark};
    EXPECT_EQ(rule_difference_class(Scheme::DooSabin, dropped, averaged), DivergenceClass::WeightFamily);
    averaged.doo_sabin.boundary = DooSabinBoundary::ChaikinBoundary;
    EXPECT_EQ(rule_difference_class(Scheme::DooSabin, dropped, averaged), DivergenceClass::BorderFacesDropped);
}

}  // namespace
}  // namespace crossdiv::verification
