#pragma once
/// @file
/// What the report's 3D viewer shows of a case where some reference diverges, for every
/// scheme: the implementation under test's levels with each vertex's provenance where it is
/// known, and each matched reference's positions in that numbering; and, when the suite made
/// one, the divergence shrunk to a small input (comparisons/shrink.h, as `crossdiv diff`);
/// where texture coordinates are compared, each implementation's values per corner.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/harness/correspondence.h"

namespace crossdiv::verification {

/// 3D views larger than this (faces at the last level) are not written: about 1 MB of side
/// file per view with four references, and a mesh any browser turns in real time.
inline constexpr int kViewMaxFaces = 50000;

/// A case's divergence shrunk to a small input that still shows it, shown beside its view.
struct MinimalDivergence {
    std::string reference;  ///< the reference whose divergence was shrunk
    std::string symptom;    ///< what persisted: "opensubdiv diverges from core (corner-rule)"
    PolyMesh mesh;          ///< the minimal input
    int tests = 0;          ///< comparisons run while shrinking
    std::string reproduce;  ///< the crossdiv compare line that shows it on the minimal mesh's file
};

struct DivergenceView {
    std::vector<PolyMesh> levels;  ///< levels 0..N of the implementation under test (polygons as polygons)
    /// births[l-1]: where each vertex of level l was born (a vertex, an edge or a face of
    /// level l-1); the primal schemes' levels have them, a level without them shows no
    /// provenance.
    std::vector<std::vector<VertexBirth>> births;
    /// Per reference, its positions at levels 0..N in our numbering: an empty level has no
    /// vertex map there (a match by position sees the last level only); NaN marks a vertex
    /// the reference has no match for.
    std::map<std::string, std::vector<std::vector<Vec3>>> references;
    /// When the case compares texture coordinates (the levels then carry their channel): per
    /// reference that gave values, its value at every corner of the last level in our corner
    /// order (harness/corner_values.h: corner_values_in_our_order; NaN where unmatched).
    std::map<std::string, std::vector<double>> reference_uvs = {};
    /// The corner of the last level (an index into its face_vertices) where some reference's
    /// texture coordinates part most from ours; -1 when none diverge.
    int uv_worst_corner = -1;
    /// The divergence of one library reference shrunk, when the suite made one.
    std::optional<MinimalDivergence> minimal = std::nullopt;
};

}  // namespace crossdiv::verification
