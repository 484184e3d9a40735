#pragma once
/// @file
/// Comparison of two refined meshes under a vertex correspondence: topology (counts, Euler
/// characteristic, boundary loops, identical face sets) and positions (max and RMS distance,
/// absolute and relative to the bounding-box diagonal, and the worst vertices).

#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/harness/mesh_topology.h"

namespace crossdiv::verification {

struct TopologyCounts {
    int vertices = 0, edges = 0, faces = 0, euler = 0, boundary_loops = 0;
    friend bool operator==(const TopologyCounts&, const TopologyCounts&) = default;
};

/// The counts of a mesh's topology, as compare_meshes measures them.
TopologyCounts topology_counts(const MeshTopology& topology);
TopologyCounts topology_counts(const PolyMesh& mesh);

/// One of the vertices that differ most, described so a reader can find it.
struct WorstVertex {
    int ours_index = -1;
    int ref_index = -1;
    int valence = 0;
    bool boundary = false;
    Vec3 ours, ref;
    double distance = 0;
};

struct MeshComparison {
    TopologyCounts ours, ref;
    bool face_sets_equal = false;
    int faces_only_in_ours = 0, faces_only_in_ref = 0;  ///< as oriented faces, up to rotation
    /// The first face of each (its index in that mesh, in the order of the faces' listings)
    /// that the other lacks; -1 when none or when the meshes were not mapped.
    int first_face_only_in_ours = -1, first_face_only_in_ref = -1;
    double diagonal = 0;                                ///< of our mesh's bounding box
    double max_abs = 0, rms_abs = 0, max_rel = 0, rms_rel = 0;
    std::vector<WorstVertex> worst;  ///< largest distances first

    bool topology_equal() const { return ours == ref && face_sets_equal; }
    /// Agreement: identical topology and max_rel <= tolerances::kAgreementRelative.
    bool agree() const;
};

/// Largest vertex distance over our bounding-box diagonal, positions only (no topology):
/// the per-level figure. INFINITY when the map does not fit or a position is NaN.
double max_relative_distance(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours);
/// The same on two position lists.
double max_relative_distance(const std::vector<Vec3>& ours, const std::vector<Vec3>& ref, const std::vector<int>& ref_to_ours);
/// The map of two lists in the same order: i -> i for i < n.
std::vector<int> identity_map(size_t n);

/// Distance of each of our vertices to its reference vertex under the map (NaN: unmatched).
std::vector<double> vertex_distances(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours);

/// Whether some vertex lies farther than `tolerance` x our diagonal from its match and every
/// such vertex is one no face of ours uses (isolated-vertex-handling).
bool only_isolated_vertices_differ(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours,
                                   double tolerance);

/// The spacing of doubles at the mesh's largest coordinate magnitude: the unit in which two
/// summation orders of the same stencils part (tolerances::kRoundingUlps).
double ulp_of_largest_coordinate(const PolyMesh& mesh);

/// The agreement bound relative to `mesh`'s diagonal for an implementation that computes in
/// float (`in_float`): the larger of `tolerance` and the float tier's bound (tolerances.h:
/// kFloatAgreementUlps + (max_valence + 2) / 2 * levels float ulps of the mesh's largest
/// coordinate); `tolerance` itself for double.
double agreement_tolerance(const PolyMesh& mesh, bool in_float, double tolerance, int max_valence, int levels);

/// The same bound for `mesh`'s first face-varying channel, relative to its values' box: the
/// float tier of the values' largest magnitude (texture coordinates refined in float by the same
/// sums as positions).
double value_agreement_tolerance(const PolyMesh& mesh, bool in_float, double tolerance, int max_valence, int levels);

/// The largest number of distinct edge neighbours of a vertex (mesh_topology's valence).
int max_valence(const PolyMesh& mesh);

/// The n of the float tier (tolerances.h) for refining `mesh`: the most terms one stencil sums
/// less one, its largest valence or, where a face is larger, that face's size less one (a face
/// point, Catmull-Clark's or bilinear's, sums every corner: a 180-sided face sums 180).
int longest_float_sum(const PolyMesh& mesh);

/// Symmetric Hausdorff distance between two vertex sets (no correspondence needed): the
/// geometric tier's measure of how far two refinements of the same surface lie apart.
double hausdorff_vertex_sets(const std::vector<Vec3>& a, const std::vector<Vec3>& b);

/// Compares `ref` with `ours`; `ref_to_ours[i]` is our vertex for reference vertex i.
MeshComparison compare_meshes(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours,
                              int worst_count = 5);

}  // namespace crossdiv::verification
