// A reference that crashes, throws, refuses or hangs is recorded, and the caller goes on.
#include <gtest/gtest.h>

#include <csignal>
#include <thread>

#include "crossdiv/verification/harness/isolate.h"

namespace crossdiv::verification {
namespace {

adapters::LevelTrace small_trace() {
    PolyMesh m;
    m.positions = {Vec3(0.1, 0.2, 0.3), Vec3(1, 0, 0), Vec3(0, 1, 1.0 / 3.0)};
    m.add_face({0, 1, 2});
    return {m, m};
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
