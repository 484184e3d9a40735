// The nearest points of a fixed set, against a search through every point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "crossdiv/verification/harness/nearest_points.h"

namespace crossdiv::verification {
namespace {

/// The k nearest by looking at every point: squared distances summed as the index does (x, y,
/// then z), nearest first, equally near by index.
std::vector<std::pair<double, unsigned>> every_point(const std::vector<Vec3>& set, const Vec3& q, size_t k) {
    std::vector<std::pair<double, unsigned>> all;
    for (size_t i = 0; i < set.size(); ++i) {
        if (!set[i].allFinite()) continue;
        const double dx = q[0] - set[i][0], dy = q[1] - set[i][1], dz = q[2] - set[i][2];
        all.push_back({dx * dx + dy * dy + dz * dz, static_cast<unsigned>(i)});
    }
    std::sort(all.begin(), all.end());
    all.resize(std::min(k, all.size()));
    return all;
}

/// The index's answer equals the search through every point: the same squared distances in
/// order, and the same points (equally near ones in any order).
void expect_exact(const NearestPoints& index, const std::vector<Vec3>& set, const Vec3& q, size_t k) {
    unsigned ids[NearestPoints::kMaxNeighbours];
    double d2[NearestPoints::kMaxNeighbours];
    const size_t n = index.nearest(q, k, ids, d2);
    const auto expected = every_point(set, q, k);
    ASSERT_EQ(n, expected.size());
    std::vector<std::pair<double, unsigned>> got;
    for (size_t i = 0; i < n; ++i) got.push_back({d2[i], ids[i]});
    for (size_t i = 0; i < n; ++i) EXPECT_EQ(got[i].first, expected[i].first) << "neighbour " << i;
    // The last distance may be shared by points beyond k: those are equally right.
    std::sort(got.begin(), got.end());
    for (size_t i = 0; i < n; ++i) {
        if (expected[i].first < expected[n - 1].first) {
            EXPECT_EQ(got[i].second, expected[i].second);
        }
    }
}

std::vector<Vec3> random_points(size_t n, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-3.0, 5.0);
    std::vector<Vec3> p(n);
    for (Vec3& x : p) x = Vec3(u(rng), u(rng), 0.25 * u(rng));
    return p;
}

TEST(NearestPoints, AnswersAsASearchThroughEveryPoint) {
    std::mt19937 rng(7);
    const std::vector<Vec3> set = random_points(3000, rng);
    const NearestPoints index(set);
    std::uniform_real_distribution<double> u(-4.0, 6.0), tiny(-1e-12, 1e-12);
    for (int i = 0; i < 300; ++i) {
        // A set point moved by a rounding (the common query), and a point anywhere, inside the
        // box or out of it.
        const Vec3& p = set[static_cast<size_t>(i) * 7];
        for (const Vec3& q : {Vec3(p + Vec3(tiny(rng), tiny(rng), tiny(rng))), Vec3(u(rng), u(rng), u(rng))})
            for (size_t k : {size_t{1}, size_t{2}, size_t{8}}) expect_exact(index, set, q, k);
    }
}

TEST(NearestPoints, TwoRefinementsOfOneSurfaceAlmostNeverNeedTheTree) {
    // The points of one set moved by roundings: each query's nearest is its own point, alone
    // within the slack, found in its cell.
    std::mt19937 rng(11);
    const std::vector<Vec3> set = random_points(20000, rng);
    const NearestPoints index(set);
    std::uniform_real_distribution<double> tiny(-1e-14, 1e-14);
    unsigned ids[2];
    double d2[2];
    for (size_t i = 0; i < set.size(); ++i) {
        const Vec3 q = set[i] + Vec3(tiny(rng), tiny(rng), tiny(rng));
        ASSERT_EQ(index.nearest(q, 1, ids, d2), 1u);
        ASSERT_EQ(ids[0], i);
        ASSERT_EQ(index.nearest_within(q, 2, 1e-12, ids, d2), 1u) << "no copy of point " << i;
        ASSERT_EQ(ids[0], i);
    }
    // Cells of 8/65,536 here: a query within 1e-12 of a wall is one in some 10^7.
    EXPECT_EQ(index.tree_queries(), 0u);
}

TEST(NearestPoints, TheNearestWithinASlackAreItsCopies) {
    std::mt19937 rng(13);
    std::vector<Vec3> set = random_points(400, rng);
    for (int i = 0; i < 3; ++i) set.push_back(set[5]);                          // exact copies
    set.push_back(set[9] + Vec3(1e-15, 0, 0));                                  // a rounding away
    for (int i = 0; i < 12; ++i) set.push_back(set[30] + Vec3(0, 1e-15 * i, 0));  // more than 8
    const NearestPoints index(set);
    unsigned ids[8];
    double d2[8];
    EXPECT_EQ(index.nearest_within(set[5], 8, 1e-13, ids, d2), 4u);
    std::sort(ids, ids + 4);
    EXPECT_EQ(std::vector<unsigned>(ids, ids + 4), (std::vector<unsigned>{5, 400, 401, 402}));
    EXPECT_EQ(index.nearest_within(set[9], 8, 1e-13, ids, d2), 2u);
    EXPECT_EQ(index.nearest_within(set[9], 8, 0.0, ids, d2), 1u) << "no slack: only the point itself";
    EXPECT_EQ(index.nearest_within(set[30], 8, 1e-13, ids, d2), 8u) << "at most k";
    EXPECT_EQ(index.nearest_within(set[31], 1, 1e-13, ids, d2), 1u);
    EXPECT_EQ(ids[0], 31u);
}

TEST(NearestPoints, ANearerPointBeyondTheCellsWallIsFound) {
    // A box 65,536 long in x: cells of 1, walls at 0.5 + i (half a cell of room below 0). The
    // query at 10.45 shares its cell [9.5, 10.5) with the point at 9.6 (0.85 away); the point at
    // 10.55 (0.1 away) lies beyond the wall, in the next cell.
    const std::vector<Vec3> set = {Vec3(0, 0, 0), Vec3(65536, 1, 1), Vec3(9.6, 0, 0), Vec3(10.55, 0, 0)};
    const NearestPoints index(set);
    unsigned ids[2];
    double d2[2];
    ASSERT_EQ(index.nearest(Vec3(10.45, 0, 0), 1, ids, d2), 1u);
    EXPECT_EQ(ids[0], 3u);
    EXPECT_EQ(d2[0], (10.45 - 10.55) * (10.45 - 10.55));
    // Within a slack that reaches past the wall: the point beyond it too.
    EXPECT_EQ(index.nearest_within(Vec3(9.9, 0, 0), 2, 0.5, ids, d2), 2u);
    EXPECT_EQ(ids[0], 2u);
    EXPECT_EQ(ids[1], 3u);
    EXPECT_EQ(index.nearest_within(Vec3(9.9, 0, 0), 2, 0.1, ids, d2), 1u);
}

TEST(NearestPoints, CopiesAtOnePlaceAndACrowdedCellAreExact) {
    std::mt19937 rng(3);
    std::vector<Vec3> set = random_points(500, rng);
    // 40 copies of one point (more than a cell holds before the tree takes its queries) and 5
    // of another.
    for (int i = 0; i < 40; ++i) set.push_back(Vec3(1, 1, 0.5));
    for (int i = 0; i < 5; ++i) set.push_back(set[17]);
    const NearestPoints index(set);
    for (size_t k : {size_t{1}, size_t{2}, size_t{8}}) {
        expect_exact(index, set, Vec3(1, 1, 0.5), k);
        expect_exact(index, set, set[17], k);
        expect_exact(index, set, set[17] + Vec3(1e-13, 0, 0), k);
    }
    EXPECT_GT(index.tree_queries(), 0u) << "the crowded cell's queries go to the tree";
}

TEST(NearestPoints, APointThatIsNotFiniteIsNeverANeighbour) {
    std::mt19937 rng(5);
    std::vector<Vec3> set = random_points(200, rng);
    set[10] = Vec3(NAN, 0, 0);
    set[20] = Vec3(INFINITY, 1, 1);
    const NearestPoints index(set);
    for (size_t i = 0; i < set.size(); i += 9) {
        if (set[i].allFinite()) {
            expect_exact(index, set, set[i], 2);
        }
    }
}

TEST(NearestPoints, FlatAndSinglePointSetsAndTheEmptySet) {
    // Every point at one place; a flat set (one axis of no extent); no point.
    const std::vector<Vec3> same(3, Vec3(2, 2, 2));
    const NearestPoints one_place(same);
    expect_exact(one_place, same, Vec3(2, 2, 2), 8);
    expect_exact(one_place, same, Vec3(0, 0, 0), 1);
    std::vector<Vec3> flat;
    for (int i = 0; i < 50; ++i) flat.push_back(Vec3(i * 0.1, (i * 7 % 13) * 0.3, 0));
    const NearestPoints flat_index(flat);
    for (const Vec3& q : flat) expect_exact(flat_index, flat, q, 2);
    const std::vector<Vec3> none;
    const NearestPoints empty(none);
    unsigned id;
    double d2;
    EXPECT_EQ(empty.nearest(Vec3(0, 0, 0), 1, &id, &d2), 0u);
}

}  // namespace
}  // namespace crossdiv::verification
