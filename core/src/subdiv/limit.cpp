#include "crossdiv/subdiv/limit.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"

namespace crossdiv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Vec3 unit_or_zero(const Vec3& n) { return n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero(); }

/// The limit of every vertex no interior mask applies to, shared by both schemes: an isolated
/// vertex stays; a boundary vertex takes the cubic B-spline limit 2/3, 1/6, 1/6 of its two
/// boundary neighbours, or stays when `corner_rule` holds and it has one face. Returns false
/// (and writes nothing) for an interior vertex.
bool boundary_or_isolated_limit(const PolyConnectivity& conn, const std::vector<Vec3>& positions, int v,
                                bool corner_rule, LimitResult& out) {
    const Vec3& p = positions[v];
    const int start = conn.vertex_corner[v];
    if (start < 0) {
        out.position[v] = p;
        return true;
    }
    if (!conn.is_boundary_vertex(v)) return false;
    const PolyConnectivity::Fan fan = conn.fan(v);
    const PolyConnectivity::BoundaryNeighbors nb = conn.boundary_neighbors(v, fan);
    const Vec3& a = positions[nb.before];
    const Vec3& b = positions[nb.after];
    out.position[v] = corner_rule && fan.faces == 1 ? p : Vec3((2.0 / 3.0) * p + (1.0 / 6.0) * (a + b));
    return true;
}

using Triplets = std::vector<Eigen::Triplet<double>>;

/// The mask form of boundary_or_isolated_limit: the terms of vertex v's row, or false for an
/// interior vertex.
bool boundary_or_isolated_mask(const PolyConnectivity& conn, int v, bool corner_rule, Triplets& out) {
    if (conn.vertex_corner[v] < 0) {
        out.emplace_back(v, v, 1.0);
        return true;
    }
    if (!conn.is_boundary_vertex(v)) return false;
    const PolyConnectivity::Fan fan = conn.fan(v);
    if (corner_rule && fan.faces == 1) {
        out.emplace_back(v, v, 1.0);
        return true;
    }
    const PolyConnectivity::BoundaryNeighbors nb = conn.boundary_neighbors(v, fan);
    out.emplace_back(v, v, 2.0 / 3.0);
    out.emplace_back(v, nb.before, 1.0 / 6.0);
    out.emplace_back(v, nb.after, 1.0 / 6.0);
    return true;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> to_matrix(int n, const Triplets& terms) {
    Eigen::SparseMatrix<double, Eigen::RowMajor> m(n, n);
    m.setFromTriplets(terms.begin(), terms.end());
    return m;
}

}  // namespace

Eigen::SparseMatrix<double, Eigen::RowMajor> loop_limit_matrix(const TriMesh& mesh, const LoopOptions& options) {
    if (has_tuned_edges(options.weights))
        throw InputError("limit masks are derived for the weight families with Loop's edge mask (loop, warren); " +
                         std::string(to_string(options.weights)) + " tunes the edge mask too");
    const PolyConnectivity conn = build_poly_connectivity(to_poly_mesh(mesh));
    Triplets terms;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (boundary_or_isolated_mask(conn, v, options.boundary == LoopBoundary::EdgeAndCorner, terms)) continue;
        const int n = conn.fan(v).faces;
        const double chi = loop_limit_ring_weight(options.weights, n);
        terms.emplace_back(v, v, 1.0 - n * chi);
        const int start = conn.vertex_corner[v];
        for (int c = start;;) {
            terms.emplace_back(v, conn.head(c), chi);
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
    }
    return to_matrix(mesh.num_vertices(), terms);
}

Eigen::SparseMatrix<double, Eigen::RowMajor> catmull_clark_limit_matrix(const PolyMesh& mesh, const CatmullClarkOptions& options) {
    if (options.boundary == CatmullClarkBoundary::MidpointAverage)
        throw InputError("the midpoint-average boundary rule (OpenMesh's) has no cubic B-spline boundary limit mask");
    const PolyConnectivity conn = build_poly_connectivity(mesh);
    Triplets terms;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (boundary_or_isolated_mask(conn, v, options.boundary == CatmullClarkBoundary::EdgeAndCorner, terms)) continue;
        const int n = conn.fan(v).faces;
        const double scale = 1.0 / (double(n) * (n + 5));
        terms.emplace_back(v, v, double(n) * n * scale);
        const int start = conn.vertex_corner[v];
        for (int c = start;;) {
            if (mesh.face_size(conn.corner_face[c]) != 4)
                throw InputError(mesh.source.describe_vertex(v) + ": a face around it is not a quad; the Catmull-Clark "
                                 "limit mask needs quads (refine one level first)");
            terms.emplace_back(v, conn.head(c), 4 * scale);
            terms.emplace_back(v, conn.head(conn.next[c]), scale);
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
    }
    return to_matrix(mesh.num_vertices(), terms);
}

