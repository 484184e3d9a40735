#include "crossdiv/verification/harness/corner_values.h"

#include <algorithm>
#include <cmath>

namespace crossdiv::verification {

double uv_box_diagonal(const FaceVaryingChannel& ch) {
    const int comps = std::min(ch.dimension, 2);
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < ch.num_values(); ++i)
        for (int k = 0; k < comps; ++k) {
            lo[k] = std::min(lo[k], ch.value(i)[k]);
            hi[k] = std::max(hi[k], ch.value(i)[k]);
        }
    if (ch.num_values() == 0) return 0;
    return comps == 1 ? hi[0] - lo[0] : std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

namespace {

/// Faces around each vertex, in compressed rows.
struct VertexFaces {
    std::vector<int> start, faces;
    explicit VertexFaces(const PolyMesh& m) : start(static_cast<size_t>(m.num_vertices()) + 1, 0) {
        for (int v : m.face_vertices) ++start[static_cast<size_t>(v) + 1];
        for (size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
        faces.resize(m.face_vertices.size());
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (int f = 0; f < m.num_faces(); ++f)
            for (int k = 0; k < m.face_size(f); ++k) faces[static_cast<size_t>(fill[static_cast<size_t>(m.face(f)[k])]++)] = f;
    }
};

}  // namespace

namespace {

/// Calls `each(ours_corner, ref_corner)` for every corner of every face of `ref`, with the
/// corner of its partner face in `ours` (a face with the same mapped vertices, found among
/// the faces around its first vertex) that has the same vertex. Returns the first face of
/// `ref` with no partner, or -1.
///
/// Two faces on one set of vertices (a pillow's two sides, a face written twice) carry values
/// of their own: the partner is, of those faces, first one not yet taken whose corners follow
/// the same cycle, then one not yet taken in the other direction (a reference that writes its
/// faces reversed), then any; the first found regardless would compare one side's values with
/// the other's. Faces that tie (a face written twice: the same corners in the same cycle, which
/// nothing but their order tells apart, and their order is the implementation's) are told apart
/// by their values: the partner is the one whose values are nearest.
template <typename Each>
int for_each_matched_corner(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours, Each each) {
    const VertexFaces around(ours);
    std::vector<int> mapped;
    std::vector<char> taken(static_cast<size_t>(ours.num_faces()), 0);
    for (int g = 0; g < ref.num_faces(); ++g) {
        const int n = ref.face_size(g);
        mapped.assign(ref.face(g), ref.face(g) + n);
        for (int& v : mapped) v = ref_to_ours[static_cast<size_t>(v)];
        int f = -1, best = 4;  // rank: 0 free and the same cycle, 1 free, 2 the same cycle, 3 any
        const int v0 = mapped[0];
        // The largest difference of the first channels' values over the corners of ref's face g
        // and ours' face `cand` (on the same vertices), corner by vertex.
        const auto value_distance = [&](int cand) {
            if (ours.face_varying.empty() || ref.face_varying.empty()) return 0.0;
            const FaceVaryingChannel &a = ours.face_varying.front(), &b = ref.face_varying.front();
            const int* c = ours.face(cand);
            double d = 0;
            for (int k = 0; k < n; ++k) {
                const int j = static_cast<int>(std::find(c, c + n, mapped[static_cast<size_t>(k)]) - c);
                const double* x = a.value(a.corner_values[static_cast<size_t>(ours.face_start[cand] + j)]);
                const double* y = b.value(b.corner_values[static_cast<size_t>(ref.face_start[g] + k)]);
                for (int e = 0; e < std::min(a.dimension, b.dimension); ++e) d = std::max(d, std::abs(x[e] - y[e]));
            }
            return d;
        };
        for (int i = around.start[static_cast<size_t>(v0)]; i < around.start[static_cast<size_t>(v0) + 1]; ++i) {
            const int cand = around.faces[static_cast<size_t>(i)];
            if (ours.face_size(cand) != n) continue;
            const int* c = ours.face(cand);
            bool same = true;
            for (int k = 0; k < n && same; ++k) same = std::find(c, c + n, mapped[k]) != c + n;
            if (!same) continue;
            const int j = static_cast<int>(std::find(c, c + n, v0) - c);
            bool cycle = true;
            for (int k = 1; k < n && cycle; ++k) cycle = c[(j + k) % n] == mapped[static_cast<size_t>(k)];
            const int rank = (taken[static_cast<size_t>(cand)] ? 2 : 0) + (cycle ? 0 : 1);
            if (rank < best) {
                best = rank;
                f = cand;
            } else if (rank == best) {
                if (value_distance(cand) < value_distance(f)) f = cand;
            }
        }
        if (f < 0) return g;
        taken[static_cast<size_t>(f)] = 1;
        for (int k = 0; k < n; ++k) {
            const int j = static_cast<int>(std::find(ours.face(f), ours.face(f) + n, mapped[k]) - ours.face(f));
            each(ours.face_start[f] + j, ref.face_start[g] + k);
        }
    }
    return -1;
}

/// Why two meshes' first channels cannot be compared corner by corner ("" when they can).
std::string why_not_comparable(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours) {
    if (ours.face_varying.empty()) return "the implementation under test gave no face-varying values";
    if (ref.face_varying.empty()) return "the reference gave no face-varying values";
    const FaceVaryingChannel &a = ours.face_varying.front(), &b = ref.face_varying.front();
    if (a.dimension != b.dimension)
        return "values of " + std::to_string(a.dimension) + " and " + std::to_string(b.dimension) + " components";
    if (ref_to_ours.size() != static_cast<size_t>(ref.num_vertices())) return "no vertex correspondence";
    return "";
}

/// The face of `mesh` that corner `c` (an index into face_vertices) belongs to.
int face_of_corner(const PolyMesh& mesh, int c) {
    return static_cast<int>(std::upper_bound(mesh.face_start.begin(), mesh.face_start.end(), c) - mesh.face_start.begin()) - 1;
}

}  // namespace

CornerValueComparison compare_corner_values(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours) {
    CornerValueComparison out;
    out.not_compared = why_not_comparable(ours, ref, ref_to_ours);
    if (!out.compared()) return out;
    const FaceVaryingChannel &a = ours.face_varying.front(), &b = ref.face_varying.front();
    out.uv_box = uv_box_diagonal(a);
    int worst = -1;
    const int unmatched = for_each_matched_corner(ours, ref, ref_to_ours, [&](int oc, int rc) {
        const double* x = a.value(a.corner_values[static_cast<size_t>(oc)]);
        const double* y = b.value(b.corner_values[static_cast<size_t>(rc)]);
        for (int d = 0; d < a.dimension; ++d) {
            const double diff = std::abs(x[d] - y[d]);
            if (diff > out.max_abs || std::isnan(diff)) {
                out.max_abs = std::isnan(diff) ? INFINITY : diff;
                worst = oc;
            }
        }
        ++out.corners;
    });
    if (unmatched >= 0) {
        out = CornerValueComparison{};
        out.not_compared = "the reference's face " + std::to_string(unmatched) + " has no partner among ours";
        return out;
    }
    if (worst >= 0) {
        out.worst_face = face_of_corner(ours, worst);
        out.worst_corner = worst - ours.face_start[static_cast<size_t>(out.worst_face)];
        out.worst_vertex = ours.face_vertices[static_cast<size_t>(worst)];
    }
    out.max_rel = out.uv_box > 0 ? out.max_abs / out.uv_box : out.max_abs;
    return out;
}

std::vector<double> corner_values_in_our_order(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours) {
    if (!why_not_comparable(ours, ref, ref_to_ours).empty()) return {};
    const FaceVaryingChannel& b = ref.face_varying.front();
    const size_t dim = static_cast<size_t>(b.dimension);
    std::vector<double> out(ours.face_vertices.size() * dim, NAN);
    for_each_matched_corner(ours, ref, ref_to_ours, [&](int oc, int rc) {
        const double* y = b.value(b.corner_values[static_cast<size_t>(rc)]);
        std::copy(y, y + dim, out.begin() + static_cast<std::ptrdiff_t>(static_cast<size_t>(oc) * dim));
    });
    return out;
}

const char* to_string(UvVertexClass c) {
    switch (c) {
        case UvVertexClass::Interior: return "interior";
        case UvVertexClass::Boundary: return "boundary";
        case UvVertexClass::Seam: return "seam";
        case UvVertexClass::Junction: return "junction";
        case UvVertexClass::Corner: return "corner";
    }
    return "?";
}

std::vector<UvVertexClass> uv_corner_classes(const PolyMesh& mesh) {
    const FaceVaryingChannel& ch = mesh.face_varying.at(0);
    const size_t corners = mesh.face_vertices.size();
    // The corners sorted by (vertex, value): a vertex's run holds its values, a value's run
    // its faces (a face meets a vertex at one corner).
    std::vector<int> order(corners);
    for (size_t c = 0; c < corners; ++c) order[c] = static_cast<int>(c);
    const auto key = [&](int c) {
        return std::pair{mesh.face_vertices[static_cast<size_t>(c)], ch.corner_values[static_cast<size_t>(c)]};
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) < key(b); });
    // A vertex on the boundary: an end of an edge that one face uses.
    std::vector<std::pair<int, int>> edges;
    edges.reserve(corners);
    for (int f = 0; f < mesh.num_faces(); ++f)
        for (int k = 0, n = mesh.face_size(f); k < n; ++k) {
            const int a = mesh.face(f)[k], b = mesh.face(f)[(k + 1) % n];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    std::vector<char> boundary(static_cast<size_t>(mesh.num_vertices()), 0);
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i == 1) boundary[static_cast<size_t>(edges[i].first)] = boundary[static_cast<size_t>(edges[i].second)] = 1;
        i = j;
    }
    std::vector<UvVertexClass> out(corners, UvVertexClass::Interior);
    for (size_t i = 0; i < corners;) {
        const int v = key(order[i]).first;
        size_t end = i, values = 0;
        while (end < corners && key(order[end]).first == v) ++end;
        for (size_t k = i; k < end; ++k) values += k == i || key(order[k]).second != key(order[k - 1]).second;
        for (size_t k = i; k < end;) {
            size_t same = k;
            while (same < end && key(order[same]).second == key(order[k]).second) ++same;
            const UvVertexClass cls = values >= 3                        ? UvVertexClass::Junction
                                      : same - k == 1                    ? UvVertexClass::Corner
                                      : values == 2                      ? UvVertexClass::Seam
                                      : boundary[static_cast<size_t>(v)] ? UvVertexClass::Boundary
                                                                         : UvVertexClass::Interior;
            for (size_t x = k; x < same; ++x) out[static_cast<size_t>(order[x])] = cls;
            k = same;
        }
        i = end;
    }
    return out;
}

UvVertexClass uv_vertex_class(const PolyMesh& mesh, int face, int corner) {
    return uv_corner_classes(mesh)[static_cast<size_t>(mesh.face_start[static_cast<size_t>(face)] + corner)];
}

}  // namespace crossdiv::verification
