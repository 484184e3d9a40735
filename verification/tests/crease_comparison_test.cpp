// Creases against OpenSubdiv on the crease catalog: Loop and Catmull-Clark, uniform and
// Chaikin decay, three levels -- every run agrees to rounding, and the tags move the surface
// far more than that (so the agreement tests the sharp rules, not the smooth ones). OpenMesh
// and CGAL, which have no crease rules, refuse a tagged mesh.
#include <gtest/gtest.h>

#include "library_guard.h"

#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/comparisons/crease_comparison.h"
#include "crossdiv/verification/comparisons/scheme_comparison.h"

namespace crossdiv::verification {
namespace {

TEST(CreaseComparison, OpenSubdivAgreesOnEveryCreaseMesh) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv");
    // Measured: at most 1.7e-16 of the diagonal; the tags move the surface by 6.7e-3 to 0.25.
    constexpr double kTagsMatter = 1e-3;
    int runs = 0;
    for (const CreaseComparison& c : compare_crease_catalog()) {
        SCOPED_TRACE(c.input + " " + c.scheme + " " + c.method);
        EXPECT_EQ(c.verdict, Verdict::Agree) << c.explanation << c.core_error;
        EXPECT_TRUE(c.faces_equal);
        ASSERT_EQ(c.max_rel_per_level.size(), 3u);
        for (double d : c.max_rel_per_level) EXPECT_LE(d, tolerances::kAgreementRelative);
        EXPECT_GT(c.effect_of_tags, kTagsMatter);
        ++runs;
    }
    EXPECT_EQ(runs, 36);
}

TEST(CreaseComparison, ChaikinAndUniformDecayDifferWhereSharpnessVaries) {
    // Along a crease loop of sharpness 1, 2, 3, 4 the two decays give different surfaces, and
    // OpenSubdiv agrees with each (above): the creasing method really reaches Far.
    const PolyMesh m = datasets::bundled_mesh("crease-cube-varying");
    CreaseRequest uniform, chaikin;
    chaikin.method = CreaseMethod::Chaikin;
    const CreaseComparison a = compare_creases(m, "varying", uniform), b = compare_creases(m, "varying", chaikin);
    EXPECT_NE(a.effect_of_tags, b.effect_of_tags);
}

TEST(CreaseComparison, ReferencesWithoutCreaseRulesRefuseTaggedMeshes) {
    SchemeRequest req;
    req.levels = 1;
    const SchemeComparison c = compare_scheme(datasets::bundled_mesh("crease-cube-top"), "crease-cube-top", req);
    ASSERT_TRUE(c.core_error.empty()) << c.core_error;
    for (const SchemeReferenceRun& r : c.runs) {
        SCOPED_TRACE(r.reference);
        if (r.reference == "opensubdiv") {
            EXPECT_EQ(r.verdict, Verdict::Agree) << r.explanation;
        } else {
            EXPECT_EQ(r.verdict, Verdict::RefRejected);
            EXPECT_NE(r.explanation.find("has no crease rules"), std::string::npos) << r.explanation;
        }
    }
}

}  // namespace
}  // namespace crossdiv::verification
