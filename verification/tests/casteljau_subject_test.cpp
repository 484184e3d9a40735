// The course's de Casteljau task with a program in core's place: the course-style program at
// the t it is told, its swapped weights named, and the ways a program fails.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "crossdiv/io/curve_io.h"
#include "crossdiv/verification/comparisons/casteljau_subject.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;

struct Quintic {
    fs::path path = fs::temp_directory_path() / ("crossdiv_casteljau_" + std::to_string(::getpid()) + ".bzc");
    CurveFile file;
    Quintic() {
        std::ofstream(path) << "6\n0 0  1 2  2 -1  3 3  4 0  5 1\n";  // degree 5: six levels
        file = read_curve_file(path.string());
    }
    ~Quintic() { fs::remove(path); }
    CasteljauSubjectComparison run(const std::string& command, double t = 0.25) const {
        return compare_casteljau_subject(path.string(), file, t, "subject", command, 60);
    }
};

const std::string kCasteljau = "python3 " + test::kSource + "/examples/subjects/python-casteljau/casteljau.py {in} ";

TEST(CasteljauSubject, TheCourseProgramAgreesAtEveryLevelAndItsSwappedWeightsAreNamed) {
    const Quintic q;
    const CasteljauSubjectComparison ok = q.run(kCasteljau + "0.25 {out}");
    ASSERT_EQ(ok.outcome.status, RunStatus::Ok) << ok.outcome.summary();
    EXPECT_EQ(ok.levels, 6);
    EXPECT_LE(ok.max_at_t, 1e-15);
    EXPECT_TRUE(ok.passed()) << ok.summary();

    const CasteljauSubjectComparison swapped = q.run(kCasteljau + "0.25 {out} --swapped");
    EXPECT_EQ(swapped.parameter, "1 - t");
    EXPECT_FALSE(swapped.passed());

    // Told another t than crossdiv compares at: neither parameter fits, the worst level named.
    const CasteljauSubjectComparison other = q.run(kCasteljau + "0.3 {out}");
    EXPECT_EQ(other.parameter, "");
    EXPECT_EQ(other.worst_level, 5);  // the point on the curve moves most
    EXPECT_FALSE(other.passed());
}

TEST(CasteljauSubject, AProgramThatFailsGetsItsOutcome) {
    const Quintic q;
    const auto python = [&](const std::string& code) { return q.run("python3 -c '" + code + "' {in} {out}"); };
    const CasteljauSubjectComparison one = python("import sys; open(sys.argv[2], \"w\").write(\"0 0 1 1\\n\")");
    EXPECT_EQ(one.outcome.status, RunStatus::WrongCount);
    EXPECT_EQ(one.outcome.message, "out.txt: 1 levels; a curve of degree 5 has 6");
    const CasteljauSubjectComparison odd = python("import sys; open(sys.argv[2], \"w\").write(\"0 0 1\\n\")");
    EXPECT_EQ(odd.outcome.status, RunStatus::UnreadableOutput);
    EXPECT_EQ(odd.outcome.message, "out.txt:1: 3 numbers: not points of 2 coordinates");
    const CasteljauSubjectComparison nan = python("import sys; open(sys.argv[2], \"w\").write(\"0 nan\\n\")");
    EXPECT_EQ(nan.outcome.status, RunStatus::NonFiniteOutput);
    const CasteljauSubjectComparison none = python("pass");
    EXPECT_EQ(none.outcome.status, RunStatus::NoOutput);
    const CasteljauSubjectComparison exits = python("raise SystemExit(4)");
    EXPECT_EQ(exits.outcome.status, RunStatus::ExitStatus);
    for (const auto* c : {&one, &odd, &nan, &none, &exits}) EXPECT_FALSE(c->passed());
}

}  // namespace
}  // namespace crossdiv::verification
