#pragma once
/// @file
/// Our vertex normals (area, angle, uniform weighting) against the references' (OpenMesh's
/// calc_vertex_normal_correct and update_vertex_normals, CGAL's compute_vertex_normals), with
/// each reference classified by measurement: which of our weightings it matches and where it
/// does not, instead of one tolerance that would hide the difference.

#include <functional>
#include <string>
#include <vector>

#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/mesh/vertex_normals.h"

namespace crossdiv::verification {

/// One reference's normals measured against ours.
struct ReferenceNormals {
    std::string name;        ///< "openmesh-correct", "openmesh-fast", "cgal"
    std::string method;      ///< the library call
    std::vector<Vec3> normals;
    std::string error;       ///< the reference refused the mesh (then nothing else is set)
    /// Largest angle (rad) to each of our weightings, in the order area, angle, uniform, over
    /// vertices where both sides have a normal.
    double max_angle[3] = {0, 0, 0};
    int worst_vertex[3] = {-1, -1, -1};
    std::string matches;     ///< the weighting within kNormalMatchRad everywhere, or ""
    std::string closest;     ///< the weighting with the smallest largest angle
    int mismatched = 0;          ///< vertices off the closest weighting by more than kNormalMatchRad
    int mismatched_boundary = 0; ///< of those, on the boundary
    /// Vertices where this normal's largest angle to an incident face normal is no larger than
    /// that of every one of our weightings (+ kNormalMatchRad): CGAL's "most visible" claim.
    int most_visible = 0;
    /// Vertices where this normal is, within kNormalMatchRad, the sine-weighted sum (each unit
    /// face normal times the sine of the face's angle at the vertex): CGAL's fallback.
    int sine_weighted = 0;
    /// Vertices that are neither of the two above.
    int unexplained = 0;
    /// Over those, the largest amount (rad) by which this normal's largest face-normal angle
    /// exceeds the smallest of ours: how far from "most visible" the reference is there.
    double visibility_excess = 0;
    std::string classification;  ///< one sentence: what the reference computes, as measured
};

struct NormalsComparison {
    NormalWeighting weighting;
    std::vector<Vec3> ours;  ///< with `weighting`
    int vertices = 0, boundary_vertices = 0;
    std::vector<ReferenceNormals> references;
};

/// Our vertex normals as the harness calls them; tests substitute a deliberately broken one.
using NormalsFunction = std::function<std::vector<Vec3>(const TriMesh&, NormalWeighting)>;

/// `references`: any of "openmesh" (both of its methods) and "cgal"; unknown or unavailable
/// names throw InputError. A reference that throws on the mesh is recorded, not fatal.
/// `ours` computes our normals (vertex_normals).
NormalsComparison compare_normals(const TriMesh& mesh, NormalWeighting weighting, const std::vector<std::string>& references,
                                  const NormalsFunction& ours = vertex_normals);

}  // namespace crossdiv::verification
