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

CornerValueComparison compare_corner_values(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours) {
    CornerValueComparison out;
    if (ours.face_varying.empty() || ref.face_varying.empty()) {
        out.not_compared = ours.face_varying.empty() ? "the implementation under test gave no face-varying values"
                                                     : "the reference gave no face-varying values";
        return out;
    }
    const FaceVaryingChannel &a = ours.face_varying.front(), &b = ref.face_varying.front();
    if (a.dimension != b.dimension) {
        out.not_compared = "values of " + std::to_string(a.dimension) + " and " + std::to_string(b.dimension) + " components";
        return out;
    }
    if (ref_to_ours.size() != static_cast<size_t>(ref.num_vertices())) {
        out.not_compared = "no vertex correspondence";
        return out;
    }
    out.uv_box = uv_box_diagonal(a);
    const VertexFaces around(ours);
    std::vector<int> mapped;
    for (int g = 0; g < ref.num_faces(); ++g) {
        const int n = ref.face_size(g);
        mapped.assign(ref.face(g), ref.face(g) + n);
        for (int& v : mapped) v = ref_to_ours[static_cast<size_t>(v)];
        // Our face with the same vertices, among the faces around its first vertex.
        int f = -1;
        const int v0 = mapped[0];
        for (int i = around.start[static_cast<size_t>(v0)]; i < around.start[static_cast<size_t>(v0) + 1] && f < 0; ++i) {
            const int cand = around.faces[static_cast<size_t>(i)];
            if (ours.face_size(cand) != n) continue;
            bool same = true;
            for (int k = 0; k < n && same; ++k) same = std::find(ours.face(cand), ours.face(cand) + n, mapped[k]) != ours.face(cand) + n;
            if (same) f = cand;
        }
        if (f < 0) {
            out.not_compared = "the reference's face " + std::to_string(g) + " has no partner among ours";
            return out;
        }
        for (int k = 0; k < n; ++k) {
            const int j = static_cast<int>(std::find(ours.face(f), ours.face(f) + n, mapped[k]) - ours.face(f));
            const double* x = a.value(a.corner_values[static_cast<size_t>(ours.face_start[f] + j)]);
            const double* y = b.value(b.corner_values[static_cast<size_t>(ref.face_start[g] + k)]);
            for (int d = 0; d < a.dimension; ++d) {
                const double diff = std::abs(x[d] - y[d]);
                if (diff > out.max_abs || std::isnan(diff)) {
                    out.max_abs = std::isnan(diff) ? INFINITY : diff;
                    out.worst_face = f;
                    out.worst_corner = j;
                    out.worst_vertex = ours.face(f)[j];
                }
            }
            ++out.corners;
        }
    }
    out.max_rel = out.uv_box > 0 ? out.max_abs / out.uv_box : out.max_abs;
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

UvVertexClass uv_vertex_class(const PolyMesh& mesh, int face, int corner) {
    const FaceVaryingChannel& ch = mesh.face_varying.at(0);
    const int v = mesh.face(face)[corner];
    const int value = ch.corner_values[static_cast<size_t>(mesh.face_start[face] + corner)];
    // The faces at v: their values, and whether an edge at v has one face (a boundary).
    std::vector<int> values;
    int faces_with_value = 0;
    std::vector<std::pair<int, int>> edges;  // (other end, count)
    for (int f = 0; f < mesh.num_faces(); ++f)
        for (int k = 0; k < mesh.face_size(f); ++k) {
            if (mesh.face(f)[k] != v) continue;
            const int x = ch.corner_values[static_cast<size_t>(mesh.face_start[f] + k)];
            if (std::find(values.begin(), values.end(), x) == values.end()) values.push_back(x);
            if (x == value) ++faces_with_value;
            for (int other : {mesh.face(f)[(k + 1) % mesh.face_size(f)], mesh.face(f)[(k + mesh.face_size(f) - 1) % mesh.face_size(f)]}) {
                auto it = std::find_if(edges.begin(), edges.end(), [&](const auto& e) { return e.first == other; });
                if (it == edges.end()) edges.emplace_back(other, 1);
                else ++it->second;
            }
        }
    if (values.size() >= 3) return UvVertexClass::Junction;
    if (faces_with_value == 1) return UvVertexClass::Corner;
    if (values.size() == 2) return UvVertexClass::Seam;
    const bool boundary = std::any_of(edges.begin(), edges.end(), [](const auto& e) { return e.second == 1; });
    return boundary ? UvVertexClass::Boundary : UvVertexClass::Interior;
}

}  // namespace crossdiv::verification
