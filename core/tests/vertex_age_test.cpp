// Vertex age: birth levels from each level's vertex count (old vertices first), the dual
// scheme's, and the colour scale.

#include <gtest/gtest.h>

#include <algorithm>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/vertex_age.h"

using namespace crossdiv;

// Loop on the icosahedron: 12 vertices, then one new vertex per edge at every level (30, 120,
// 480 edges), so 12, 42, 162, 642 vertices and ages 0 x 12, 1 x 30, 2 x 120, 3 x 480.
TEST(VertexAge, BirthLevelsOfAPrimalScheme) {
    const std::vector<size_t> counts{12, 42, 162, 642};
    const std::vector<int> born = vertex_birth_levels(counts, false);
    ASSERT_EQ(born.size(), 642u);
    for (auto [age, count] : {std::pair{0, 12}, {1, 30}, {2, 120}, {3, 480}})
        EXPECT_EQ(std::count(born.begin(), born.end(), age), count) << age;
    EXPECT_EQ(born[11], 0);
    EXPECT_EQ(born[12], 1);
    EXPECT_EQ(born[41], 1);
    EXPECT_EQ(born[42], 2);
    EXPECT_EQ(born[641], 3);
}

TEST(VertexAge, EveryVertexOfADualSchemeIsNew) {
    const std::vector<size_t> counts{8, 24, 96};  // Doo-Sabin on a cube: 4 corners per face
    const std::vector<int> born = vertex_birth_levels(counts, true);
    EXPECT_EQ(born, std::vector<int>(96, 2));
}

TEST(VertexAge, RefusesCountsThatAreNoRefinement) {
    EXPECT_THROW(vertex_birth_levels(std::vector<size_t>{}, false), InputError);
    const std::vector<size_t> shrinking{12, 10};
    try {
        vertex_birth_levels(shrinking, false);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "level 1 has fewer vertices (10) than level 0 (12): not a refinement that keeps its old vertices");
    }
}

// The scale runs through viridis: the input's vertices dark blue, the newest yellow, each level
// its own colour.
TEST(VertexAge, ColoursRunFromDarkBlueToYellow) {
    EXPECT_EQ(age_color(0, 3), Vec3(0.267, 0.005, 0.329));
    EXPECT_EQ(age_color(3, 3), Vec3(0.993, 0.906, 0.144));
    EXPECT_EQ(age_color(1, 2), Vec3(0.128, 0.567, 0.551));  // viridis(1/2)
    for (int l = 0; l < 3; ++l) EXPECT_GT((age_color(l, 3) - age_color(l + 1, 3)).norm(), 0.2) << l;
    EXPECT_EQ(age_color(0, 0), age_color(0, 3));
}
