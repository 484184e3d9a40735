#pragma once
/// @file
/// The triangle mesh every surface builder returns: positions and triangles (a TriMesh, so
/// the mesh checks and the adapters take it as is) with one unit normal per vertex, and the
/// welding that joins vertices which coincide (patch boundaries, poles, seams).

#include <Eigen/Geometry>  // cross products
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

/// A tessellated surface. Triangles are counterclockwise seen from the side the normals
/// point to (the builders choose that side; see each builder).
struct SurfaceMesh {
    TriMesh mesh;
    std::vector<Vec3> normals;  ///< unit, one per vertex of `mesh`
    /// Triangles not emitted because two of their corners are one vertex (a collapsed patch
    /// edge, a pole of a surface of revolution): counted so that a report can say so.
    int collapsed_triangles = 0;
};

/// The default bound on the triangles of one built surface (sweeps, patches): about 4 GB of
/// positions, normals and triangles with the builders' intermediates, a safe share of a
/// 24 GB machine. Commands take --max-faces to move it.
inline constexpr long long kDefaultMaxSurfaceTriangles = 50'000'000;

/// @throws InputError when `triangles` exceeds `limit`, naming `what` and both counts.
void require_surface_size(long long triangles, long long limit, const std::string& what);

/// Welding joins points closer than this times the bounding-box diagonal of the input:
/// far above the rounding of two evaluations of one boundary curve from either side (a few
/// ulps of the coordinates), far below any intended feature of a course model (1e-3).
inline constexpr double kWeldRelative = 1e-9;

/// For each point, the index of the first point it is welded to (itself when none is
/// within `tol`). Points join transitively (a chain of points each within tol of the next is
/// one class). Points are sorted into cells of side tol / 2, whose diameter is below tol, so
/// the points of one cell are one class at once; two classes in cells at most two apart
/// join at the first pair found within tol. No pair of points is compared twice within a
/// cell, so many points in one cell (a model whose size makes tol wide next to its detail)
/// cost O(n log n), not O(n^2); no hashing of doubles and no node-based map.
std::vector<int> weld_classes(std::span<const Vec3> points, double tol);

/// Welds the mesh's vertices with weld_classes (tol = kWeldRelative * diagonal unless given),
/// keeps the first vertex of each class (order of first occurrence), averages the normals of
/// a class (then normalizes), and drops the triangles welding collapses (counted in
/// collapsed_triangles). Returns the largest angle (radians) between normals that were
/// averaged: 0 where the pieces meet with a common tangent plane.
double weld(SurfaceMesh& surface, double tol = -1);

/// Unit normal of each triangle (zero for a zero-area triangle).
std::vector<Vec3> face_normals(const TriMesh& mesh);

/// Signed volume enclosed by the triangles, sum of det(a, b, c) / 6: positive when a closed
/// mesh's triangles are counterclockwise seen from outside (normals outward).
double signed_volume(const TriMesh& mesh);

/// Number of edges used by exactly one triangle (0 for a watertight mesh), counting each
/// undirected edge once.
int boundary_edge_count(const TriMesh& mesh);

/// The undirected edge (a, b) as one key, the smaller end in the high half.
std::uint64_t edge_key(int a, int b);

/// How many keys occur exactly once in `edge_keys` (sorted here): the boundary edges of the
/// faces whose edges they are.
int unpaired_edge_count(std::vector<std::uint64_t> edge_keys);

}  // namespace crossdiv
