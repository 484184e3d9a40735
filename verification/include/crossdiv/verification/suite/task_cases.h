#pragma once
/// @file
/// A suite's course-task cases: a subject (a manifest's `subject` or one of a roster's
/// `subjects`) put in core's place for one course task on one input, as the CLI's --subject
/// does it (comparisons/*_subject.h), made a case record the class table reads:
///
///   tessellate       curve files (SWP, BZC): every record's uniform samples and frames
///   casteljau        a one-curve BZC file, t=T (0.5): every level at t
///   patch            BEZ files, res=N (8): positions and normals per grid point
///   sweep            SWP files with srev and gcyl records, frames=recursive|rmf: positions,
///                    normals, faces and watertightness
///   vertex-normals   meshes: the weighting its normals follow
///   flip-split       a mesh, ops='flip 6 7, split 0 1': the mesh after each operation
///
/// The record's rule is the convention the case asks (core's: "as written", "t", "area", ...;
/// in `boundary`), and its subject names the convention the program follows where one fits
/// ("bezier basis", "1 - t", "uniform", "recursive frames, seam left open", ...): the class
/// table's pass, other-rule or fail. A program that fails to run fails the case.

#include <string>

#include "crossdiv/verification/suite/case_record.h"
#include "crossdiv/verification/suite/manifest.h"

namespace crossdiv::verification {

/// Runs the task case `job` (its operation names the task). @throws InputError for an input
/// the task does not take, or a case without a subject.
CaseRecord run_task_case(const SuiteJob& job, const std::string& out_dir);

}  // namespace crossdiv::verification
