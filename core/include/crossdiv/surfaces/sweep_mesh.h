#pragma once
/// @file
/// The one meshing routine both sweeps use (the CS-C3100 seed's advice): a grid of rings,
/// ring i being the profile placed at sweep sample i, zigzagged into triangles. Seams of
/// closed rings are joined by index; poles (a profile point on the axis of revolution, so
/// every ring has the same point there) are welded into one vertex without degenerate
/// triangles.

#include <functional>
#include <vector>

#include "crossdiv/surfaces/surface_mesh.h"

namespace crossdiv {

/// Ring-major samples of a swept surface: positions[i * ring_size + j] is profile sample j
/// in ring i. A closed direction lists each sample once: the ring (or profile) that would
/// repeat the first is not stored, and the mesh joins the last to the first.
struct SweepGrid {
    int rings = 0, ring_size = 0;
    std::vector<Vec3> positions, normals;  ///< normals unit, pointing to the surface's outside
    std::vector<double> profile_params;    ///< ring_size (+1 when closed_profile: the end)
    std::vector<double> sweep_params;      ///< rings (+1 when closed_sweep: the end)
    bool closed_profile = false, closed_sweep = false;
    const Vec3& at(int i, int j) const { return positions[static_cast<size_t>(i) * ring_size + j]; }
};

/// Triangles of the grid: each cell (i, j)-(i+1, j)-(i+1, j+1)-(i, j+1) split along its
/// (i, j)-(i+1, j+1) diagonal, wound so that the triangles face the side the vertex normals
/// point to (decided once for the whole grid, by the sign of the summed agreement, so a
/// part of the surface whose normals disagree with its faces shows up in the checks rather
/// than being silently flipped). Then welded (kWeldRelative), which joins poles and drops
/// the triangles they collapse.
SurfaceMesh mesh_sweep(const SweepGrid& grid);

/// Exact surface point at (profile parameter, sweep parameter).
using ExactSurface = std::function<Vec3(double profile_param, double sweep_param)>;

/// Measured deviation of the meshed grid from the exact surface it samples: every cell is
/// sampled at (k + 1) x (k + 1) parameter points, the exact point at each is computed, and
/// its distance to the nearer of the cell's two flat triangles is taken. The maximum over
/// all samples: measured, and at least the one-sided Hausdorff distance from the surface to
/// the mesh (a point is never measured against a farther triangle than its nearest one).
double grid_deviation(const SweepGrid& grid, const ExactSurface& exact, int k = 6);

/// Distance from p to the triangle abc (closest point by region, Ericson 2005, 5.1.5).
double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace crossdiv
