#pragma once
/// @file
/// Per-vertex curvature of a triangle mesh by the discrete operators of Meyer, Desbrun,
/// Schroeder and Barr, "Discrete differential-geometry operators for triangulated
/// 2-manifolds" (VisMath 2002):
///
/// - the mixed area A_i (sec. 3.3, fig. 4): the Voronoi area of vertex i inside each triangle
///   that is not obtuse, 1/8 sum cot(opposite angle) |x_i - x_j|^2 over its two edges at i;
///   in an obtuse triangle half its area to the obtuse corner and a quarter to the others.
///   The mixed areas tile the surface: they sum to its area.
/// - the mean curvature normal (eq. 8): 2 H n = 1/(2 A_i) sum_j (cot a_ij + cot b_ij)(x_i - x_j),
///   H signed against the vertex normal: positive where the surface bends away from it
///   (H = 1/r on a sphere of radius r with outward normals).
/// - the Gaussian curvature (eq. 9): K = (2 pi - sum of the angles at i) / A_i, the angle
///   defect over the mixed area.
/// - principal curvatures k1,2 = H +- sqrt(max(H^2 - K, 0)) (eq. 10; the discrete H^2 - K
///   can be slightly negative near umbilics, hence the clamp, as in the paper).
/// - principal directions: the eigenvectors of the symmetric 2x2 tensor B in the tangent plane
///   fitted by least squares to the normal curvature of every edge at i,
///   k_ij = 2 (x_i - x_j) . n / |x_i - x_j|^2, with the edge projected into the plane (sec. 5.2,
///   with unit weights per edge and triangle side; the paper weighs by Voronoi area).
///
/// The vertex normal is the angle-weighted one (vertex_normals.h, NormalWeighting::Angle).
///
/// Boundary: a boundary vertex's neighbourhood is a half-disc, and none of the operators above
/// is an estimate of the surface's curvature there. Its curvatures are not estimated
/// (CurvatureStatus::Boundary, values 0); its angle defect is the boundary's turning angle
/// pi - sum of the angles (the discrete geodesic curvature), so that the discrete
/// Gauss-Bonnet theorem holds on every manifold mesh, open or closed, to rounding:
///     sum over interior vertices (2 pi - sum angles) + sum over boundary vertices
///     (pi - sum angles) = 2 pi chi,   chi = V - E + F (isolated vertices not counted).
/// It is exact because every triangle's angles sum to pi, and 3F = 2E - E_boundary. A triangle
/// with two coincident corners has no angles (atan2(0, 0) = 0 is taken), and the sum then
/// misses pi for each such triangle.

#include <vector>

#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

/// What was estimated at a vertex.
enum class CurvatureStatus : unsigned char {
    Estimated,   ///< interior vertex with a positive mixed area
    Boundary,    ///< on the boundary: only the angle defect (the turning angle) is given
    Isolated,    ///< in no triangle: nothing is given
    Degenerate,  ///< interior, but every triangle around it has zero area
};

/// Per-vertex curvature, flat arrays indexed by vertex. Where the status is not Estimated the
/// curvatures and directions are 0.
struct DiscreteCurvature {
    std::vector<CurvatureStatus> status;
    std::vector<double> angle_defect;  ///< interior 2 pi - sum of angles; boundary pi - sum; isolated 0
    std::vector<double> mixed_area;    ///< A_i (also at boundary vertices; 0 if isolated)
    std::vector<double> mean;          ///< H, signed against `normal`
    std::vector<double> gaussian;      ///< K = angle defect / A_i
    std::vector<double> k1;            ///< maximum principal curvature, k1 >= k2
    std::vector<double> k2;            ///< minimum principal curvature
    std::vector<Vec3> direction1;      ///< unit tangent direction of k1 (0 where undefined: an umbilic fit)
    std::vector<Vec3> direction2;      ///< unit tangent direction of k2, normal x direction1
    std::vector<Vec3> normal;          ///< the angle-weighted unit vertex normal
    /// chi = V - E + F of the mesh, isolated vertices not counted (as the angle defects do not).
    int euler_characteristic = 0;

    int num_estimated() const;
    /// The sum of every vertex's angle defect: 2 pi chi (the discrete Gauss-Bonnet theorem).
    double total_angle_defect() const;
};

/// The curvature of every vertex of `mesh`, in O(V + F).
/// @throws InputError naming the element when the mesh is not a manifold, consistently
///         oriented triangle mesh (build_tri_connectivity's conditions), has a non-finite
///         coordinate, or a vertex whose curvature overflows double (naming the vertex).
DiscreteCurvature discrete_curvature(const TriMesh& mesh);

/// "estimated", "boundary", "isolated", "degenerate".
const char* to_string(CurvatureStatus status);

}  // namespace crossdiv
