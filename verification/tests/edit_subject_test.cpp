// The course's half-edge task with a program in core's place: flips and splits applied in
// order, each prefix compared with core's half-edge mesh; the course-style program agrees,
// including a refused boundary flip, and its two slips are named at the operation they break.
#include <gtest/gtest.h>

#include "crossdiv/verification/comparisons/edit_subject.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

const std::string kEdit = "python3 " + test::kSource + "/examples/subjects/python-edit/edit.py {in} {ops} {out}";

/// On the open patch: an interior flip, a boundary split, a refused boundary flip, an interior
/// split and a flip of an edge the split made.
const std::vector<EditOperation> kOperations =
    parse_edit_operations("flip 6 7, split 0 1, flip 0 5, split 7 12, flip 12 13");

EditSubjectComparison run_edit(const std::string& command) {
    return compare_edit_subject("open-patch", test::bundled("open-patch"), kOperations, "subject", command, 60);
}

TEST(EditSubject, TheCourseProgramAgreesAtEveryOperation) {
    const EditSubjectComparison c = run_edit(kEdit);
    ASSERT_EQ(c.steps.size(), 5u);
    EXPECT_EQ(c.steps[0].core, "flipped to 12-1");
    EXPECT_EQ(c.steps[1].core, "new vertex 25");
    EXPECT_EQ(c.steps[2].core, "refused: boundary edge (one face)");
    EXPECT_EQ(c.steps[3].core, "new vertex 26");
    for (const EditStep& s : c.steps) EXPECT_TRUE(s.agrees()) << s.operation << ": " << s.outcome.summary();
    EXPECT_TRUE(c.passed());
    EXPECT_EQ(c.summary(), "subject 'subject': 5 of 5 operations agree");
}

TEST(EditSubject, ASplitAwayFromTheMidpointAndATurnedFlipAreNamed) {
    const EditSubjectComparison third = run_edit(kEdit + " --third");
    EXPECT_TRUE(third.steps[0].agrees());
    EXPECT_FALSE(third.steps[1].agrees());
    EXPECT_EQ(third.steps[1].worst_vertex, 25);
    EXPECT_NE(third.summary().find("operation 2 (split 0 1; core: new vertex 25): vertex 25 off by"), std::string::npos)
        << third.summary();
    const EditSubjectComparison turned = run_edit(kEdit + " --turned-flip");
    EXPECT_EQ(turned.steps[0].faces_only_in_subject, 2);
    EXPECT_EQ(turned.steps[0].faces_only_in_core, 2);
    EXPECT_FALSE(turned.passed());
}

TEST(EditSubject, AProgramThatFailsGetsItsOutcomeAndABadListIsRefused) {
    const EditSubjectComparison crash = run_edit("python3 -c 'import os, signal; os.kill(os.getpid(), signal.SIGSEGV)' {in} {ops} {out}");
    ASSERT_EQ(crash.steps.size(), 1u);  // one failure is its outcome
    EXPECT_EQ(crash.steps[0].outcome.status, RunStatus::Crashed);
    EXPECT_FALSE(crash.passed());
    const EditSubjectComparison none = run_edit("python3 -c pass {in} {ops} {out}");
    EXPECT_EQ(none.steps[0].outcome.status, RunStatus::NoOutput);
    EXPECT_THROW(parse_edit_operations("flip 1"), InputError);
    EXPECT_THROW(parse_edit_operations("rotate 1 2"), InputError);
    EXPECT_THROW(compare_edit_subject("open-patch", test::bundled("open-patch"), parse_edit_operations("flip 0 24"), "s",
                                      kEdit, 60),
                 InputError);  // no edge joins 0 and 24
}

}  // namespace
}  // namespace crossdiv::verification
