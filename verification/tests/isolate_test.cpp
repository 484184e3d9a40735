// A reference that crashes, throws, refuses or hangs is recorded, and the caller goes on.
#include <gtest/gtest.h>

#include <cstdlib>

#include <chrono>
#include <csignal>
#include <thread>

#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/implementations/isolated_calls.h"

namespace crossdiv::verification {
namespace {

adapters::LevelTrace small_trace() {
    PolyMesh m;
    m.positions = {Vec3(0.1, 0.2, 0.3), Vec3(1, 0, 0), Vec3(0, 1, 1.0 / 3.0)};
    m.add_face({0, 1, 2});
    return {m, m};
}

TEST(StderrSummary, KeepsASanitizersFirstReportLineBeforeItsLegend) {
    std::string legend;
    for (int i = 0; i < 40; ++i) legend += "  Heap left redzone:       fa\n";
    const std::string report = "==77==ERROR: AddressSanitizer: heap-buffer-overflow on address 0x6020 at pc 0x55";
    const std::string summary = stderr_summary("some output\n" + report + "\n" + legend, 100);
    EXPECT_EQ(summary.substr(0, report.size()), report);
    EXPECT_NE(summary.find(report + " ..."), std::string::npos) << summary;
    EXPECT_NE(summary.find("Heap left redzone"), std::string::npos) << summary;
    EXPECT_EQ(summary.find('\n'), std::string::npos);
    // Short text is kept whole; without a report only the tail is kept.
    EXPECT_EQ(stderr_summary("a\nb\n", 100), "a b");
    EXPECT_EQ(stderr_summary(legend, 20).substr(0, 3), "...");
    // UBSan's form names the file and line.
    const std::string ub = "core/x.cpp:12:7: runtime error: signed integer overflow";
    EXPECT_EQ(stderr_summary(ub + "\n" + legend, 50).substr(0, ub.size()), ub);
}

TEST(Isolate, ResultCrossesTheProcessBoundaryBitExact) {
    const IsolatedTrace r = run_isolated(small_trace, 30);
    ASSERT_EQ(r.outcome.status, RunStatus::Ok) << r.outcome.summary();
    ASSERT_TRUE(r.trace.has_value());
    ASSERT_EQ(r.trace->size(), 2u);
    EXPECT_EQ((*r.trace)[1].positions, small_trace()[1].positions);
    EXPECT_EQ((*r.trace)[1].face_vertices, (std::vector<int>{0, 1, 2}));
}

TEST(Isolate, CrashIsRecordedWithItsSignal) {
    const IsolatedTrace r = run_isolated([]() -> adapters::LevelTrace { std::raise(SIGSEGV); return {}; }, 30);
    EXPECT_EQ(r.outcome.status, RunStatus::Crashed);
    EXPECT_NE(r.outcome.summary().find("crashed: signal 11"), std::string::npos) << r.outcome.summary();
}

TEST(Isolate, AbortAfterWritingToStderrKeepsTheMessage) {
    const IsolatedTrace r = run_isolated(
        []() -> adapters::LevelTrace {
            std::fputs("assertion failed: valence < 50\n", stderr);
            std::abort();
        },
        30);
    EXPECT_EQ(r.outcome.status, RunStatus::Crashed);
    EXPECT_NE(r.outcome.message.find("assertion failed: valence < 50"), std::string::npos) << r.outcome.message;
}

TEST(Isolate, RejectedAndThrownAreTold) {
    const IsolatedTrace rej = run_isolated([]() -> adapters::LevelTrace { throw adapters::Rejected("no quads"); }, 30);
    EXPECT_EQ(rej.outcome.summary(), "rejected: no quads");
    const IsolatedTrace thr = run_isolated([]() -> adapters::LevelTrace { throw std::runtime_error("boom"); }, 30);
    EXPECT_EQ(thr.outcome.summary(), "threw: boom");
}

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ISOLATE_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define ISOLATE_TEST_ASAN 1
#endif

// A run that asks for more than kIsolatedMemoryBytes fails in its child and is recorded as
// failed: the 7 GiB are never reserved. In a plain build the RLIMIT_AS cap makes it
// std::bad_alloc. Under the address sanitizer RLIMIT_AS cannot be used (its shadow memory
// needs terabytes of address space); the same cap is then the sanitizer's
// max_allocation_size_mb, which run.sh sets, and the child dies with the sanitizer's report:
// a crash, recorded as such.
TEST(Isolate, AChildPastTheMemoryCapIsToldSo) {
#ifdef ISOLATE_TEST_ASAN
    const char* options = std::getenv("ASAN_OPTIONS");
    ASSERT_TRUE(options && std::string(options).find("max_allocation_size_mb=6144") != std::string::npos)
        << "run the sanitizer tests through ./run.sh sanitize, which caps allocations at kIsolatedMemoryBytes";
#endif
    const IsolatedTrace r = run_isolated(
        []() -> adapters::LevelTrace {
            std::vector<char> huge(static_cast<size_t>(kIsolatedMemoryBytes + (1LL << 30)));
            huge.back() = 1;
            return {};
        },
        30);
#ifdef ISOLATE_TEST_ASAN
    EXPECT_EQ(r.outcome.status, RunStatus::Crashed) << r.outcome.summary();
#else
    EXPECT_EQ(r.outcome.status, RunStatus::Threw);
    EXPECT_NE(r.outcome.message.find("bad_alloc"), std::string::npos) << r.outcome.message;
#endif
}

TEST(Isolate, HangIsKilledAtTheTimeLimit) {
    const IsolatedTrace r = run_isolated(
        []() -> adapters::LevelTrace {
            for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
        },
        0.3);
    EXPECT_EQ(r.outcome.status, RunStatus::Timeout);
    EXPECT_GE(r.outcome.seconds, 0.3);
    EXPECT_LT(r.outcome.seconds, 10.0);
}

TEST(Isolate, ExitWithoutAnswerIsACrash) {
    const IsolatedTrace r = run_isolated([]() -> adapters::LevelTrace { std::_Exit(3); }, 30);
    EXPECT_EQ(r.outcome.status, RunStatus::Crashed);
    EXPECT_NE(r.outcome.message.find("exited with code 3"), std::string::npos) << r.outcome.message;
}

}  // namespace
}  // namespace crossdiv::verification

