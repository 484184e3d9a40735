#pragma once
/// @file
/// Isosurfaces measured and compared: what marching cubes made (watertight, manifold, Euler
/// characteristic, enclosed volume, distance to an exact surface) and how it differs from
/// scikit-image's marching cubes (Lewiner et al.'s MC33 table, or the 1987 table) run on the
/// same samples as an external program.

#include <optional>
#include <string>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/implementation.h"
#include "crossdiv/volume/marching_cubes.h"

namespace crossdiv::verification {

/// The facts of one isosurface mesh.
struct IsosurfaceMeasures {
    int vertices = 0, faces = 0;
    int boundary_edges = 0;    ///< edges of one triangle: holes, or the cut at the grid's boundary
    int boundary_loops = 0;
    int mesh_errors = 0;       ///< check_mesh errors (non-manifold edge or vertex, orientation)
    std::string first_error;   ///< the first of them, naming its element
    int euler = 0;             ///< V - E + F
    double volume = 0;         ///< signed, by the divergence theorem (the enclosed volume when closed)
    bool watertight() const { return boundary_edges == 0 && mesh_errors == 0; }
};
IsosurfaceMeasures measure_isosurface(const TriMesh& mesh);

/// A run of an implementation's marching cubes (Implementation::isosurface).
struct IsosurfaceRun {
    RunOutcome outcome;  ///< ok, or how it failed (unavailable when the program is not installed)
    TriMesh mesh;
};
/// `implementation`'s isosurface by `method` ("lewiner" or "lorensen" for scikit-image), its
/// failure recorded in the outcome, never thrown.
IsosurfaceRun run_isosurface(const Implementation& implementation, const ScalarGrid& grid, const IsosurfaceOptions& options,
                             const std::string& method);

/// How two isosurfaces of the same samples relate, from the closest to the farthest.
enum class IsosurfaceAgreement {
    Identical,          ///< the same vertices (to float32 rounding) and the same oriented triangles
    OtherTriangulation, ///< the same vertices, closedness and Euler characteristic; other triangles
    OtherTopology,      ///< the same vertices; the triangles join them into another topology
    OtherVertices,      ///< a crossing of one (a vertex on a grid edge) is not a vertex of the other
};
/// "identical", "other-triangulation", "other-topology", "other-vertices".
const char* to_string(IsosurfaceAgreement agreement);

struct IsosurfaceComparison {
    IsosurfaceAgreement agreement = IsosurfaceAgreement::Identical;
    double tolerance = 0;              ///< vertex match distance
    double max_vertex_distance = 0;    ///< over matched vertices
    int ours_unmatched = 0;            ///< our crossings (vertices on grid edges) with no counterpart
    int theirs_unmatched = 0;
    /// Vertices inside a cube, off the grid edges (our polygon centres, MC33's extra vertex in
    /// its interior-ambiguous cases): not matched, their triangles differ by construction.
    int ours_interior = 0, theirs_interior = 0;
    int faces_only_ours = 0, faces_only_theirs = 0;  ///< triangles (as vertex sets) in one only
    int reversed_faces = 0;            ///< shared triangles with the other orientation
    IsosurfaceMeasures ours, theirs;
    std::string explanation;           ///< the classification in words, with the numbers
};

/// The vertex match distance for samples rounded to float32 (as scikit-image does): the
/// sample, the crossing fraction and the index coordinate each carry float32 rounding.
double float32_vertex_tolerance(const ScalarGrid& grid);

/// Matches each vertex to the nearest of the other mesh's within float32_vertex_tolerance(grid),
/// compares triangles through the match, and classifies; both meshes are isosurfaces of `grid`.
IsosurfaceComparison compare_isosurfaces(const TriMesh& ours, const TriMesh& theirs, const ScalarGrid& grid);

}  // namespace crossdiv::verification
