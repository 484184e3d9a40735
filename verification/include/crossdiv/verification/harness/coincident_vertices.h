#pragma once
/// @file
/// Whether positions can tell a mesh's vertices apart: two vertices within a distance of each
/// other (at one position when the distance is 0) cannot be matched by position, nor can the
/// faces that use them. The invariance check compares such a refinement as point sets.

#include <span>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// Whether two of `positions` lie within `distance` of each other (Euclidean, the bound
/// included); with `distance` 0 (or not positive), whether two are equal. The points are
/// bucketed in cells of that size, so two within it share a cell or are neighbours: O(n log n).
bool has_vertices_within(std::span<const Vec3> positions, double distance);

}  // namespace crossdiv::verification
