#pragma once
/// @file
/// A refined topology that differs from core's, with no named rule to explain it, is never a
/// harmless class: it fails, and who differs is measured. A reference whose faces are not core's
/// and not any other reference's makes faces no one else makes: a bug of its own (or an unknown
/// rule), not "the library makes different faces". When references agree with each other on
/// faces that are not core's, core (or the subject under test) is the one that differs. Either
/// way the run is unexplained, its explanation naming which.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/mesh_comparison.h"

namespace crossdiv::verification {

/// The faces one implementation made, comparable with another's.
struct MadeFaces {
    TopologyCounts counts;
    /// Every vertex has a partner in core's numbering: `faces` holds each face's corners there,
    /// rotated to start at its smallest, the faces in lexicographic order (orientation kept).
    bool in_core_numbering = false;
    std::vector<int> face_start, corners;
};

/// `mesh`'s faces through `to_core` (one entry per vertex of `mesh`, -1 where unmatched; empty
/// when there is no correspondence: then only the counts are kept).
MadeFaces made_faces(const PolyMesh& mesh, std::span<const int> to_core);

/// The same faces: equal face sets where both are in core's numbering, else equal counts.
bool same_faces(const MadeFaces& a, const MadeFaces& b);

/// The post-pass over a comparison's runs (`made[i]`: the faces of runs[i], present where they
/// are not core's): a Topology divergence shared with no other reference fails (Unexplained,
/// naming that); and when two or more references make the same faces, none of them core's, each
/// of their Topology divergences fails as the implementation under test's (`under_test`: "core"
/// or the subject's name).
void require_shared_topology(std::vector<RefinementRun>& runs, const std::vector<std::optional<MadeFaces>>& made,
                             const std::string& under_test);

}  // namespace crossdiv::verification
