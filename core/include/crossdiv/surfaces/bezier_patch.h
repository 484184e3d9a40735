#pragma once
/// @file
/// Tensor-product Bezier patches of any degree: evaluation by separable de Casteljau (the
/// CS184 meshedit seed: each row at u, then the resulting column at v), the Bernstein
/// tensor sum as a second algorithm, partial derivatives, the unit normal with a defined
/// fallback at degenerate points, and tessellation into one welded triangle mesh.

#include <span>
#include <string>
#include <vector>

#include "crossdiv/surfaces/surface_mesh.h"

namespace crossdiv {

/// A patch of rows x cols control points, row-major: control[r * cols + c]. u runs along a
/// row (over the columns), v across the rows; degree cols - 1 in u and rows - 1 in v. The
/// BEZ files' 4 lines of 4 points are the 4 rows.
struct BezierPatch {
    int rows = 0, cols = 0;
    std::vector<Vec3> control;
    int line = 0;  ///< where the patch starts in its file (0 when not from a file)
    const Vec3& at(int r, int c) const { return control[static_cast<size_t>(r) * cols + c]; }
};

/// Position, first partial derivatives and the mixed derivative at (u, v).
struct PatchJet {
    Vec3 position, du, dv, duv;
};

/// How patch_normal found the normal.
enum class NormalSource {
    Derivatives,  ///< du x dv: the regular case
    Limit,        ///< a vanishing derivative replaced by the mixed derivative duv, pointed
                  ///< into the patch: the limit of du x dv approaching the point (a
                  ///< collapsed edge such as the teapot lid's pole)
    ControlNet,   ///< still degenerate: the normal of the control net's corner diagonals
};
std::string_view to_string(NormalSource s);

/// The point at (u, v): every row by de Casteljau at u, then the column at v.
/// @throws InputError if the patch has no control points or control.size() != rows * cols.
Vec3 patch_point(const BezierPatch& patch, double u, double v);

/// The point as the Bernstein tensor sum  sum_ij B_i^n(v) B_j^m(u) p_ij: a different
/// algorithm, for cross-checks.
Vec3 patch_bernstein_point(const BezierPatch& patch, double u, double v);

/// Position and derivatives from two separable passes (the rows' points and the rows'
/// u-derivatives, each then evaluated along v).
PatchJet patch_jet(const BezierPatch& patch, double u, double v);

/// A derivative counts as vanishing below this times the control net's bounding-box
/// diagonal, and du x dv as degenerate below this times |du| |dv|: a few thousand ulps,
/// because a collapsed edge gives exact zeros up to the rounding of the interpolation.
inline constexpr double kPatchDegenerateRelative = 1e-12;

/// The unit normal, du x dv normalized, with the fallbacks of NormalSource.
Vec3 patch_normal(const BezierPatch& patch, double u, double v, NormalSource* source = nullptr);

/// Tessellation of each patch into res x res quads (each split along its (u0,v0)-(u1,v1)
/// diagonal, counterclockwise seen from the du x dv side), welded across patches with
/// kWeldRelative. @throws InputError if res < 1, a patch is malformed, or the tessellation would
/// have more than max_triangles triangles.
SurfaceMesh tessellate_patches(std::span<const BezierPatch> patches, int res,
                               long long max_triangles = kDefaultMaxSurfaceTriangles);

/// Largest gap between two patches along boundary curves they share: for each pair of
/// patch edges with the same control polygon (within kWeldRelative of the model's size,
/// either direction), the largest distance between the two edges' evaluated curves at
/// `samples` + 1 parameters (each patch evaluates its own edge: rounding only, or a bug).
/// Returns 0 when no edges are shared; `shared_edges` receives the number of edge pairs.
double max_boundary_gap(std::span<const BezierPatch> patches, int samples, int* shared_edges = nullptr);

}  // namespace crossdiv
