#pragma once
// What `crossdiv compare` and `diff` print of a subject (an implementation put in core's
// place), for every scheme: its run, its match to core, the fit of each named rule per vertex
// class, and one verdict line over every input.

#include <map>
#include <set>
#include <string>

#include "crossdiv/verification/comparisons/refinement_comparison.h"

namespace crossdiv::cli {

/// The subject's run, its match to core and the rule fits of each vertex class.
void print_subject(const verification::RefinementComparison& c);

/// Whether the subject fails or follows no named rule on this input: what `crossdiv diff
/// --subject` shrinks.
bool symptom_of_subject(const verification::RefinementComparison& c);

/// What the subject's runs over every input say, in one line, and whether it failed.
struct SubjectVerdict {
    explicit SubjectVerdict(verification::Scheme scheme) : rules(scheme) {}
    verification::RuleTally rules;
    /// Per reference: the runs that agree, and the runs that compared it with the subject.
    std::map<std::string, std::pair<int, int>> reference_agreement;
    std::set<std::string> classes;
    int inputs = 0, failures = 0, unexplained = 0;

    void add(const verification::RefinementComparison& c);
    std::string line(const std::string& name) const;
    /// A subject fails when it fails to run or diverges unexplained; a named rule it follows
    /// that a reference lacks is a diagnosis, not a failure.
    bool failed() const { return failures || unexplained; }
};

}  // namespace crossdiv::cli
