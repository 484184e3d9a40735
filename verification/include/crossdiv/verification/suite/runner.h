#pragma once
/// @file
/// Running a suite's jobs: one job in this process, or a list of them with worker processes
/// (fork), each worker writing its records to a file of its own and the job index to a pipe
/// so that progress is reported as jobs finish. A worker that dies takes only its unfinished
/// jobs with it: they are recorded as failures of ours, and the run goes on.

#include <functional>
#include <string>
#include <vector>

#include "crossdiv/verification/suite/case_record.h"
#include "crossdiv/verification/suite/manifest.h"

namespace crossdiv::verification {

/// Runs one job with its operation. Never throws for bad input: a file core cannot read is
/// recorded as core's refusal, an internal error as core's failure.
CaseRecord run_job(const SuiteJob& job, const std::string& out_dir);

/// Runs `jobs` with `workers` processes; `progress(done, total, record)` is called in this
/// process after each job. Records come back ordered by job index.
std::vector<CaseRecord> run_jobs(const std::vector<SuiteJob>& jobs, int workers, const std::string& out_dir,
                                 const std::function<void(int, int, const CaseRecord&)>& progress);

/// One line for progress output: each reference's outcome, or the checks' tally, or core's
/// refusal or failure.
std::string describe_record(const CaseRecord& c);

}  // namespace crossdiv::verification
