#include "crossdiv/mesh/vertex_normals.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

std::string_view to_string(NormalWeighting w) {
    switch (w) {
        case NormalWeighting::Area: return "area";
        case NormalWeighting::Angle: return "angle";
        case NormalWeighting::Uniform: return "uniform";
    }
    return "?";
}

std::optional<NormalWeighting> parse_normal_weighting(std::string_view name) {
    for (NormalWeighting w : {NormalWeighting::Area, NormalWeighting::Angle, NormalWeighting::Uniform})
        if (to_string(w) == name) return w;
    return std::nullopt;
}

namespace {

/// The angle between u and v, by atan2 of |u x v| and u . v (accurate for small and
/// near-straight angles, where acos of the normalized dot product loses digits).
double angle_between(const Vec3& u, const Vec3& v) { return std::atan2(u.cross(v).norm(), u.dot(v)); }

}  // namespace

std::vector<Vec3> vertex_normals(const TriMesh& mesh, NormalWeighting weighting) {
    const int nv = mesh.num_vertices();
    std::vector<Vec3> sum(static_cast<size_t>(nv), Vec3::Zero());
    const auto& P = mesh.positions;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const Triangle& t = mesh.triangles[f];
        for (int v : t)
            if (v < 0 || v >= nv)
                throw InputError(mesh.source.describe_face(f) + ": vertex index " + std::to_string(v) +
                                 " out of range [0, " + std::to_string(nv) + ")");
        const Vec3 cross = (P[t[1]] - P[t[0]]).cross(P[t[2]] - P[t[0]]);
        if (weighting == NormalWeighting::Area) {
            for (int v : t) sum[v] += cross;
            continue;
        }
        const double len = cross.norm();
        if (len == 0.0) continue;
        const Vec3 unit = cross / len;
        for (int j = 0; j < 3; ++j) {
            const Vec3& p = P[t[j]];
            const double w =
                weighting == NormalWeighting::Angle ? angle_between(P[t[(j + 1) % 3]] - p, P[t[(j + 2) % 3]] - p) : 1.0;
            sum[t[j]] += w * unit;
        }
    }
    for (Vec3& n : sum) {
        const double len = n.norm();
        n = len > 0.0 ? Vec3(n / len) : Vec3::Zero();
    }
    return sum;
}

}  // namespace crossdiv
