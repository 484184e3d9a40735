#pragma once
/// @file
/// Which reference vertex is which of ours. Libraries number refined vertices their own way;
/// before positions can be compared each reference vertex must be paired with ours.

#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// How a correspondence was found, strongest first.
enum class MatchMethod {
    Order,     ///< the library numbered every vertex as we do
    Topology,  ///< recovered level by level from provenance (parent vertex, edge, face) alone
    Nearest,   ///< nearest neighbour of positions (nearest_points.h), a bijection
    /// Nearest neighbours, closest pairs first, and the vertices left over (a reference vertex
    /// far from where it should be) placed by the faces around them.
    NearestAndFaces,
    None,      ///< no bijection found
};

/// "order", "topology", "nearest", "nearest+faces", "none".
const char* to_string(MatchMethod method);

struct Correspondence {
    MatchMethod method = MatchMethod::None;
    std::vector<int> ref_to_ours;  ///< our vertex for each reference vertex of the last level
    /// The map at every level 0..N when matched level by level (Order, Topology); empty for
    /// Nearest, which only sees the last level.
    std::vector<std::vector<int>> level_maps;
    std::string note;              ///< why a stronger method failed, when it did
};

/// How far apart, relative to the bounding-box diagonal, match_nearest_and_faces takes two of
/// our vertices to be copies at one place, by default.
constexpr double kCopyDistance = 1e-13;

/// Nearest-neighbour matching of `ref` onto `ours` (k-d tree); method None unless bijective.
Correspondence match_nearest(const std::vector<Vec3>& ours, const std::vector<Vec3>& ref);

/// match_nearest, and when two reference vertices want the same one of ours (a reference
/// vertex moved far, onto another's place): mutual nearest pairs are taken closest first, and each vertex
/// left over is placed through a reference face with two matched neighbouring corners: our
/// face with that edge has it at the same place (repeated while that places more), then a single leftover pair is
/// paired. So a divergence confined to a few vertices is measured, not lost to matching.
/// Method None unless this gives a bijection.
///
/// Two of our vertices within `copy_distance` of the diagonal of each other are copies at one
/// place, told apart by their faces alone (a face all of whose corners are copies, by its
/// corners' cyclic order). The default is a tenth of the weak tier's agreement tolerance:
/// two sums of the same neighbours in another order differ by a few units in the last place.
/// A float reference passes its tolerance: it cannot tell apart vertices closer than that.
Correspondence match_nearest_and_faces(const PolyMesh& ours, const PolyMesh& ref, double copy_distance = kCopyDistance);

/// Matches a reference's levels to ours level by level from provenance alone, for the
/// primal schemes (a triangle split into four: Loop, the Butterflies; an n-gon into n quads:
/// Catmull-Clark). `ours` is levels 0..N, `ref` the reference's.
///
/// The reference's level 0 must be our input (same order, checked bit for bit). At level
/// k+1 the reference keeps its level-k vertices first (all three libraries do; it is checked,
/// not assumed: old vertices must be pairwise non-adjacent). Each child face holding one old
/// vertex names its parent face (a corner triangle (a, e_ab, e_ca) the face (a, b, c); the
/// quads around a face point the polygon of their old corners, in order); a new vertex is
/// then named by its parent face and, for an edge point, its two old neighbours. So
/// coincident vertices (polygons back to back) and two edges with the same ends (a pillow's
/// refined levels) match exactly, and positions play no part: a reference whose rule moves
/// vertices far, onto others' places, is matched too. Method None, with the level and the
/// reason in the note, when this fails.
Correspondence match_by_provenance(const std::vector<const PolyMesh*>& ours, const adapters::LevelTrace& ref);

/// match_by_provenance, and when the reference's order cannot be derived, positions of the
/// last level (match_nearest_and_faces: faces as the tie-breaker); the note says why
/// provenance failed.
Correspondence match_refinement(const std::vector<const PolyMesh*>& ours, const adapters::LevelTrace& ref);

using adapters::VertexBirth;

/// Where each vertex of `fine` was born in `coarse`, for a primal refinement that keeps the
/// coarse vertices first, in their order: read from the faces as match_by_provenance reads a
/// reference's level (an edge named by the lowest-numbered face around it). Empty when `fine`
/// is not such a refinement of `coarse`.
std::vector<VertexBirth> primal_births(const PolyMesh& coarse, const PolyMesh& fine);

/// Pointers to every level of `levels`, for match_refinement.
std::vector<const PolyMesh*> level_view(const adapters::LevelTrace& levels);

/// `mesh` with vertex i renumbered to `to_ours[i]` (a bijection onto 0..n-1): positions
/// moved, faces rewritten, face order kept.
PolyMesh renumber(const PolyMesh& mesh, const std::vector<int>& to_ours);

}  // namespace crossdiv::verification
