#pragma once
/// @file
/// The minimal failing input of every subject of a suite run: after the cases, the first case
/// each subject fails (per scheme, the case its class-table row names) is shrunk with the
/// subject alone in core's place (comparisons/shrink.h: its failure or its lack of a named rule
/// must persist), the minimal mesh written as minimal/<subject>-<scheme>.obj and named in that
/// case's record (detail "minimal": mesh, faces, vertices, symptom, tests; or a note why it was
/// not shrunk). The class table links it (roster_table.h).
///
/// Not shrunk, with the reason noted: a course task's case (shrink.h takes a scheme's mesh), a subject that hangs (each try would cost its time
/// limit), a result file (it cannot be re-run on a smaller input), a failure the smaller runs do
/// not reproduce.

#include <string>
#include <vector>

#include "crossdiv/verification/suite/case_record.h"
#include "crossdiv/verification/suite/manifest.h"

namespace crossdiv::verification {

/// Shrinks the first failure of every subject in `records` (made from `jobs`), `workers`
/// children at a time, and writes each minimal input into `out_dir`.
void shrink_subject_failures(const std::vector<SuiteJob>& jobs, std::vector<CaseRecord>& records, const std::string& out_dir,
                             int workers);

}  // namespace crossdiv::verification
