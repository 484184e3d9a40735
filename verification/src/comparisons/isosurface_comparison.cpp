#include "crossdiv/verification/comparisons/isosurface_comparison.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <tuple>

#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/adapters/reference.h"
#include "harness/point_cloud.h"

namespace crossdiv::verification {

IsosurfaceMeasures measure_isosurface(const TriMesh& mesh) {
    IsosurfaceMeasures m;
    const PolyMesh poly = to_poly_mesh(mesh);
    const MeshTopology t = mesh_topology(poly);
    m.vertices = mesh.num_vertices(), m.faces = mesh.num_faces();
    m.boundary_edges = t.boundary_edges, m.boundary_loops = t.boundary_loops, m.euler = t.euler;
    for (const MeshIssue& issue : check_mesh(poly))
        if (issue.severity == Severity::Error) {
            if (m.mesh_errors++ == 0) m.first_error = issue.message;
        }
    for (const Triangle& f : mesh.triangles)
        m.volume += mesh.positions[f[0]].dot(mesh.positions[f[1]].cross(mesh.positions[f[2]])) / 6;
    return m;
}

const char* to_string(IsosurfaceAgreement a) {
    switch (a) {
        case IsosurfaceAgreement::Identical: return "identical";
        case IsosurfaceAgreement::OtherTriangulation: return "other-triangulation";
        case IsosurfaceAgreement::OtherTopology: return "other-topology";
        case IsosurfaceAgreement::OtherVertices: return "other-vertices";
    }
    return "?";
}

IsosurfaceRun run_isosurface(const Implementation& implementation, const ScalarGrid& grid, const IsosurfaceOptions& options,
                             const std::string& method) {
    IsosurfaceRun run;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        run.mesh = implementation.isosurface(grid, options, method);
    } catch (const ImplementationFailure& e) {
        run.outcome = {e.status(), e.what(), 0};
    } catch (const adapters::Rejected& e) {
        run.outcome = {RunStatus::Rejected, e.what(), 0};
    }
    run.outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return run;
}

double float32_vertex_tolerance(const ScalarGrid& grid) {
    const double unit_roundoff = std::numeric_limits<float>::epsilon() / 2;
    const int largest = *std::max_element(grid.size.begin(), grid.size.end());
    return tolerances::kIsosurfaceFloatRoundings * unit_roundoff * (largest + 4) * grid.spacing.maxCoeff();
}

namespace {

/// For each vertex of `from`, its nearest vertex of `to` within `tolerance` (-1: none), and the
/// largest distance over those matched.
std::vector<int> nearest_within(const TriMesh& from, const TriMesh& to, double tolerance, double& largest) {
    std::vector<int> match(from.num_vertices(), -1);
    if (to.num_vertices() == 0) return match;
    const PointCloud cloud{to.positions};
    PointTree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    for (int v = 0; v < from.num_vertices(); ++v) {
        unsigned index = 0;  // nanoflann 1.4's index type
        double d2 = 0;
        tree.knnSearch(from.positions[v].data(), 1, &index, &d2);
        const double d = std::sqrt(d2);
        if (d <= tolerance) match[v] = static_cast<int>(index), largest = std::max(largest, d);
    }
    return match;
}

/// Whether p lies on a grid edge: at least two of its index coordinates whole, to `tolerance`.
bool on_grid_edge(const ScalarGrid& grid, const Vec3& p, double tolerance) {
    int whole = 0;
    for (int a = 0; a < 3; ++a) {
        const double index = (p[a] - grid.origin[a]) / grid.spacing[a];
        whole += std::abs(index - std::round(index)) * grid.spacing[a] <= tolerance;
    }
    return whole >= 2;
}

/// Unmatched vertices, split into those on grid edges and those inside cubes.
std::pair<int, int> unmatched(const TriMesh& m, const std::vector<int>& match, const ScalarGrid& grid, double tolerance) {
    int on_edges = 0, inside = 0;
    for (int v = 0; v < m.num_vertices(); ++v)
        if (match[v] < 0) ++(on_grid_edge(grid, m.positions[v], tolerance) ? on_edges : inside);
    return {on_edges, inside};
}

/// A triangle as its sorted corners and whether its orientation is that of the sorted order.
struct FaceKey {
    std::array<int, 3> sorted;
    bool even;
    bool operator<(const FaceKey& o) const { return sorted < o.sorted; }
};
FaceKey face_key(int a, int b, int c) {
    std::array<int, 3> s{a, b, c};
    std::sort(s.begin(), s.end());
    // (a, b, c) is an even rotation of the sorted triple iff it is one of its three rotations.
    const bool even = (a == s[0] && b == s[1]) || (a == s[1] && b == s[2]) || (a == s[2] && b == s[0]);
    return {s, even};
}

}  // namespace

