#include "crossdiv/mesh/mesh_checks.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace crossdiv {
namespace {

struct UnionFind {
    std::vector<int> parent;
    explicit UnionFind(int n) : parent(static_cast<size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(int a, int b) { parent[find(a)] = find(b); }
};

/// One corner's directed edge, for grouping the faces of each undirected edge by sorting.
struct HalfEdge {
    int lo, hi;    ///< sorted endpoints
    int corner;    ///< global corner index (face_start[f] + k)
    bool forward;  ///< true when the face runs lo -> hi
    bool operator<(const HalfEdge& o) const {
        return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : corner < o.corner;
    }
};

std::string edge_name(int a, int b) { return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")"; }

}  // namespace

const char* to_string(MeshIssueKind kind) {
    switch (kind) {
        case MeshIssueKind::IndexOutOfRange: return "index-out-of-range";
        case MeshIssueKind::RepeatedVertex: return "repeated-vertex";
        case MeshIssueKind::TooFewCorners: return "too-few-corners";
        case MeshIssueKind::NonManifoldEdge: return "non-manifold-edge";
        case MeshIssueKind::InconsistentOrientation: return "inconsistent-orientation";
        case MeshIssueKind::NonManifoldVertex: return "non-manifold-vertex";
        case MeshIssueKind::IsolatedVertex: return "isolated-vertex";
        case MeshIssueKind::ZeroAreaFace: return "zero-area-face";
        case MeshIssueKind::NonFiniteCoordinate: return "non-finite-coordinate";
    }
    return "unknown";
}

std::vector<MeshIssue> check_mesh(const PolyMesh& mesh) {
    std::vector<MeshIssue> issues;
    const MeshSource& src = mesh.source;
    const int nv = mesh.num_vertices(), nf = mesh.num_faces();
    auto report = [&](MeshIssueKind k, Severity s, std::string m) { issues.push_back({k, s, std::move(m)}); };

    for (int v = 0; v < nv; ++v)
        if (!mesh.positions[v].allFinite())
            report(MeshIssueKind::NonFiniteCoordinate, Severity::Error,
                   src.describe_vertex(v) + ": coordinate is NaN or infinite");

    // Faces with bad indices are reported and then left out of the topological checks.
    std::vector<char> face_ok(static_cast<size_t>(nf), 1);
    std::vector<int> sorted_corners;
    for (int f = 0; f < nf; ++f) {
        const int* fv = mesh.face(f);
        const int n = mesh.face_size(f);
        if (n < 3) {
            report(MeshIssueKind::TooFewCorners, Severity::Error,
                   src.describe_face(f) + ": has " + std::to_string(n) + " corners, a face needs at least 3");
            face_ok[f] = 0;
            continue;
        }
        for (int k = 0; k < n; ++k)
            if (fv[k] < 0 || fv[k] >= nv) {
                report(MeshIssueKind::IndexOutOfRange, Severity::Error,
                       src.describe_face(f) + ": vertex index " + std::to_string(fv[k]) + " out of range [0, " +
                           std::to_string(nv) + ")");
                face_ok[f] = 0;
            }
        if (!face_ok[f]) continue;
        // Sorted, a repeated vertex is a run: O(n log n) for a face of n corners, not O(n^2).
        sorted_corners.assign(fv, fv + n);
        std::sort(sorted_corners.begin(), sorted_corners.end());
        for (int k = 1; k < n; ++k)
            if (sorted_corners[k] == sorted_corners[k - 1] && (k == 1 || sorted_corners[k - 1] != sorted_corners[k - 2])) {
                report(MeshIssueKind::RepeatedVertex, Severity::Error,
                       src.describe_face(f) + ": repeated vertex " + std::to_string(sorted_corners[k]));
                face_ok[f] = 0;
            }
    }

    // Group directed edges by undirected edge.
    std::vector<HalfEdge> hes;
    std::vector<int> corner_face(mesh.face_vertices.size(), -1);
    for (int f = 0; f < nf; ++f) {
        if (!face_ok[f]) continue;
        const int n = mesh.face_size(f);
        for (int k = 0; k < n; ++k) {
            const int c = mesh.face_start[f] + k;
            corner_face[c] = f;
            const int a = mesh.face(f)[k], b = mesh.face(f)[(k + 1) % n];
            hes.push_back({std::min(a, b), std::max(a, b), c, a < b});
        }
    }
    std::sort(hes.begin(), hes.end());

    // Corners at the same vertex are in one fan when their faces share an edge at that vertex.
    UnionFind fans(static_cast<int>(mesh.face_vertices.size()));
    auto next_corner = [&](int c) {
        const int f = corner_face[c];
        return c + 1 < mesh.face_start[f + 1] ? c + 1 : mesh.face_start[f];
    };
    for (size_t i = 0; i < hes.size();) {
        size_t j = i;
        int forward = 0;
        while (j < hes.size() && hes[j].lo == hes[i].lo && hes[j].hi == hes[i].hi) forward += hes[j++].forward;
        const int count = static_cast<int>(j - i);
        const std::string name = edge_name(hes[i].lo, hes[i].hi);
        if (count > 2)
            report(MeshIssueKind::NonManifoldEdge, Severity::Error,
                   name + " is shared by " + std::to_string(count) + " faces (" +
                       src.describe_face(corner_face[hes[i].corner]) + " is one)");
        else if (count == 2 && forward != 1)
            report(MeshIssueKind::InconsistentOrientation, Severity::Error,
                   name + ": " + src.describe_face(corner_face[hes[i].corner]) + " and " +
                       src.describe_face(corner_face[hes[i + 1].corner]) +
                       " traverse it in the same direction (inconsistent orientation)");
        for (size_t k = i + 1; k < j; ++k) {
            // Corner c runs from its vertex to next_corner(c)'s vertex: unite the corners
            // that sit at lo and those that sit at hi.
            auto at = [&](const HalfEdge& h, bool want_lo) {
                const bool tail_is_lo = h.forward;
                return tail_is_lo == want_lo ? h.corner : next_corner(h.corner);
            };
            fans.unite(at(hes[i], true), at(hes[k], true));
            fans.unite(at(hes[i], false), at(hes[k], false));
        }
        i = j;
    }

    std::vector<int> first_root(static_cast<size_t>(nv), -1);
    std::vector<char> reported(static_cast<size_t>(nv), 0), used(static_cast<size_t>(nv), 0);
    for (int f = 0; f < nf; ++f) {
        if (!face_ok[f]) continue;
        for (int c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
            const int v = mesh.face_vertices[c];
            used[v] = 1;
            const int root = fans.find(c);
            if (first_root[v] < 0) first_root[v] = root;
            else if (first_root[v] != root && !reported[v]) {
                reported[v] = 1;
                report(MeshIssueKind::NonManifoldVertex, Severity::Error,
                       src.describe_vertex(v) + " is non-manifold: its faces form more than one fan (bowtie vertex)");
            }
        }
    }
    // A vertex named only by an invalid face is still not isolated in the file's intent.
    for (int f = 0; f < nf; ++f)
        if (!face_ok[f])
            for (int k = 0; k < mesh.face_size(f); ++k)
                if (mesh.face(f)[k] >= 0 && mesh.face(f)[k] < nv) used[mesh.face(f)[k]] = 1;
    for (int v = 0; v < nv; ++v)
        if (!used[v])
            report(MeshIssueKind::IsolatedVertex, Severity::Warning, src.describe_vertex(v) + " is used by no face");

    for (int f = 0; f < nf; ++f) {
        if (!face_ok[f]) continue;
        const int* fv = mesh.face(f);
        const int n = mesh.face_size(f);
        Vec3 normal = Vec3::Zero();  // Newell's method: twice the vector area of the polygon
        double longest2 = 0;
        for (int k = 0; k < n; ++k) {
            const Vec3& p = mesh.positions[fv[k]];
            const Vec3& q = mesh.positions[fv[(k + 1) % n]];
            normal += (p - mesh.positions[fv[0]]).cross(q - mesh.positions[fv[0]]);
            longest2 = std::max(longest2, (q - p).squaredNorm());
        }
        const double area = 0.5 * normal.norm();
        if (std::isfinite(area) && area <= kZeroAreaRelative * longest2)
            report(MeshIssueKind::ZeroAreaFace, Severity::Warning,
                   src.describe_face(f) + ": zero area (" + std::to_string(area) + ")");
    }
    return issues;
}

}  // namespace crossdiv
