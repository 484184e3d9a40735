#pragma once
/// @file
/// A suite's invariance cases (comparisons/invariance.h): each implementation of the case's
/// scheme (core and the references, or the subject in core's place) refines a mesh and the mesh
/// written otherwise, and must give the same surface. A case line
///
///     case bundled:all,edgecases:all invariance scheme=loop levels=2 [impls=core,opensubdiv]
///          [transform=rotate-corners,...] [seed=K] [boundary=..] [weights=..] [fvar=..] [tolerance=..]
///
/// makes one record per input with one run per implementation and transformation, a check
/// whose subject is the implementation and whose check is the transformation:
///
///   invariant                  agree
///   not-compared               not-compared (vertices at one position: only point sets agree)
///   not-invariant              diverge, classed by explain_not_invariant for a reference
///                              (isolated-vertex-handling, non-manifold-handling, valence-limit,
///                              degenerate-face-handling); for core or a subject always
///                              unexplained, a failure, with the measured cause in its explanation
///   nondeterministic           ref-nondeterministic (with its class) for a reference; for core
///                              or a subject a failure
///
/// An implementation whose run on the input itself fails has one run, check "input": a
/// reference's ref-rejected / ref-crashed / ref-invalid-output, core's (or the subject's)
/// ours-rejected classed by what the input breaks, a failure unless the case declares it
/// (refuses=), as in the comparisons. Each implementation's first failing finding (a reference's
/// first unexplained one, else its first) is shrunk by delta
/// debugging within kInvarianceShrinkSeconds and written beside the results
/// (invariance/jobN-IMPL-TRANSFORM.obj) with the command that reproduces it.

#include <cstdint>
#include <optional>
#include <string>

#include "crossdiv/verification/comparisons/invariance.h"
#include "crossdiv/verification/suite/case_record.h"
#include "crossdiv/verification/suite/manifest.h"

namespace crossdiv::verification {

/// The time one finding may take to shrink, as a library's failure in a comparison
/// (failure_shrink.h): a catalog mesh takes tens of checks of milliseconds each; a real model
/// of 20,000 faces, whose every check refines it twice, hundreds of checks of up to a second,
/// and past the limit the smallest input found so far is the result, marked cut short.
inline constexpr double kInvarianceShrinkSeconds = 60;

/// A finding shrunk to a minimal input and written to a file.
struct InvarianceMinimal {
    std::string mesh;  ///< the file written
    int faces = 0;
    int tests = 0;  ///< checks run while shrinking
    InputTransformation transformation = InputTransformation::Repeat;
    std::string explanation;  ///< the check on the minimal input
    std::string reproduce;    ///< the crossdiv invariance command line that shows it again
    bool cut_short = false;   ///< the time limit ended the shrinking (InvarianceShrink::cut_short)
};

/// As results and the invariance command's JSON state it: mesh, faces, tests, cut_short,
/// transformation, explanation, reproduce.
nlohmann::json to_json(const InvarianceMinimal& m);

/// The first failing check of `report` shrunk (shrink_not_invariant) and written as
/// `file_stem`-IMPL-TRANSFORM.obj in `folder`, with its reproduce line (rule and face-varying
/// flags included; a subject's command is left for the user to fill in). Failing: for the
/// implementation under test any not-invariant or nondeterministic check; for a reference one
/// whose cause (`causes`, one per check, causes_of) no class names, else its first finding.
/// Nothing when there is no finding, or the finding does not show again when shrinking starts.
std::optional<InvarianceMinimal> shrink_first_finding(const Implementation& impl, bool subject, bool under_test,
                                                      const PolyMesh& input, const RefineRequest& request,
                                                      const InvarianceReport& report,
                                                      const std::vector<std::optional<InvarianceCause>>& causes,
                                                      std::uint64_t seed, double tolerance, double timeout_seconds,
                                                      bool isolate, const std::string& folder, const std::string& file_stem);

/// Runs the invariance case `job`. @throws InputError for an input core's scheme refuses by
/// its faces alone (a polygon under Loop), as the comparison cases do.
CaseRecord run_invariance_case(const SuiteJob& job, const std::string& out_dir);

}  // namespace crossdiv::verification
