#include "crossdiv/mesh/discrete_curvature.h"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/mesh/vertex_normals.h"

namespace crossdiv {

namespace {

/// Eigenvalues of the fitted tensor closer than this, relative to the larger, are equal to
/// rounding (an umbilic): the fit then names no direction.
constexpr double kUmbilicRelativeGap = 64 * std::numeric_limits<double>::epsilon();

/// Normal equations of the least-squares fit of the tangent curvature tensor
/// B = [[a, b], [b, c]] to normal curvatures along edges: one row (x^2, 2xy, y^2) per edge.
struct TensorFit {
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
};

/// Cotangent of the angle between u and v, and the angle itself; both from |u x v| and u . v.
struct Corner {
    double cot;
    double angle;
};
Corner corner(const Vec3& u, const Vec3& v) {
    const double sine = u.cross(v).norm(), cosine = u.dot(v);
    return {cosine / sine, std::atan2(sine, cosine)};
}

/// A unit vector perpendicular to the unit vector n.
Vec3 any_perpendicular(const Vec3& n) {
    const Vec3 axis = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
    return (axis - axis.dot(n) * n).normalized();
}

}  // namespace

const char* to_string(CurvatureStatus status) {
    switch (status) {
        case CurvatureStatus::Estimated: return "estimated";
        case CurvatureStatus::Boundary: return "boundary";
        case CurvatureStatus::Isolated: return "isolated";
        case CurvatureStatus::Degenerate: return "degenerate";
    }
    return "?";
}

int DiscreteCurvature::num_estimated() const {
    int n = 0;
    for (CurvatureStatus s : status) n += s == CurvatureStatus::Estimated;
    return n;
}

double DiscreteCurvature::total_angle_defect() const {
    double sum = 0.0;
    for (double d : angle_defect) sum += d;
    return sum;
}

namespace {

/// The operators on `mesh`, whose bounding-box diagonal is about 1.
DiscreteCurvature curvature_at_unit_scale(const TriMesh& mesh, const TriConnectivity& conn) {
    const int nv = mesh.num_vertices();
    const auto& P = mesh.positions;
    const size_t n = static_cast<size_t>(nv);

    DiscreteCurvature out;
    out.status.assign(n, CurvatureStatus::Isolated);
    out.angle_defect.assign(n, 0.0);
    out.mixed_area.assign(n, 0.0);
    out.mean.assign(n, 0.0);
    out.gaussian.assign(n, 0.0);
    out.k1.assign(n, 0.0);
    out.k2.assign(n, 0.0);
    out.direction1.assign(n, Vec3::Zero());
    out.direction2.assign(n, Vec3::Zero());
    out.normal = vertex_normals(mesh, NormalWeighting::Angle);

    std::vector<double> angle_sum(n, 0.0);
    std::vector<Vec3> laplacian(n, Vec3::Zero());  // sum (cot a + cot b)(x_i - x_j)

    // One pass over the triangles: each corner's angle, its share of the mixed area, and the
    // cotangent terms of the two edges it sees. A zero-area triangle adds its angles (0, 0 and
    // pi when its corners are distinct and collinear) but no area and no cotangent term (they
    // are undefined).
    for (const Triangle& t : mesh.triangles) {
        const Vec3 e[3] = {P[t[2]] - P[t[1]], P[t[0]] - P[t[2]], P[t[1]] - P[t[0]]};  // e[j] opposite corner j
        for (int v : t)
            if (out.status[v] == CurvatureStatus::Isolated) out.status[v] = CurvatureStatus::Degenerate;
        Corner c[3];
        for (int j = 0; j < 3; ++j) {
            c[j] = corner(e[(j + 2) % 3], -e[(j + 1) % 3]);
            angle_sum[t[j]] += c[j].angle;  // a flat triangle's are 0, 0 and pi: the sum stays exact
        }
        const double area = 0.5 * e[2].cross(-e[1]).norm();
        if (!(area > 0.0)) continue;
        const bool obtuse = c[0].cot < 0 || c[1].cot < 0 || c[2].cot < 0;
        for (int j = 0; j < 3; ++j) {
            const int i = t[j], a = (j + 1) % 3, b = (j + 2) % 3;
            // Edge x_i -> x_a is e[b] (seen from corner b), edge x_i -> x_b is -e[a].
            laplacian[i] += c[b].cot * (-e[b]) + c[a].cot * e[a];
            if (!obtuse)
                out.mixed_area[i] += (c[b].cot * e[b].squaredNorm() + c[a].cot * e[a].squaredNorm()) / 8.0;
            else
                out.mixed_area[i] += c[j].cot < 0 ? area / 2.0 : area / 4.0;
        }
    }

    std::vector<TensorFit> fit(n);
    std::vector<Vec3> tangent(n, Vec3::Zero());
    out.euler_characteristic = mesh.num_faces() - conn.num_edges();
    for (int v = 0; v < nv; ++v) {
        if (out.status[v] == CurvatureStatus::Isolated) continue;
        ++out.euler_characteristic;
        const bool boundary = conn.is_boundary_vertex(v);
        out.angle_defect[v] = (boundary ? std::numbers::pi : 2.0 * std::numbers::pi) - angle_sum[v];
        if (boundary) {
            out.status[v] = CurvatureStatus::Boundary;
            continue;
        }
        if (!(out.mixed_area[v] > 0.0) || out.normal[v].isZero()) continue;  // stays Degenerate
        out.status[v] = CurvatureStatus::Estimated;
        const Vec3 mean_normal = laplacian[v] / (2.0 * out.mixed_area[v]);  // 2 H n
        const double h = 0.5 * mean_normal.norm();
        out.mean[v] = mean_normal.dot(out.normal[v]) < 0 ? -h : h;
        out.gaussian[v] = out.angle_defect[v] / out.mixed_area[v];
        const double root = std::sqrt(std::max(out.mean[v] * out.mean[v] - out.gaussian[v], 0.0));
        out.k1[v] = out.mean[v] + root;
        out.k2[v] = out.mean[v] - root;
        tangent[v] = any_perpendicular(out.normal[v]);
    }

    // The direction fit: every triangle side of every edge at an estimated vertex.
    for (const Triangle& t : mesh.triangles)
        for (int j = 0; j < 3; ++j) {
            const int i = t[j];
            if (out.status[i] != CurvatureStatus::Estimated) continue;
            const Vec3& nrm = out.normal[i];
            const Vec3 u = tangent[i], w = nrm.cross(u);
            for (int other : {t[(j + 1) % 3], t[(j + 2) % 3]}) {
                const Vec3 edge = P[i] - P[other];
                const double len2 = edge.squaredNorm();
                const Vec3 in_plane = edge - edge.dot(nrm) * nrm;
                const double plane_len = in_plane.norm();
                if (!(len2 > 0.0) || !(plane_len > 0.0)) continue;
                const double x = in_plane.dot(u) / plane_len, y = in_plane.dot(w) / plane_len;
                const Eigen::Vector3d row(x * x, 2.0 * x * y, y * y);
                fit[i].normal_matrix += row * row.transpose();
                fit[i].rhs += row * (2.0 * edge.dot(nrm) / len2);
            }
        }
    for (int v = 0; v < nv; ++v) {
        if (out.status[v] != CurvatureStatus::Estimated) continue;
        const Eigen::FullPivLU<Eigen::Matrix3d> lu(fit[v].normal_matrix);
        if (lu.rank() < 3) continue;  // fewer than three distinct edge directions
        const Eigen::Vector3d abc = lu.solve(fit[v].rhs);
        Eigen::Matrix2d tensor;
        tensor << abc[0], abc[1], abc[1], abc[2];
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(tensor);
        const Eigen::Vector2d lambda = eig.eigenvalues();  // ascending
        if (lambda[1] - lambda[0] <= kUmbilicRelativeGap * std::max(std::abs(lambda[0]), std::abs(lambda[1])))
            continue;
        const Vec3 u = tangent[v], w = out.normal[v].cross(u);
        const Eigen::Vector2d d1 = eig.eigenvectors().col(1);
        out.direction1[v] = (d1[0] * u + d1[1] * w).normalized();
        out.direction2[v] = out.normal[v].cross(out.direction1[v]);
    }
    return out;
}

}  // namespace

DiscreteCurvature discrete_curvature(const TriMesh& mesh) {
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (!mesh.positions[v].allFinite())
            throw InputError(mesh.source.describe_vertex(v) + ": coordinate is not finite");
    const TriConnectivity conn = build_tri_connectivity(mesh);  // throws for non-manifold input
    // Squared edge lengths and cross products of a mesh of size 1e160 overflow and of 1e-160
    // underflow: the operators run on the mesh scaled by a power of two (exact) to a diagonal
    // in [0.5, 1), and the results are scaled back (H and k by 1/s, K by 1/s^2, areas by s^2).
    // A result that leaves the range of double then (an area of 1e400, a curvature that
    // underflows to 0) is refused rather than returned wrong. Scaling up cannot overflow: a
    // mesh of size s resolves no coordinate beyond s 2^53.
    const double diagonal = bounding_box_diagonal(mesh.positions);
    int exponent = 0;
    if (diagonal > 0.0 && std::isfinite(diagonal)) std::frexp(diagonal, &exponent);
    TriMesh unit = mesh;
    for (Vec3& p : unit.positions) p = Vec3(std::ldexp(p.x(), -exponent), std::ldexp(p.y(), -exponent), std::ldexp(p.z(), -exponent));
    DiscreteCurvature out = curvature_at_unit_scale(unit, conn);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        const bool curved = out.mean[v] != 0.0, gauss_curved = out.gaussian[v] != 0.0;
        out.mixed_area[v] = std::ldexp(out.mixed_area[v], 2 * exponent);
        out.mean[v] = std::ldexp(out.mean[v], -exponent);
        out.k1[v] = std::ldexp(out.k1[v], -exponent);
        out.k2[v] = std::ldexp(out.k2[v], -exponent);
        out.gaussian[v] = std::ldexp(out.gaussian[v], -2 * exponent);
        const bool in_range = std::isfinite(out.k1[v]) && std::isfinite(out.k2[v]) && std::isfinite(out.gaussian[v]) &&
                              std::isfinite(out.mixed_area[v]) && out.mixed_area[v] > 0.0 &&
                              (!curved || out.mean[v] != 0.0) && (!gauss_curved || out.gaussian[v] != 0.0);
        if (out.status[v] == CurvatureStatus::Estimated && !in_range)
            throw InputError(mesh.source.describe_vertex(v) + ": its curvature or area is out of the range of double "
                             "(mesh diagonal " + std::to_string(diagonal) + ")");
    }
    return out;
}

}  // namespace crossdiv
