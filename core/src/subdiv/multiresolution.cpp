#include "crossdiv/subdiv/multiresolution.h"

#include <Eigen/Geometry>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/vertex_normals.h"
#include "crossdiv/subdiv/least_squares.h"
#include "crossdiv/subdiv/loop.h"

namespace crossdiv {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

std::vector<Vec3> times(const RowMatrix& s, const std::vector<Vec3>& p) {
    std::vector<Vec3> out(static_cast<size_t>(s.rows()), Vec3::Zero());
    for (Eigen::Index r = 0; r < s.rows(); ++r)
        for (RowMatrix::InnerIterator it(s, r); it; ++it) out[static_cast<size_t>(r)] += it.value() * p[static_cast<size_t>(it.col())];
    return out;
}

void check_count(const std::vector<Vec3>& p, int expected, const char* what) {
    if (static_cast<int>(p.size()) != expected)
        throw InputError(std::string("multiresolution: ") + std::to_string(p.size()) + " " + what + " for " +
                         std::to_string(expected) + " vertices");
}

}  // namespace

LoopMultiresolution::LoopMultiresolution(const TriMesh& base, const LoopOptions& options, int levels) {
    if (levels < 1 || levels > 8) throw InputError("multiresolution: the level count must be 1 .. 8, not " + std::to_string(levels));
    num_base_ = base.num_vertices();
    TriMesh level = base;
    triangles_.push_back(level.triangles);
    for (int l = 0; l < levels; ++l) {
        subdivision_.emplace_back(loop_subdivision_matrix(level, options));
        level = loop_subdivide(level, options, 1);
        triangles_.push_back(level.triangles);
    }
}

std::vector<Eigen::Matrix3d> LoopMultiresolution::frames(int level, const std::vector<Vec3>& positions) const {
    TriMesh mesh;
    mesh.positions = positions;
    mesh.triangles = triangles_[level];
    const std::vector<Vec3> normals = vertex_normals(mesh, NormalWeighting::Angle);
    // The tangent points to the next corner of the first triangle naming the vertex, or to the
    // previous one where that edge runs along the normal: a choice made by the connectivity,
    // so a rigid motion of the positions moves every frame with it.
    std::vector<std::array<int, 2>> toward(positions.size(), {-1, -1});
    for (const Triangle& t : mesh.triangles)
        for (int c = 0; c < 3; ++c)
            if (toward[t[c]][0] < 0) toward[t[c]] = {t[(c + 1) % 3], t[(c + 2) % 3]};
    std::vector<Eigen::Matrix3d> out(positions.size());
    for (size_t v = 0; v < positions.size(); ++v) {
        const Vec3& n = normals[v];
        if (toward[v][0] < 0 || !(n.norm() > 0.5))
            throw InputError("multiresolution: vertex " + std::to_string(v) + " of level " + std::to_string(level) +
                             " has no normal (isolated, or its faces cancel), so no frame for its detail");
        Vec3 t1 = Vec3::Zero();
        for (int w : toward[v]) {
            const Vec3 e = positions[w] - positions[v];
            const Vec3 tangent = e - e.dot(n) * n;
            if (tangent.norm() > 1e-8 * e.norm()) {
                t1 = tangent.normalized();
                break;
            }
        }
        if (t1.isZero())
            throw InputError("multiresolution: vertex " + std::to_string(v) + " of level " + std::to_string(level) +
                             " has its edges along its normal, so no tangent for its detail's frame");
        out[v].col(0) = t1;
        out[v].col(1) = n.cross(t1);
        out[v].col(2) = n;
    }
    return out;
}

std::vector<Vec3> LoopMultiresolution::subdivide(const std::vector<Vec3>& base) const {
    check_count(base, num_base_, "base positions");
    std::vector<Vec3> p = base;
    for (const RowMatrix& s : subdivision_) p = times(s, p);
    return p;
}

MultiresolutionDecomposition LoopMultiresolution::decompose(const std::vector<Vec3>& finest) const {
    check_count(finest, num_vertices(num_levels()), "finest positions");
    MultiresolutionDecomposition d;
    d.details.resize(static_cast<size_t>(num_levels()));
    std::vector<Vec3> fine = finest;
    for (int l = num_levels(); l >= 1; --l) {
        const RowMatrix& s = subdivision_[l - 1];
        std::vector<Vec3> coarse = least_squares(s, fine, "multiresolution analysis");
        const std::vector<Vec3> predicted = times(s, coarse);
        const std::vector<Eigen::Matrix3d> f = frames(l, predicted);
        std::vector<Vec3>& detail = d.details[l - 1];
        detail.resize(fine.size());
        for (size_t v = 0; v < fine.size(); ++v) detail[v] = f[v].transpose() * (fine[v] - predicted[v]);
        fine = std::move(coarse);
    }
    d.base = std::move(fine);
    return d;
}

std::vector<Vec3> LoopMultiresolution::recompose(const MultiresolutionDecomposition& d) const {
    check_count(d.base, num_base_, "base positions");
    if (static_cast<int>(d.details.size()) != num_levels())
        throw InputError("multiresolution: details of " + std::to_string(d.details.size()) + " levels for " +
                         std::to_string(num_levels()));
    std::vector<Vec3> p = d.base;
    for (int l = 1; l <= num_levels(); ++l) {
        check_count(d.details[l - 1], num_vertices(l), "details");
        std::vector<Vec3> q = times(subdivision_[l - 1], p);
        const std::vector<Eigen::Matrix3d> f = frames(l, q);
        for (size_t v = 0; v < q.size(); ++v) q[v] += f[v] * d.details[l - 1][v];
        p = std::move(q);
    }
    return p;
}

std::vector<char> LoopMultiresolution::edit_reach(const std::vector<int>& edited, bool with_frames) const {
    std::vector<char> moved(static_cast<size_t>(num_base_), 0);
    for (int v : edited) moved.at(static_cast<size_t>(v)) = 1;
    for (int l = 1; l <= num_levels(); ++l) {
        const RowMatrix& s = subdivision_[l - 1];
        std::vector<char> next(static_cast<size_t>(s.rows()), 0);
        for (Eigen::Index r = 0; r < s.rows(); ++r)
            for (RowMatrix::InnerIterator it(s, r); it; ++it)
                if (it.value() != 0 && moved[static_cast<size_t>(it.col())]) next[static_cast<size_t>(r)] = 1;
        if (with_frames) {
            // A vertex's frame reads its own and its neighbours' predictions.
            std::vector<char> ring = next;
            for (const Triangle& t : triangles_[l])
                if (next[t[0]] || next[t[1]] || next[t[2]]) ring[t[0]] = ring[t[1]] = ring[t[2]] = 1;
            next = std::move(ring);
        }
        moved = std::move(next);
    }
    return moved;
}

}  // namespace crossdiv
