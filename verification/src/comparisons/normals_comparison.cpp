#include "crossdiv/verification/comparisons/normals_comparison.h"
#include "crossdiv/verification/harness/vector_angle.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

constexpr NormalWeighting kWeightings[3] = {NormalWeighting::Area, NormalWeighting::Angle, NormalWeighting::Uniform};
static_assert(static_cast<int>(NormalWeighting::Area) == 0 && static_cast<int>(NormalWeighting::Angle) == 1 &&
              static_cast<int>(NormalWeighting::Uniform) == 2, "kWeightings is indexed by the enum");


/// Per vertex, the largest angle between `n` and the unit normals of its faces (0 without faces).
std::vector<double> largest_face_angle(const TriMesh& mesh, const std::vector<Vec3>& n) {
    std::vector<double> out(static_cast<size_t>(mesh.num_vertices()), 0.0);
    const auto& P = mesh.positions;
    for (const Triangle& t : mesh.triangles) {
        const Vec3 c = (P[t[1]] - P[t[0]]).cross(P[t[2]] - P[t[0]]);
        if (c.norm() == 0.0) continue;
        for (int v : t)
            if (n[v].norm() > 0) out[v] = std::max(out[v], vector_angle(n[v], c.normalized()));
    }
    return out;
}

/// CGAL's fallback weighting: (v2 - v) x (v1 - v) / (|v1 - v| |v2 - v|) per face, i.e. the
/// unit face normal times the sine of the angle at the vertex; normalized.
std::vector<Vec3> sine_weighted_normals(const TriMesh& mesh) {
    std::vector<Vec3> n(static_cast<size_t>(mesh.num_vertices()), Vec3::Zero());
    const auto& P = mesh.positions;
    for (const Triangle& t : mesh.triangles)
        for (int j = 0; j < 3; ++j) {
            const Vec3 e1 = P[t[(j + 1) % 3]] - P[t[j]], e2 = P[t[(j + 2) % 3]] - P[t[j]];
            const double den = e1.norm() * e2.norm();
            if (den > 0) n[t[j]] += e1.cross(e2) / den;
        }
    for (Vec3& v : n)
        if (v.norm() > 0) v.normalize();
    return n;
}

void measure(const TriMesh& mesh, const std::vector<std::vector<Vec3>>& ours, const std::vector<char>& boundary,
             const std::vector<std::vector<double>>& ours_visibility, ReferenceNormals& r) {
    const int nv = mesh.num_vertices();
    for (int w = 0; w < 3; ++w)
        for (int v = 0; v < nv; ++v) {
            if (ours[w][v].norm() == 0 || r.normals[v].norm() == 0) continue;
            const double a = vector_angle(ours[w][v], r.normals[v]);
            if (a > r.max_angle[w] || r.worst_vertex[w] < 0) r.max_angle[w] = a, r.worst_vertex[w] = v;
        }
    int best = 0;
    for (int w = 1; w < 3; ++w)
        if (r.max_angle[w] < r.max_angle[best]) best = w;
    r.closest = std::string(to_string(kWeightings[best]));
    if (r.max_angle[best] <= tolerances::kNormalMatchRad) r.matches = r.closest;
    for (int v = 0; v < nv; ++v) {
        if (ours[best][v].norm() == 0 || r.normals[v].norm() == 0) continue;
        if (vector_angle(ours[best][v], r.normals[v]) > tolerances::kNormalMatchRad) {
            ++r.mismatched;
            r.mismatched_boundary += boundary[v];
        }
    }
    const std::vector<double> vis = largest_face_angle(mesh, r.normals);
    const std::vector<Vec3> sine = sine_weighted_normals(mesh);
    for (int v = 0; v < nv; ++v) {
        bool best_visible = true;
        for (int w = 0; w < 3; ++w) best_visible = best_visible && vis[v] <= ours_visibility[w][v] + tolerances::kNormalMatchRad;
        const bool is_sine = sine[v].norm() > 0 && r.normals[v].norm() > 0 && vector_angle(sine[v], r.normals[v]) <= tolerances::kNormalMatchRad;
        r.most_visible += best_visible;
        r.sine_weighted += is_sine;
        r.unexplained += !best_visible && !is_sine;
        if (!best_visible && !is_sine)
            r.visibility_excess = std::max(r.visibility_excess,
                                           vis[v] - std::min({ours_visibility[0][v], ours_visibility[1][v], ours_visibility[2][v]}));
    }
    char buf[512];
    if (!r.matches.empty())
        std::snprintf(buf, sizeof buf, "%s weighting (largest angle %.2e rad)", r.matches.c_str(), r.max_angle[best]);
    else if (r.mismatched == r.mismatched_boundary && r.mismatched > 0)
        std::snprintf(buf, sizeof buf, "%s weighting inside; differs at %d boundary vertices only (largest %.3e rad at vertex %d)",
                      r.closest.c_str(), r.mismatched, r.max_angle[best], r.worst_vertex[best]);
    else if (r.unexplained == 0)
        std::snprintf(buf, sizeof buf, "none of area/angle/uniform (closest %s, %.3e rad at vertex %d): at every vertex either "
                      "the most visible normal (%d: no larger angle to a face normal than any of ours) or the sine-weighted sum (%d)",
                      r.closest.c_str(), r.max_angle[best], r.worst_vertex[best], r.most_visible, r.sine_weighted);
    else
        std::snprintf(buf, sizeof buf, "none of area/angle/uniform (closest %s, %.3e rad at vertex %d; %d of %d vertices differ, "
                      "%d on the boundary; most visible at %d, sine-weighted at %d, neither at %d, there up to %.2e rad less visible than ours)",
                      r.closest.c_str(), r.max_angle[best], r.worst_vertex[best], r.mismatched, nv, r.mismatched_boundary,
                      r.most_visible, r.sine_weighted, r.unexplained, r.visibility_excess);
    r.classification = buf;
}

}  // namespace

NormalsComparison compare_normals(const TriMesh& mesh, NormalWeighting weighting, const std::vector<std::string>& references,
                                  const NormalsFunction& our_normals) {
    // Each weighting once; the requested one is handed out from the same computation.
    std::vector<std::vector<Vec3>> ours;
    std::vector<std::vector<double>> visibility;
    for (NormalWeighting w : kWeightings) {
        ours.push_back(our_normals(mesh, w));
        visibility.push_back(largest_face_angle(mesh, ours.back()));
    }
    NormalsComparison c{weighting, ours[static_cast<size_t>(weighting)], mesh.num_vertices(), 0, {}};
    std::vector<char> boundary(static_cast<size_t>(mesh.num_vertices()), 0);
    try {
        const TriConnectivity conn = build_tri_connectivity(mesh);
        for (int v = 0; v < mesh.num_vertices(); ++v) c.boundary_vertices += boundary[v] = conn.is_boundary_vertex(v);
    } catch (const InputError&) {
        // Not a manifold: the boundary split of the counts is left at zero.
    }
    // Only the references asked for (none when none are named).
    const std::vector<const Implementation*> refs =
        references.empty() ? std::vector<const Implementation*>{}
                           : select_references(&Capabilities::vertex_normals, references, "normals");
    for (const Implementation* ref : refs) {
        for (NamedNormals& named : ref->vertex_normals(mesh)) {
            ReferenceNormals r;
            r.name = std::move(named.name);
            r.method = std::move(named.method);
            r.normals = std::move(named.normals);
            r.error = std::move(named.error);
            if (r.error.empty()) measure(mesh, ours, boundary, visibility, r);
            c.references.push_back(std::move(r));
        }
    }
    return c;
}

}  // namespace crossdiv::verification