LimitResult loop_limit(const TriMesh& mesh, const LoopOptions& options) {
    // The ring weight chi comes from the eigenvectors of the local subdivision matrix whose
    // edge mask is 3/8, 1/8; the tuned families change that mask, and their limit is not this one.
    if (has_tuned_edges(options.weights))
        throw InputError("limit positions are derived for the weight families with Loop's edge mask (loop, warren); " +
                         std::string(to_string(options.weights)) + " tunes the edge mask too");
    // The polygon connectivity makes the same checks as Loop's (finite coordinates, manifold,
    // oriented) and walks rings in the same order, so one build serves both.
    const PolyMesh poly = to_poly_mesh(mesh);
    const PolyConnectivity conn = build_poly_connectivity(poly);
    LimitResult out;
    out.position.resize(static_cast<size_t>(mesh.num_vertices()));
    out.normal.assign(out.position.size(), Vec3::Constant(kNaN));
    std::vector<int> ring;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (boundary_or_isolated_limit(conn, mesh.positions, v, options.boundary == LoopBoundary::EdgeAndCorner, out))
            continue;
        const Vec3& p = mesh.positions[v];
        const int start = conn.vertex_corner[v];
        ring.clear();
        for (int c = start;;) {
            ring.push_back(conn.head(c));
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
        const int n = static_cast<int>(ring.size());
        const double chi = loop_limit_ring_weight(options.weights, n);
        Vec3 sum = Vec3::Zero(), t1 = Vec3::Zero(), t2 = Vec3::Zero();
        for (int i = 0; i < n; ++i) {
            const Vec3& q = mesh.positions[ring[i]];
            sum += q;
            t1 += std::cos(2 * M_PI * i / n) * q;
            t2 += std::sin(2 * M_PI * i / n) * q;
        }
        out.position[v] = (1.0 - n * chi) * p + chi * sum;
        // The walk crosses each corner's outgoing edge into the face on its right, so the ring
        // turns clockwise seen from outside and t2 x t1 is the outward normal.
        out.normal[v] = unit_or_zero(t2.cross(t1));
    }
    return out;
}

LimitResult catmull_clark_limit(const PolyMesh& mesh, const CatmullClarkOptions& options) {
    if (options.boundary == CatmullClarkBoundary::MidpointAverage)
        throw InputError("the midpoint-average boundary rule (OpenMesh's) has no cubic B-spline boundary limit mask");
    const PolyConnectivity conn = build_poly_connectivity(mesh);
    LimitResult out;
    out.position.resize(static_cast<size_t>(mesh.num_vertices()));
    out.normal.assign(out.position.size(), Vec3::Constant(kNaN));
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (boundary_or_isolated_limit(conn, mesh.positions, v,
                                       options.boundary == CatmullClarkBoundary::EdgeAndCorner, out))
            continue;
        const Vec3& p = mesh.positions[v];
        const int start = conn.vertex_corner[v];
        const int n = conn.fan(v).faces;
        const double a_n = 1 + std::cos(2 * M_PI / n) + std::cos(M_PI / n) * std::sqrt(2 * (9 + std::cos(2 * M_PI / n)));
        Vec3 e_sum = Vec3::Zero(), f_sum = Vec3::Zero(), t1 = Vec3::Zero(), t2 = Vec3::Zero();
        int i = 0;
        for (int c = start;; ++i) {
            if (mesh.face_size(conn.corner_face[c]) != 4)
                throw InputError(mesh.source.describe_vertex(v) + ": face " + std::to_string(conn.corner_face[c]) +
                                 " around it has " + std::to_string(mesh.face_size(conn.corner_face[c])) +
                                 " corners; the Catmull-Clark limit mask needs quads (refine one level first)");
            const Vec3& e = mesh.positions[conn.head(c)];
            const Vec3& f = mesh.positions[conn.head(conn.next[c])];
            e_sum += e;
            f_sum += f;
            // f_i lies between e_i and e_{i-1}: the walk crosses the outgoing edge of each corner,
            // so face i holds the ring vertices i and i - 1.
            const double c0 = std::cos(2 * M_PI * i / n), c1 = std::cos(2 * M_PI * (i - 1) / n);
            const double s0 = std::sin(2 * M_PI * i / n), s1 = std::sin(2 * M_PI * (i - 1) / n);
            t1 += a_n * c0 * e + (c0 + c1) * f;
            t2 += a_n * s0 * e + (s0 + s1) * f;
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
        out.position[v] = (double(n) * n * p + 4.0 * e_sum + f_sum) / (double(n) * (n + 5));
        out.normal[v] = unit_or_zero(t2.cross(t1));  // clockwise ring, as in loop_limit
    }
    return out;
}

}  // namespace crossdiv
