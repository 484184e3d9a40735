// The course's curve task with a program in core's place: the course-style Python tessellator
// named by its basis and frame rule, a swapped basis matrix named, every way a program fails
// given its outcome, and crossdiv's own tessellate as a subject of each frame rule.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "crossdiv/io/curve_io.h"
#include "crossdiv/verification/comparisons/curve_subject.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using test::kSource;

/// Two planar and two space curves, the B-spline of three segments, the Bezier chain of two.
const char* kCurves = R"(bez2 . 8 7
[0 0]
[1 1]
[2 1]
[3 0]
[4 -1]
[5 -1]
[6 0]

bsp2 . 6 6
[0 0]
[1 1]
[2 1]
[3 0]
[4 -1]
[5 0]

bez3 . 10 4
[-1 -2 0]
[0 -1 1]
[0 1 -1]
[1 -2 0]

bsp3 . 10 5
[-2 0 1]
[0 2 1]
[0 3 -1]
[2 0 -1]
[3 1 0]
)";

struct CurveFixture {
    fs::path dir = fs::temp_directory_path() / ("crossdiv_curve_subject_" + std::to_string(::getpid()));
    std::string path = (dir / "four.swp").string();
    CurveFile file;
    CurveFixture() {
        fs::create_directories(dir);
        std::ofstream(path) << kCurves;
        file = read_curve_file(path);
    }
    ~CurveFixture() { fs::remove_all(dir); }
    CurveSubjectComparison run(const std::string& command, double timeout = 60) const {
        return compare_curve_subject(path, file, "subject", command, timeout);
    }
};

const std::string kExample = "python3 " + kSource + "/examples/subjects/python-curves/tessellate.py {in} {out}";

std::string misbehaving_curves(const std::string& mode) {
    return "python3 " + kSource + "/verification/tests/subjects/misbehaving_curves.py " + mode + " {in} {out}";
}

TEST(CurveSubject, TheCourseProgramFollowsTheRecordsAndTheRecursiveFrame) {
    const CurveFixture f;
    const CurveSubjectComparison c = f.run(kExample);
    ASSERT_EQ(c.outcome.status, RunStatus::Ok) << c.outcome.summary();
    ASSERT_EQ(c.curves.size(), 4u);
    // Samples: STEPS per segment, joints shared: 2 * 8 + 1, 3 * 6 + 1, 11, 2 * 10 + 1.
    const std::vector<int> counts = {17, 19, 11, 21};
    for (size_t i = 0; i < 4; ++i) {
        const CurveSubjectCurve& k = c.curves[i];
        EXPECT_EQ(k.core_samples, counts[i]) << k.curve;
        EXPECT_EQ(k.position_rule, "as written") << k.curve;
        EXPECT_EQ(k.frame_rule, "recursive") << k.curve;
        EXPECT_LE(k.tangent_deg, 1e-9) << k.curve;
        EXPECT_LE(k.binormal_deg, 1e-9) << k.curve;
    }
    // The space curves tell the frame rules apart: the rotation-minimizing frame turns less.
    for (const CurveConventionFit& fit : c.curves[3].frames) {
        if (fit.name == "rmf") {
            EXPECT_GT(fit.max, 1.0) << "rmf and recursive coincide on the bsp3 curve";
        }
    }
    EXPECT_TRUE(c.passed()) << c.summary();
}

TEST(CurveSubject, ASwappedBasisMatrixIsNamedAndFails) {
    const CurveFixture f;
    const CurveSubjectComparison c = f.run(kExample + " --bspline-as-bezier");
    ASSERT_EQ(c.outcome.status, RunStatus::Ok) << c.outcome.summary();
    EXPECT_EQ(c.curves[0].position_rule, "as written");
    EXPECT_EQ(c.curves[1].position_rule, "bezier basis");
    EXPECT_EQ(c.curves[3].position_rule, "bezier basis");
    EXPECT_FALSE(c.passed());
    EXPECT_NE(c.summary().find("bezier basis on 2 of 4"), std::string::npos) << c.summary();
}

TEST(CurveSubject, CrossdivsOwnTessellationIsASubjectOfEachFrameRule) {
    const CurveFixture f;
    for (const char* frames : {"recursive", "rmf"}) {
        const CurveSubjectComparison c = f.run(test::kCrossdiv + " tessellate {in} -o {out} --frames " + frames);
        ASSERT_EQ(c.outcome.status, RunStatus::Ok) << c.outcome.summary();
        EXPECT_EQ(c.curves[3].frame_rule, frames);
        EXPECT_EQ(c.curves[3].positions.front().max, 0);  // 17 significant digits, the same sums
        EXPECT_TRUE(c.passed()) << c.summary();
    }
}

struct CurveFailure {
    const char* mode;
    RunStatus status;
    const char* in_message;
};

class CurveProgramFailure : public ::testing::TestWithParam<CurveFailure> {};

TEST_P(CurveProgramFailure, IsNamed) {
    const CurveFixture f;
    const CurveFailure m = GetParam();
    const CurveSubjectComparison c = f.run(misbehaving_curves(m.mode), std::string_view(m.mode) == "hang" ? 2 : 60);
    EXPECT_EQ(c.outcome.status, m.status) << c.outcome.summary();
    EXPECT_NE(c.outcome.message.find(m.in_message), std::string::npos) << c.outcome.message;
    EXPECT_FALSE(c.passed());
}

INSTANTIATE_TEST_SUITE_P(Modes, CurveProgramFailure,
                         ::testing::Values(CurveFailure{"crash", RunStatus::Crashed, "signal 11"},
                                           CurveFailure{"hang", RunStatus::Timeout, "no result after 2 s"},
                                           CurveFailure{"nothing", RunStatus::NoOutput, "no output file out.csv"},
                                           CurveFailure{"nan", RunStatus::NonFiniteOutput, "out.csv:3: y"},
                                           CurveFailure{"garbage", RunStatus::UnreadableOutput, "out.csv:3: x '1.2.3'"}),
                         [](const auto& info) { return std::string(info.param.mode); });

TEST(CurveSubject, ADroppedSampleAFrenetFrameAndAnUnnormalizedTangentAreNamed) {
    const CurveFixture f;
    const CurveSubjectComparison shorter = f.run(misbehaving_curves("short"));
    ASSERT_EQ(shorter.outcome.status, RunStatus::Ok);
    EXPECT_EQ(shorter.curves[0].problem, "16 samples where core makes 17 (STEPS 8 intervals per segment)");
    EXPECT_FALSE(shorter.passed());

    // Frenet's frame is named where it is defined; it flips at the S-curve's inflection (no
    // planar rule fits), and on the B-spline whose inflection falls on a sample it is undefined
    // there: the program writes a zero normal, which no rule fits.
    const CurveSubjectComparison frenet = f.run(misbehaving_curves("frenet"));
    EXPECT_EQ(frenet.curves[0].frame_rule, "frenet");
    EXPECT_EQ(frenet.curves[1].frame_rule, "");
    EXPECT_EQ(frenet.curves[2].frame_rule, "frenet");
    EXPECT_EQ(frenet.curves[3].frame_rule, "frenet");
    EXPECT_FALSE(frenet.passed());

    const CurveSubjectComparison unit = f.run(misbehaving_curves("unit"));
    EXPECT_LE(unit.curves[0].tangent_deg, 1e-9);
    EXPECT_GT(unit.curves[0].tangent_length, 0.5);
    EXPECT_FALSE(unit.passed());
    EXPECT_NE(unit.summary().find("tangents not unit on 4 of 4"), std::string::npos) << unit.summary();
}

}  // namespace
}  // namespace crossdiv::verification
