#pragma once
/// @file
/// Which reference vertex is which of ours. Libraries number refined vertices their own way;
/// before positions can be compared each reference vertex must be paired with ours.

#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/subdiv/loop.h"

namespace crossdiv::verification {

/// How a correspondence was found, strongest first.
enum class MatchMethod {
    Order,     ///< the library numbered every vertex as we do
    Topology,  ///< recovered level by level from connectivity alone
    Nearest,   ///< nearest neighbour of positions (k-d tree), a bijection
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

/// Matches the last level of a reference Loop trace to ours.
///
/// Level by level: the reference's level 0 is our input (same order, checked bit for bit);
/// at level k+1 the library keeps its level-k vertices first (all three do; it is checked,
/// not assumed: old vertices must be pairwise non-adjacent), and each new vertex is adjacent
/// to exactly the two old endpoints of its parent edge, which names our edge point. When
/// this fails at any level, positions of the last level are matched by nearest neighbour.
/// @param our_origins our_origins[k] is the provenance of our level k+1 vertices.
/// @param our_last our last level's positions (for the nearest-neighbour fallback).
Correspondence match_loop_refinement(const std::vector<std::vector<VertexOrigin>>& our_origins,
                                     const std::vector<Vec3>& our_input, const adapters::LevelTrace& ref,
                                     const std::vector<Vec3>& our_last);

/// Nearest-neighbour matching of `ref` onto `ours` (k-d tree); method None unless bijective.
Correspondence match_nearest(const std::vector<Vec3>& ours, const std::vector<Vec3>& ref);

/// match_nearest, and when two reference vertices want the same one of ours (a reference
/// vertex moved far, onto another's place): mutual nearest pairs are taken closest first, and each vertex
/// left over is placed through a reference face with two matched neighbouring corners: our
/// face with that edge has it at the same place (repeated while that places more), then a single leftover pair is
/// paired. So a divergence confined to a few vertices is measured, not lost to matching.
/// Method None unless this gives a bijection.
Correspondence match_nearest_and_faces(const PolyMesh& ours, const PolyMesh& ref);

/// The provenance of a 1-to-4 triangle split level (Loop, Butterfly) read off its own
/// connectivity: the first `coarse_vertices` vertices are the old ones, and each new vertex
/// is the edge point of the two old vertices it is adjacent to. Empty, with `why` filled, when
/// `fine` is not numbered that way.
std::vector<VertexOrigin> split_origins(int coarse_vertices, const PolyMesh& fine, std::string& why);

/// Matches the last level of a reference trace of a 1-to-4 triangle split scheme to ours
/// level by level from connectivity alone (match_loop_refinement, with our provenance read by
/// split_origins): positions play no part, so a reference whose rule moves some vertices far
/// (onto others' places) is still matched. `ours` holds every level 0..N.
Correspondence match_split_refinement(const adapters::LevelTrace& ours, const adapters::LevelTrace& ref);

/// `mesh` with vertex i renumbered to `to_ours[i]` (a bijection onto 0..n-1): positions
/// moved, faces rewritten, face order kept.
PolyMesh renumber(const PolyMesh& mesh, const std::vector<int>& to_ours);

}  // namespace crossdiv::verification
