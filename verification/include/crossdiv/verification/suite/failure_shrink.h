#pragma once
/// @file
/// After a suite's cases, its failures shrunk to minimal meshes (comparisons/shrink.h), each
/// written into the results folder and named in its record as detail "minimal": mesh, faces,
/// vertices, symptom, tests, and `reproduce` (the `crossdiv compare` line that shows it
/// again), or a note why it was not shrunk.
///
/// - **A subject's first failure** (per scheme, the case its class-table row names), with the
///   subject alone in core's place (its failure or its lack of a named rule must persist):
///   minimal/<roster>-<subject>-<scheme>.obj, in the case's record; the class table links it
///   (roster_table.h).
/// - **A reference's failure**: every run in which a library or program crashed, threw or wrote an
///   invalid result (NaN, wrong counts, an unreadable mesh), and every divergence of one from
///   core that no class explains, with that reference alone (its failure or its divergence
///   must persist): minimal/job<N>-<reference>.obj, in that run's record. Each within
///   kReferenceShrinkSeconds: a real model of 20,000 faces has hundreds of candidates; past the
///   limit the smallest mesh found so far is the result, marked `cut_short`.
///   A failure (crash, invalid result) of the same run of a reference as another case's (same
///   input, scheme, levels and the reference's own rule: cases that differ in core's rule
///   alone) is shrunk once; the other records hold the same result with `same_as`, that case.
///
/// A program reference (MeshLab, Open3D, Blender) is shrunk as a library is: a serving one is
/// handed each candidate as a request (each shrinking child starts it once), and its reproduce
/// line registers it (`--reference`, ProgramSpec's reference_option).
///
/// Not shrunk, with the reason noted: a course task's case (shrink.h takes a scheme's mesh), a
/// subject that hangs or a reference's time-out (each try would cost its time limit), a result
/// file (it cannot be re-run on a smaller input), a failure the comparison run again does not
/// show (a reference reading memory it does not own may fail in one run only).

#include <string>
#include <vector>

#include "crossdiv/verification/suite/case_record.h"
#include "crossdiv/verification/suite/manifest.h"

namespace crossdiv::verification {

/// The time one library failure may take to shrink.
constexpr double kReferenceShrinkSeconds = 60;

/// Shrinks the first failure of every subject and every failure of a library reference in
/// `records` (made from `jobs`), `workers` children at a time, and writes each minimal input
/// into `out_dir`.
void shrink_failures(const std::vector<SuiteJob>& jobs, std::vector<CaseRecord>& records, const std::string& out_dir,
                     int workers);

}  // namespace crossdiv::verification
