#pragma once
/// @file
/// The half-edge work of one mesh as suite checks (the `edits` and `normals` operations):
/// the edit differential against every reference with edits, and the vertex normals of each
/// weighting against the library call that implements it and against an oracle.

#include <string>

#include "crossdiv/verification/comparisons/edit_differential.h"
#include "crossdiv/verification/comparisons/normals_comparison.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// Seeded random sequences of flips and splits per mesh, and their length.
inline constexpr int kSuiteEditSeeds = 3;
inline constexpr int kSuiteEditOps = 60;

/// kSuiteEditSeeds sequences of kSuiteEditOps operations (60% flips) on `input`, each applied
/// to ours and in lockstep to OpenMesh and CGAL, validity and faces checked after every
/// operation (run_edit_differential): one check per sequence, a count of disagreements that
/// must be zero; a failing sequence is shrunk and named in the check's note, in the syntax of
/// `crossdiv edit`. And Loop by split and flip (loop_split_flip.h) against the index-based
/// Loop, bit for bit, under Loop's and Warren's weights. An input that is not a manifold,
/// oriented triangle mesh fails, named.
CheckReport check_edits(const std::string& input, const OurEdits& ours = {});

/// Our vertex normals on `input` against the library calls that implement a weighting
/// (OpenMesh's calc_vertex_normal_correct: area; update_vertex_normals: uniform), each the
/// largest angle in radians within tolerances::kNormalMatchRad; CGAL's compute_vertex_normals,
/// which follows none, agreeing where it matches one of ours and `normal-rule` elsewhere,
/// with its measured classification (most visible, sine-weighted, neither) in the note;
/// and the angle weighting, which no reference has, against the Thuermer-Wuethrich sum
/// written out here (not read from core).
CheckReport check_normals(const std::string& input, const NormalsFunction& ours = vertex_normals);

}  // namespace crossdiv::verification
