// The goal lines of `crossdiv bench` from hand-made records: which records a goal reads, its
// figure and its target. Times are made up here; the bench itself never asserts a time.
#include <gtest/gtest.h>

#include <cmath>

#include "crossdiv/verification/bench/bench.h"

namespace crossdiv::verification {
namespace {

BenchRecord record(std::string impl, std::string scheme, std::string memory, long long output_faces, double ms) {
    BenchRecord r;
    r.impl = std::move(impl);
    r.scheme = std::move(scheme);
    r.memory = std::move(memory);
    r.input = "torus";
    r.levels = 2;
    r.output_faces = output_faces;
    r.median_ms = ms;
    return r;
}

TEST(BenchGoals, TheFloorIsTheOutputWrittenOnceAtTheMeasuredBandwidth) {
    // 320000 triangles on a torus: 160000 vertices of 24 bytes and 320000 triangles of 12,
    // 7.68 MB in all; at 8 GB/s that is 0.96 ms.
    EXPECT_DOUBLE_EQ(loop_output_bytes(320000), 160000.0 * 24 + 320000.0 * 12);
    EXPECT_NEAR(floor_ms("loop", 320000, 8.0), 0.96, 1e-12);
    // 100000 quads of a genus-1 mesh: as many vertices; 24 + 16 bytes each, 4 MB: 0.5 ms.
    EXPECT_NEAR(floor_ms("catmull-clark", 100000, 8.0), 0.5, 1e-12);
}

TEST(BenchGoals, LoopIsHeldToItsFloorAndToItsWarmTimeWhenCold) {
    const std::vector<BenchRecord> records = {
        record("core", "loop", "warm", 320000, 1.40), record("core", "loop", "cold", 320000, 2.90),
        record("opensubdiv", "loop", "warm", 320000, 6.0),
        // Too small for a goal, and Catmull-Clark has no goal on its own figures.
        record("core", "loop", "warm", 80000, 0.2), record("core", "catmull-clark", "warm", 320000, 9.0)};
    const std::vector<CoreGoal> goals = core_goals(records, 8.0);
    ASSERT_EQ(goals.size(), 2u);
    EXPECT_EQ(goals[0].kind, CoreGoal::Kind::Floor);
    EXPECT_NEAR(goals[0].ratio, 1.40 / 0.96, 1e-12);  // 1.46: met
    EXPECT_TRUE(goals[0].met());
    EXPECT_EQ(goals[1].kind, CoreGoal::Kind::ColdOverWarm);
    EXPECT_NEAR(goals[1].ratio, 2.90 / 1.40, 1e-12);  // 2.07: not met
    EXPECT_FALSE(goals[1].met());
    EXPECT_EQ(to_json(goals[1])["goal"], "cold over warm");
    EXPECT_EQ(to_json(goals[1])["met"], false);
}

TEST(BenchGoals, ColdLoopMustBeFourTimesTheFastestReferenceAndCatmullClarkNoSlower) {
    const std::vector<BenchRecord> records = {
        record("core", "loop", "cold", 320000, 10.0),          record("cgal", "loop", "cold", 320000, 39.0),
        record("opensubdiv", "loop", "cold", 320000, 45.0),    record("core", "catmull-clark", "cold", 320000, 10.0),
        record("opensubdiv", "catmull-clark", "cold", 320000, 11.0), record("core", "loop", "warm", 320000, 5.0),
        record("opensubdiv", "loop", "warm", 320000, 21.0)};
    const std::vector<BenchGoal> goals = bench_goals(records);
    ASSERT_EQ(goals.size(), 3u);
    EXPECT_EQ(goals[0].fastest_reference, "cgal");
    EXPECT_NEAR(goals[0].ratio, 3.9, 1e-12);
    EXPECT_EQ(goals[0].target, kBenchLoopColdGoalRatio);
    EXPECT_FALSE(goals[0].met());
    EXPECT_EQ(goals[1].target, kBenchColdGoalRatio);
    EXPECT_TRUE(goals[1].met());  // 1.1x
    EXPECT_EQ(goals[2].target, kBenchGoalRatio);
    EXPECT_TRUE(goals[2].met());  // 4.2x
}

TEST(BenchGoals, RatiosPairTheRunsTakenSideBySide) {
    // Round by round the machine ran at full speed, at half, at two thirds: the ratio of the
    // medians (20 / 5 = 4) mixes rounds, the runs side by side give 2, 4 and 3.
    EXPECT_DOUBLE_EQ(paired_ratio({10, 20, 30}, {5, 5, 10}), 3.0);
    EXPECT_TRUE(std::isnan(paired_ratio({}, {1.0})));
    BenchRecord a = record("core", "loop", "cold", 320000, 20), b = record("core", "loop", "warm", 320000, 5);
    EXPECT_DOUBLE_EQ(ratio_of(a, b), 4.0);  // no runs kept: the medians
    a.runs_ms = {10, 20, 30};
    b.runs_ms = {5, 5, 10};
    EXPECT_DOUBLE_EQ(ratio_of(a, b), 3.0);
    // The cold-over-warm goal takes the paired ratio.
    const std::vector<CoreGoal> goals = core_goals({b, a}, 8.0);
    ASSERT_EQ(goals.size(), 2u);
    EXPECT_DOUBLE_EQ(goals[1].ratio, 3.0);
}

}  // namespace
}  // namespace crossdiv::verification