namespace crossdiv::verification {
namespace {

/// A library whose curvature estimator crashes, whose Hausdorff distance hangs and whose
/// simplification refuses; its curvatures on a mesh of three vertices come back when asked
/// with `honest`.
class MisbehavingLibrary final : public Implementation {
public:
    explicit MisbehavingLibrary(bool honest)
        : Implementation("misbehaving", "test", ImplementationKind::Library,
                         {.schemes = {}, .curvatures = true, .hausdorff_distance = true, .simplification = true}),
          honest_(honest) {}
    PrincipalCurvatures curvatures(const TriMesh& m) const override {
        if (!honest_) std::abort();
        PrincipalCurvatures c{"made up", {1, 0, 1}, {1, 2, 3}, {-1, -2, -3}, {0, 0.5, 1}, {-1, -4, -9}, {}};
        c.direction1 = {Vec3(1, 0, 0), Vec3::Zero(), Vec3(0, 0.6, 0.8)};
        c.k1.resize(m.positions.size());
        return c;
    }
    double hausdorff_distance(const TriMesh&, const TriMesh&) const override {
        std::this_thread::sleep_for(std::chrono::seconds(30));
        return 0;
    }
    TriMesh simplify(const TriMesh&, int) const override { throw adapters::Rejected("no edge can be collapsed"); }

private:
    bool honest_;
};

TriMesh one_triangle() {
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    m.triangles = {{0, 1, 2}};
    return m;
}

// The library calls besides refinement (curvature, Hausdorff distance, simplification) run
// isolated: a crash, a hang and a refusal are outcomes, and the caller goes on.
TEST(IsolatedCalls, ALibraryThatCrashesHangsOrRefusesIsAnOutcome) {
    const MisbehavingLibrary lib(false);
    const TriMesh m = one_triangle();
    const IsolatedValue<PrincipalCurvatures> c = curvatures_isolated(lib, m);
    EXPECT_EQ(c.outcome.status, RunStatus::Crashed) << c.outcome.summary();
    EXPECT_NE(c.outcome.message.find("signal 6"), std::string::npos) << c.outcome.message;
    EXPECT_FALSE(c.value);
    const IsolatedValue<double> h = hausdorff_isolated(lib, m, m, 0.5);
    EXPECT_EQ(h.outcome.status, RunStatus::Timeout);
    EXPECT_FALSE(h.value);
    const IsolatedValue<TriMesh> s = simplify_isolated(lib, m, 1);
    EXPECT_EQ(s.outcome.status, RunStatus::Rejected);
    EXPECT_EQ(s.outcome.message, "no edge can be collapsed");
}

TEST(IsolatedCalls, CurvaturesCrossTheProcessBoundaryIntact) {
    const MisbehavingLibrary lib(true);
    const TriMesh m = one_triangle();
    const IsolatedValue<PrincipalCurvatures> c = curvatures_isolated(lib, m);
    ASSERT_TRUE(c.value) << c.outcome.summary();
    const PrincipalCurvatures want = lib.curvatures(m);
    EXPECT_EQ(c.value->method, "made up");
    EXPECT_EQ(c.value->estimated, want.estimated);
    EXPECT_EQ(c.value->k1, want.k1);
    EXPECT_EQ(c.value->k2, want.k2);
    EXPECT_EQ(c.value->mean, want.mean);
    EXPECT_EQ(c.value->gaussian, want.gaussian);
    EXPECT_EQ(c.value->direction1, want.direction1);
}

}  // namespace
}  // namespace crossdiv::verification