IsosurfaceComparison compare_isosurfaces(const TriMesh& ours, const TriMesh& theirs, const ScalarGrid& grid) {
    IsosurfaceComparison c;
    const double tolerance = float32_vertex_tolerance(grid);
    c.tolerance = tolerance;
    c.ours = measure_isosurface(ours);
    c.theirs = measure_isosurface(theirs);
    const std::vector<int> to_theirs = nearest_within(ours, theirs, tolerance, c.max_vertex_distance);
    const std::vector<int> to_ours = nearest_within(theirs, ours, tolerance, c.max_vertex_distance);
    std::tie(c.ours_unmatched, c.ours_interior) = unmatched(ours, to_theirs, grid, tolerance);
    std::tie(c.theirs_unmatched, c.theirs_interior) = unmatched(theirs, to_ours, grid, tolerance);

    std::vector<FaceKey> their_faces;
    for (const Triangle& t : theirs.triangles) their_faces.push_back(face_key(t[0], t[1], t[2]));
    std::sort(their_faces.begin(), their_faces.end());
    std::vector<char> found(their_faces.size(), 0);
    for (const Triangle& t : ours.triangles) {
        const int a = to_theirs[t[0]], b = to_theirs[t[1]], d = to_theirs[t[2]];
        const FaceKey k = a < 0 || b < 0 || d < 0 ? FaceKey{{-1, -1, -1}, true} : face_key(a, b, d);
        const auto it = std::lower_bound(their_faces.begin(), their_faces.end(), k);
        if (k.sorted[0] < 0 || it == their_faces.end() || it->sorted != k.sorted || found[it - their_faces.begin()]) {
            ++c.faces_only_ours;
            continue;
        }
        found[it - their_faces.begin()] = 1;
        c.reversed_faces += it->even != k.even;
    }
    c.faces_only_theirs = static_cast<int>(std::count(found.begin(), found.end(), 0));

    const std::string counts = fmt::format("ours V {} F {} chi {} boundary edges {} cube-interior vertices {}; theirs V {} F {} "
                                           "chi {} boundary edges {} cube-interior vertices {}",
                                           c.ours.vertices, c.ours.faces, c.ours.euler, c.ours.boundary_edges, c.ours_interior,
                                           c.theirs.vertices, c.theirs.faces, c.theirs.euler, c.theirs.boundary_edges,
                                           c.theirs_interior);
    if (c.ours_unmatched > 0 || c.theirs_unmatched > 0) {
        c.agreement = IsosurfaceAgreement::OtherVertices;
        c.explanation = fmt::format("{} of our crossings and {} of theirs have no counterpart within {:.3g}; {}", c.ours_unmatched,
                                    c.theirs_unmatched, tolerance, counts);
    } else if (c.faces_only_ours == 0 && c.faces_only_theirs == 0 && c.reversed_faces == 0) {
        c.agreement = IsosurfaceAgreement::Identical;
        c.explanation = fmt::format("every vertex within {:.3g} (largest {:.3g}), every triangle the same with its orientation; {}",
                                    tolerance, c.max_vertex_distance, counts);
    } else {
        const bool same_topology = c.ours.euler == c.theirs.euler && c.ours.boundary_edges == c.theirs.boundary_edges &&
                                   c.ours.mesh_errors == c.theirs.mesh_errors;
        c.agreement = same_topology ? IsosurfaceAgreement::OtherTriangulation : IsosurfaceAgreement::OtherTopology;
        c.explanation = fmt::format("the same crossings (largest distance {:.3g}); {} triangles only ours, {} only theirs, {} "
                                    "reversed; {}", c.max_vertex_distance, c.faces_only_ours, c.faces_only_theirs,
                                    c.reversed_faces, counts);
    }
    return c;
}

}  // namespace crossdiv::verification
