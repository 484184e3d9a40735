// The course's vertex-normal task with a program in core's place: the course-style Python
// program named by its weighting, its two classic slips named, and the ways a program fails.
#include <gtest/gtest.h>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/comparisons/normals_subject.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

using test::kSource;

const std::string kNormalsExample = "python3 " + kSource + "/examples/subjects/python-normals/normals.py {in} {out}";

NormalsSubjectComparison run(const std::string& command, const std::string& mesh = "torus", double timeout = 60) {
    return compare_normals_subject(mesh, test::bundled(mesh), "subject", command, timeout);
}

TEST(NormalsSubject, TheCourseProgramIsAreaWeightedAndItsSlipsAreNamed) {
    // The torus's faces differ in area and angle: every weighting is told apart.
    const NormalsSubjectComparison area = run(kNormalsExample);
    ASSERT_EQ(area.outcome.status, RunStatus::Ok) << area.outcome.summary();
    EXPECT_EQ(area.weighting, "area");
    EXPECT_EQ(area.compared, 96);
    EXPECT_TRUE(area.passed()) << area.summary();
    for (const WeightingFit& w : area.weightings) {
        if (w.name != "area") {
            EXPECT_GT(w.max_deg, 0.1) << w.name;
        }
    }

    const NormalsSubjectComparison uniform = run(kNormalsExample + " --uniform");
    EXPECT_EQ(uniform.weighting, "uniform");
    EXPECT_TRUE(uniform.passed());  // a named weighting: a diagnosis (OpenMesh's update_vertex_normals)

    const NormalsSubjectComparison inward = run(kNormalsExample + " --clockwise");
    EXPECT_EQ(inward.weighting, "area, reversed");
    EXPECT_FALSE(inward.passed());
    EXPECT_EQ(inward.summary(), "subject 'subject': area, reversed weighting on 96 vertices");
}

TEST(NormalsSubject, AProgramThatFailsGetsItsOutcome) {
    const auto python = [](const std::string& code) { return "python3 -c '" + code + "' {in} {out}"; };
    const NormalsSubjectComparison few = run(python("import sys; open(sys.argv[2], \"w\").write(\"vn 0 0 1\\n\")"));
    EXPECT_EQ(few.outcome.status, RunStatus::WrongCount);
    EXPECT_EQ(few.outcome.message, "out.obj: 1 normals for 96 vertices");
    const NormalsSubjectComparison nan = run(python("import sys; open(sys.argv[2], \"w\").write(\"vn 0 nan 1\\n\" * 96)"));
    EXPECT_EQ(nan.outcome.status, RunStatus::NonFiniteOutput);
    EXPECT_NE(nan.outcome.message.find("out.obj:1: 'nan' is not finite"), std::string::npos) << nan.outcome.message;
    const NormalsSubjectComparison words = run(python("import sys; open(sys.argv[2], \"w\").write(\"vn 0 1\\n\")"));
    EXPECT_EQ(words.outcome.status, RunStatus::UnreadableOutput);
    const NormalsSubjectComparison nothing = run(python("pass"));
    EXPECT_EQ(nothing.outcome.status, RunStatus::NoOutput);
    const NormalsSubjectComparison hang = run(python("import time; time.sleep(60)"), "torus", 1);
    EXPECT_EQ(hang.outcome.status, RunStatus::Timeout);
    const NormalsSubjectComparison missing = run("/nonexistent/normals {in} {out}");
    EXPECT_EQ(missing.outcome.status, RunStatus::Crashed);
    for (const auto* c : {&few, &nan, &words, &nothing, &hang, &missing}) EXPECT_FALSE(c->passed());
}

}  // namespace
}  // namespace crossdiv::verification
