#pragma once
/// @file
/// Vertex age: the level at which each vertex of a refined mesh was born, and a colour per
/// level for pictures (the CS-C3100 seed colours a subdivided mesh by vertex age).
///
/// Core's primal schemes (Loop, Catmull-Clark, sqrt3, the Butterflies) number every level's
/// vertices old first: vertex v of level L was born at the first level l whose vertex count
/// exceeds v, and keeps that index ever after. A dual scheme (Doo-Sabin) replaces every vertex
/// at every level, so all of level L's vertices are born at L.

#include <span>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// The birth level of each vertex of the last level, from the vertex count of every level
/// (vertex_counts[0] the input's). @throws InputError if the counts are empty or decrease
/// (not a refinement that numbers old vertices first).
std::vector<int> vertex_birth_levels(std::span<const size_t> vertex_counts, bool dual);

/// The colour of birth level `level` of 0 .. `levels`: samples of the viridis colour map
/// (dark blue for the input's vertices to yellow for the newest), RGB in [0, 1].
Vec3 age_color(int level, int levels);

}  // namespace crossdiv
