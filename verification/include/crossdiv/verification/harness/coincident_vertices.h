#pragma once
/// @file
/// Whether positions can tell a mesh's vertices apart: two vertices within a distance of each
/// other (at one position when the distance is 0) cannot be matched by position, nor can the
/// faces that use them. The invariance check compares such a refinement as point sets; a
/// refinement comparison does not compare a float reference whose steps merge core's vertices.

#include <span>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// Whether two of `positions` lie within `distance` of each other (Euclidean, the bound
/// included); with `distance` 0 (or not positive), whether two are equal. The points are
/// bucketed in cells of that size, so two within it share a cell or are neighbours: O(n log n).
bool has_vertices_within(std::span<const Vec3> positions, double distance);

/// How many of `positions` share their position with another once every coordinate is rounded
/// to float (0: a float tells them all apart). Far from the origin a float's step outgrows the
/// mesh's details: a float implementation's vertices there cannot be matched by position.
size_t vertices_float_cannot_tell_apart(std::span<const Vec3> positions);

}  // namespace crossdiv::verification
