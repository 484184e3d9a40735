// The "did you mean" of the command line: distances counted by hand, and which slips get a
// suggestion.
#include <gtest/gtest.h>

#include "../cli/nearest_name.h"

namespace crossdiv::cli {
namespace {

TEST(NearestName, EditDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps) {
    EXPECT_EQ(edit_distance("", ""), 0);
    EXPECT_EQ(edit_distance("levels", "levels"), 0);
    EXPECT_EQ(edit_distance("level", "levels"), 1);     // one insertion
    EXPECT_EQ(edit_distance("levelss", "levels"), 1);   // one deletion
    EXPECT_EQ(edit_distance("lebels", "levels"), 1);    // one substitution
    EXPECT_EQ(edit_distance("levles", "levels"), 1);    // two neighbours swapped
    EXPECT_EQ(edit_distance("comapre", "compare"), 1);  // the same
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3);   // k->s, e->i, +g
    EXPECT_EQ(edit_distance("", "abc"), 3);
}

TEST(NearestName, SuggestsASlipAndNothingFarOrAmbiguous) {
    const std::vector<std::string> names{"--levels", "--against", "--scheme", "--subject", "--subject-name"};
    EXPECT_EQ(nearest_name("--level", names), "--levels");
    EXPECT_EQ(nearest_name("--agianst", names), "--against");
    EXPECT_EQ(nearest_name("--schme", names), "--scheme");
    EXPECT_EQ(nearest_name("--colour", names), std::nullopt);  // 5 edits from every name
    EXPECT_EQ(nearest_name("--subj", names), std::nullopt);    // the start of two names
    EXPECT_EQ(nearest_name("--sch", names), "--scheme");       // the start of one
    EXPECT_EQ(nearest_name("-x", {"-o"}), std::nullopt);       // 1 edit of 2 characters: no guess
}

}  // namespace
}  // namespace crossdiv::cli
