#include "crossdiv/verification/harness/mesh_comparison.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/hole_faces.h"
#include "crossdiv/verification/harness/corner_values.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/harness/nearest_points.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {
namespace {

/// The faces a mesh emits, each listed from its least rotation (orientation kept), in one
/// flat array (no list per face: the comparisons take meshes of millions of faces), with the
/// faces ordered by their listings: equal sequences of listings mean equal oriented face sets.
struct CanonicalFaces {
    std::vector<int> corners;  ///< every emitted face's listing, one after another
    std::vector<int> start;    ///< face i is corners[start[i]] .. corners[start[i + 1] - 1]
    std::vector<int> order;    ///< the faces in lexicographic order of their listings
    std::vector<int> source;   ///< face i's index in its mesh

    std::span<const int> face(int i) const {
        return {corners.data() + start[static_cast<size_t>(i)], static_cast<size_t>(start[i + 1] - start[i])};
    }
    /// Whether the listing of face i comes before that of face j of `other`.
    bool before(int i, const CanonicalFaces& other, int j) const {
        const auto a = face(i), b = other.face(j);
        return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
    }
};

/// The faces `m` emits, mapped through `map` when given. Hole faces are refined but not
/// emitted, so a reference that drops or keeps other holes than core shows as faces only in
/// one of the two.
CanonicalFaces canonical_faces(const PolyMesh& m, const std::vector<int>* map) {
    CanonicalFaces c;
    c.corners.reserve(m.face_vertices.size());
    c.start.reserve(static_cast<size_t>(m.num_faces()) + 1);
    c.start.push_back(0);
    std::vector<int> cycle;
    for_each_emitted_face(m, [&](int f) {
        cycle.assign(m.face(f), m.face(f) + m.face_size(f));
        if (map)
            for (int& v : cycle) v = (*map)[v];
        const size_t first = least_rotation(cycle);
        c.corners.insert(c.corners.end(), cycle.begin() + static_cast<std::ptrdiff_t>(first), cycle.end());
        c.corners.insert(c.corners.end(), cycle.begin(), cycle.begin() + static_cast<std::ptrdiff_t>(first));
        c.start.push_back(static_cast<int>(c.corners.size()));
        c.source.push_back(f);
    });
    // Ordered by first corner by a counting sort (a listing starts at its least vertex, so a
    // bucket holds some of the faces around one vertex), then within each bucket by the rest.
    const int faces = static_cast<int>(c.start.size()) - 1;
    int lowest = 0, highest = -1;
    for (int f = 0; f < faces; ++f)
        if (c.start[f + 1] > c.start[f]) {
            lowest = std::min(lowest, c.corners[static_cast<size_t>(c.start[f])]);
            highest = std::max(highest, c.corners[static_cast<size_t>(c.start[f])]);
        }
    const auto bucket = [&](int f) { return c.start[f + 1] > c.start[f] ? c.corners[static_cast<size_t>(c.start[f])] - lowest + 1 : 0; };
    std::vector<int> first(static_cast<size_t>(highest - lowest + 3), 0);
    for (int f = 0; f < faces; ++f) ++first[static_cast<size_t>(bucket(f)) + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    c.order.resize(static_cast<size_t>(faces));
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (int f = 0; f < faces; ++f) c.order[static_cast<size_t>(fill[static_cast<size_t>(bucket(f))]++)] = f;
    for (size_t b = 0; b + 1 < first.size(); ++b)
        std::sort(c.order.begin() + first[b], c.order.begin() + first[b + 1], [&](int i, int j) { return c.before(i, c, j); });
    return c;
}

/// Number of faces of `a` not in `b` (a merge of the two orders, as std::set_difference,
/// counted), and the mesh index of the least of them in `first` (-1: none).
int count_only_in(const CanonicalFaces& a, const CanonicalFaces& b, int& first) {
    int n = 0;
    first = -1;
    for (size_t i = 0, j = 0; i < a.order.size();) {
        if (j == b.order.size() || a.before(a.order[i], b, b.order[j])) {
            if (first < 0) first = a.source[static_cast<size_t>(a.order[i])];
            ++n;
            ++i;
        }
        else if (b.before(b.order[j], a, a.order[i])) ++j;
        else { ++i; ++j; }
    }
    return n;
}

/// Whether `a` and `b` list the same faces, each as often.
bool same_faces(const CanonicalFaces& a, const CanonicalFaces& b) {
    if (a.order.size() != b.order.size()) return false;
    for (size_t k = 0; k < a.order.size(); ++k) {
        const auto x = a.face(a.order[k]), y = b.face(b.order[k]);
        if (!std::equal(x.begin(), x.end(), y.begin(), y.end())) return false;
    }
    return true;
}

}  // namespace

double max_relative_distance(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours) {
    return max_relative_distance(ours.positions, ref.positions, ref_to_ours);
}

double max_relative_distance(const std::vector<Vec3>& ours, const std::vector<Vec3>& ref, const std::vector<int>& ref_to_ours) {
    if (ref_to_ours.size() != ref.size() || ref.size() != ours.size()) return INFINITY;
    double max_abs = 0;
    for (size_t i = 0; i < ref.size(); ++i) {
        const double d = (ref[i] - ours[static_cast<size_t>(ref_to_ours[i])]).norm();
        max_abs = std::isnan(d) ? INFINITY : std::max(max_abs, d);
    }
    const double diagonal = bounding_box_diagonal(ours);
    return max_abs / (diagonal > 0 ? diagonal : 1.0);
}

std::vector<int> identity_map(size_t n) {
    std::vector<int> map(n);
    std::iota(map.begin(), map.end(), 0);
    return map;
}

std::vector<double> vertex_distances(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours) {
    std::vector<double> d(static_cast<size_t>(ours.num_vertices()), NAN);
    for (int i = 0; i < ref.num_vertices() && i < static_cast<int>(ref_to_ours.size()); ++i) {
        const int o = ref_to_ours[i];
        if (o >= 0 && o < ours.num_vertices()) d[o] = (ref.positions[i] - ours.positions[o]).norm();
    }
    return d;
}

bool only_isolated_vertices_differ(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours,
                                   double tolerance) {
    const std::vector<double> d = vertex_distances(ours, ref, ref_to_ours);
    const double limit = tolerance * bounding_box_diagonal(ours.positions);
    std::vector<char> used(d.size(), 0);
    for (int v : ours.face_vertices) used[v] = 1;
    bool any = false;
    for (size_t v = 0; v < d.size(); ++v)
        if (!(d[v] <= limit)) {
            if (used[v]) return false;
            any = true;
        }
    return any;
}

namespace {
/// Largest distance from a point of `from` to its nearest point of `to`.
double directed_hausdorff(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
    if (to.empty()) return from.empty() ? 0.0 : INFINITY;
    const NearestPoints index(to);
    double worst = 0;
    for (const Vec3& p : from) {
        unsigned idx = 0;
        double d2 = 0;
        index.nearest(p, 1, &idx, &d2);
        worst = std::max(worst, std::sqrt(d2));
    }
    return worst;
}
}  // namespace

double hausdorff_vertex_sets(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    return std::max(directed_hausdorff(a, b), directed_hausdorff(b, a));
}

double ulp_of_largest_coordinate(const PolyMesh& m) {
    double largest = 0;
    for (const Vec3& p : m.positions) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    return std::nextafter(largest, INFINITY) - largest;
}

namespace {

/// kFloatAgreementUlps and the sums' rounding, in float ulps of `largest`, over `size`.
double float_tier(float largest, int max_valence, int levels, double size) {
    const double ulps = tolerances::kFloatAgreementUlps + 0.5 * (max_valence + 2) * levels;
    const double ulp = static_cast<double>(std::nextafter(largest, INFINITY)) - largest;
    return ulps * ulp / (size > 0 ? size : 1.0);
}

}  // namespace

double agreement_tolerance(const PolyMesh& mesh, bool in_float, double tolerance, int max_valence, int levels) {
    if (!in_float) return tolerance;
    float largest = 0;
    for (const Vec3& p : mesh.positions) largest = std::max(largest, static_cast<float>(p.cwiseAbs().maxCoeff()));
    return std::max(tolerance, float_tier(largest, max_valence, levels, bounding_box_diagonal(mesh.positions)));
}

double value_agreement_tolerance(const PolyMesh& mesh, bool in_float, double tolerance, int max_valence, int levels) {
    if (!in_float || mesh.face_varying.empty()) return tolerance;
    const FaceVaryingChannel& ch = mesh.face_varying.front();
    float largest = 0;
    for (double x : ch.values) largest = std::max(largest, std::abs(static_cast<float>(x)));
    return std::max(tolerance, float_tier(largest, max_valence, levels, uv_box_diagonal(ch)));
}

int longest_float_sum(const PolyMesh& mesh) {
    int longest = max_valence(mesh);
    for (int f = 0; f < mesh.num_faces(); ++f) longest = std::max(longest, mesh.face_size(f) - 1);
    return longest;
}

int max_valence(const PolyMesh& mesh) {
    const std::vector<int> valence = mesh_topology(mesh).valence;
    return valence.empty() ? 0 : *std::max_element(valence.begin(), valence.end());
}

TopologyCounts topology_counts(const MeshTopology& t) {
    return {t.vertices, t.edges, t.faces, t.euler, t.boundary_loops};
}

TopologyCounts topology_counts(const PolyMesh& mesh) { return topology_counts(mesh_topology(mesh)); }

bool MeshComparison::agree() const { return topology_equal() && max_rel <= tolerances::kAgreementRelative; }

MeshComparison compare_meshes(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours,
                              int worst_count) {
    MeshComparison c;
    const MeshTopology to = mesh_topology(ours), tr = mesh_topology(ref);
    c.ours = topology_counts(to);
    c.ref = topology_counts(tr);
    c.diagonal = bounding_box_diagonal(ours.positions);

    const bool mapped = ref_to_ours.size() == static_cast<size_t>(ref.num_vertices()) &&
                        ref.num_vertices() == ours.num_vertices();
    if (mapped) {
        const auto a = canonical_faces(ours, nullptr), b = canonical_faces(ref, &ref_to_ours);
        c.face_sets_equal = same_faces(a, b);
        if (!c.face_sets_equal) {
            c.faces_only_in_ours = count_only_in(a, b, c.first_face_only_in_ours);
            c.faces_only_in_ref = count_only_in(b, a, c.first_face_only_in_ref);
        }
    } else {
        c.faces_only_in_ours = ours.num_faces();
        c.faces_only_in_ref = ref.num_faces();
        c.max_abs = c.rms_abs = c.max_rel = c.rms_rel = INFINITY;
        return c;
    }

    std::vector<double> dist(static_cast<size_t>(ref.num_vertices()));
    double sum2 = 0;
    for (int i = 0; i < ref.num_vertices(); ++i) {
        dist[i] = (ref.positions[i] - ours.positions[ref_to_ours[i]]).norm();
        if (std::isnan(dist[i])) dist[i] = INFINITY;
        sum2 += dist[i] * dist[i];
        c.max_abs = std::max(c.max_abs, dist[i]);
    }
    c.rms_abs = ref.num_vertices() ? std::sqrt(sum2 / ref.num_vertices()) : 0.0;
    const double scale = c.diagonal > 0 ? c.diagonal : 1.0;
    c.max_rel = c.max_abs / scale;
    c.rms_rel = c.rms_abs / scale;

    std::vector<int> order(dist.size());
    std::iota(order.begin(), order.end(), 0);
    const size_t k = std::min(order.size(), static_cast<size_t>(std::max(worst_count, 0)));
    std::partial_sort(order.begin(), order.begin() + static_cast<long>(k), order.end(),
                      [&](int a, int b) { return dist[a] > dist[b]; });
    for (size_t i = 0; i < k; ++i) {
        const int r = order[i], o = ref_to_ours[r];
        c.worst.push_back({o, r, to.valence[o], to.boundary_vertex[o] != 0, ours.positions[o], ref.positions[r], dist[r]});
    }
    return c;
}

}  // namespace crossdiv::verification
