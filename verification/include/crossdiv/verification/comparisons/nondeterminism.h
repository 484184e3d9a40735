#pragma once
/// @file
/// A reference whose result depends on memory it never wrote gives another answer from run to
/// run (OpenMesh's Loop leaves an isolated vertex's new position unset), and a class read off
/// one run would flip between runs of the same suite. Every isolated run fills its heap with
/// kHeapFill first (isolate.h); each run of a reference in a child is run a second time with
/// kSecondHeapFill, and a result that changes is recorded as ref-nondeterministic, keeping the
/// first run's class and naming where the two runs part. (A library run takes milliseconds on
/// the suite's meshes: 1,900 of them took 16.5 s in all, so the second run costs little.)

#include <optional>
#include <string>

#include "crossdiv/verification/harness/isolate.h"

namespace crossdiv::verification {

/// Where two runs' results part, in words: their statuses, the first level whose counts
/// differ, the first vertex whose position differs in any bit (both values; a NaN equals itself
/// bit for bit), or the first level whose faces differ; nothing when they are the same.
std::optional<std::string> first_difference(const IsolatedTrace& a, const IsolatedTrace& b);

/// Whether a run that ended so is run a second time: it made a result, or failed in a way
/// another run could change (crashed, threw, an invalid result); not a timeout, which would cost
/// the limit again, nor a refusal, which is the library's decision about its input.
bool reruns_for_determinism(RunStatus status);

}  // namespace crossdiv::verification
