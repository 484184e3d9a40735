#pragma once
/// @file
/// Marching cubes (Lorensen and Cline 1987) with the asymptotic decider (Nielson and Hamann
/// 1991): the isosurface value = level of a scalar grid as a triangle mesh whose vertices lie on
/// grid edges, one shared vertex per crossed edge.
///
/// Each cube's surface is traced rather than looked up in a case table: on each of its six
/// faces the crossings are joined by segments (on a face whose diagonal corners are alike, the
/// ambiguous face, by the face rule), the segments chain into closed polygons, and each polygon
/// is triangulated. The segments of a face depend only on its four values, so the two cubes
/// that share a face join its crossings alike and the surface has no holes: every edge has two
/// triangles and every vertex one fan, except at the grid's own boundary, where the surface is
/// cut open.
///
/// The decider resolves the faces; it does not test the cube's interior (MC33's interior
/// ambiguity), so inside one cube the surface can join what the trilinear interpolant
/// separates (or the reverse). That changes topology only at features smaller than a cell.
///
/// A sample exactly at the level counts as outside, so no vertex is ever made twice; a
/// crossing can then lie on a sample, and several vertices can share that position (a
/// zero-area triangle, as any marching cubes makes at such samples).

#include <cstdint>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/volume/scalar_grid.h"

namespace crossdiv {

/// How the crossings of an ambiguous face are joined.
enum class AmbiguousFaceRule {
    /// Join the inside corners when the bilinear interpolant's saddle is inside (Nielson and
    /// Hamann): decided by the face alone, so neighbours agree.
    AsymptoticDecider,
    /// Separate the corners of the sign that is the minority in the cube (the inside ones when
    /// at most four corners are inside): how Lorensen and Cline's table, with complementary
    /// cases folded together, resolves a face. Two cubes can decide a shared face differently
    /// and leave a hole; kept to show that.
    SeparateMinority,
};
/// "decider", "minority".
const char* to_string(AmbiguousFaceRule rule);
/// @throws InputError for another name.
AmbiguousFaceRule ambiguous_face_rule_from_string(std::string_view name);

/// Which side of the level is the solid the surface encloses; its triangles face away from it.
enum class InsideIs {
    Below,  ///< value < level (signed distances, implicit functions)
    Above,  ///< value > level (densities: CT, MRI)
};

struct IsosurfaceOptions {
    double level = 0;
    InsideIs inside = InsideIs::Below;
    AmbiguousFaceRule rule = AmbiguousFaceRule::AsymptoticDecider;
};

/// The mesh and what the extraction met on the way.
struct Isosurface {
    TriMesh mesh;
    /// For each vertex, the grid edge it lies on: axis * num_samples + index of its lower sample;
    /// -1 for a polygon's centre (see centred_polygons).
    std::vector<int64_t> vertex_edge;
    int64_t ambiguous_faces = 0;   ///< faces (each counted once per cube) with diagonal corners alike
    int64_t joined_faces = 0;      ///< of those, where the inside corners were joined
    /// Polygons that no fan could triangulate without an edge between two crossings of one
    /// ambiguous face (which the neighbour cube could make too, giving an edge of four
    /// triangles): they get a vertex at their centroid instead.
    int64_t centred_polygons = 0;
};

/// The isosurface of `grid` at options.level.
/// @throws InputError when the level is not finite, a value minus the level overflows (naming
///         the sample) or a vertex position leaves the range of double; the grid must pass
///         check_grid.
Isosurface marching_cubes(const ScalarGrid& grid, const IsosurfaceOptions& options);

}  // namespace crossdiv
