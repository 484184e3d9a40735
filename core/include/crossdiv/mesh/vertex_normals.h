#pragma once
/// @file
/// Vertex normals of a triangle mesh as a weighted sum of its faces' normals, the weighting
/// named. The weightings differ wherever a vertex's faces differ in size or shape, which is
/// why the references disagree: OpenMesh's calc_vertex_normal_correct is Area,
/// update_vertex_normals is Uniform, and CGAL's PMP::compute_vertex_normals is neither.

#include <optional>
#include <string_view>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

enum class NormalWeighting {
    /// The seed's: the sum of the faces' cross products (b - a) x (c - a), each twice its
    /// face's area times its unit normal, normalized.
    Area,
    /// Each unit face normal weighted by the face's interior angle at the vertex (Thuermer
    /// and Wuethrich 1998): independent of how the faces around the vertex are triangulated.
    Angle,
    /// The plain sum of unit face normals.
    Uniform,
};

/// "area", "angle", "uniform".
std::string_view to_string(NormalWeighting w);
/// The weighting named `name`, or nothing for an unknown name.
std::optional<NormalWeighting> parse_normal_weighting(std::string_view name);

/// One unit normal per vertex. A vertex with no face, or whose faces' weighted normals cancel
/// or all have zero area, gets the zero vector: no direction is better than an invented one.
/// Faces of zero area add nothing in any weighting (their unit normal is undefined).
/// @throws InputError naming the face when a face names a vertex out of range.
std::vector<Vec3> vertex_normals(const TriMesh& mesh, NormalWeighting weighting);

}  // namespace crossdiv
