#include "crossdiv/subdiv/limit_fitting.h"

#include <cmath>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/closest_point.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/least_squares.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/loop.h"
#include "normal_equations.h"

namespace crossdiv {
namespace {

using detail::Points;
using detail::check_finite;
using detail::to_matrix;
using detail::to_points;
using detail::solve_normal_equations;

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

void check_levels(int levels) {
    if (levels < 0) throw InputError("fitting: the level count must be >= 0, not " + std::to_string(levels));
}

/// S_L ... S_1 of `levels` levels from `level`, which is left at the last level.
template <class Mesh, class Matrix, class Refine>
Eigen::SparseMatrix<double> composed_levels(Mesh& level, int levels, Matrix matrix, Refine refine) {
    Eigen::SparseMatrix<double> composed(level.num_vertices(), level.num_vertices());
    composed.setIdentity();
    for (int l = 0; l < levels; ++l) {
        composed = matrix(level) * composed;
        level = refine(level);
    }
    return composed;
}

}  // namespace

std::vector<Vec3> LimitSampling::evaluate(const std::vector<Vec3>& control) const {
    return to_points(stencils * to_matrix(control));
}

TriMesh LimitSampling::surface(const std::vector<Vec3>& control) const {
    TriMesh mesh;
    mesh.positions = evaluate(control);
    mesh.triangles = triangles;
    return mesh;
}

LimitSampling loop_limit_sampling(const TriMesh& control, const LoopOptions& options, int levels) {
    check_levels(levels);
    TriMesh level = control;
    const Eigen::SparseMatrix<double> composed = composed_levels(
        level, levels, [&](const TriMesh& m) { return loop_subdivision_matrix(m, options); },
        [&](const TriMesh& m) { return loop_subdivide(m, options, 1); });
    LimitSampling out;
    out.stencils = RowMatrix(loop_limit_matrix(level, options) * composed);
    out.triangles = std::move(level.triangles);
    out.levels = levels;
    return out;
}

LimitSampling catmull_clark_limit_sampling(const PolyMesh& control, const CatmullClarkOptions& options, int levels) {
    check_levels(levels);
    if (!control.creases.empty()) throw InputError("fitting takes meshes without crease or corner tags");
    PolyMesh level = control;
    const Eigen::SparseMatrix<double> composed = composed_levels(
        level, levels, [&](const PolyMesh& m) { return catmull_clark_subdivision_matrix(m, options); },
        [&](const PolyMesh& m) { return catmull_clark_subdivide(m, options, 1); });
    LimitSampling out;
    out.stencils = RowMatrix(catmull_clark_limit_matrix(level, options) * composed);
    for (int f = 0; f < level.num_faces(); ++f) {
        const int* c = &level.face_vertices[static_cast<size_t>(level.face_start[f])];
        for (int k = 1; k + 1 < level.face_size(f); ++k) out.triangles.push_back({c[0], c[k], c[k + 1]});
    }
    out.levels = levels;
    return out;
}

std::vector<Vec3> fit_limit_points(const LimitSampling& sampling, const std::vector<Vec3>& points) {
    return least_squares(sampling.stencils, points, "fitting");
}

FittingResult fit_limit_surface(const LimitSampling& sampling, const std::vector<Vec3>& start, const TriMesh& target,
                                const FittingOptions& options) {
    if (static_cast<int>(start.size()) != sampling.num_control())
        throw InputError("fitting: " + std::to_string(start.size()) + " start positions for " +
                         std::to_string(sampling.num_control()) + " control vertices");
    check_finite(start, "fitting: start position");
    check_finite(target.positions, target.source.file.empty() ? "fitting: target vertex" : target.source.file + ": vertex");
    for (int f = 0; f < target.num_faces(); ++f)
        for (int v : target.triangles[f])
            if (v < 0 || v >= target.num_vertices())
                throw InputError("fitting: target triangle " + std::to_string(f) + " names vertex " + std::to_string(v) +
                                 " of " + std::to_string(target.num_vertices()));
    if (target.triangles.empty()) throw InputError("fitting: the target has no triangles");

    const RowMatrix& a = sampling.stencils;
    const Eigen::SparseMatrix<double> at = a.transpose();
    const Eigen::SparseMatrix<double> ata = at * a;
    const TriangleTree target_tree(target.positions, target.triangles);
    const Points t = to_matrix(target.positions);
    const int ns = sampling.num_samples(), nt = target.num_vertices();

    FittingResult result;
    Points x = to_matrix(start);
    Points closest_on_target(ns, 3);
    std::vector<Eigen::Triplet<double>> b_terms;
    for (int k = 0;; ++k) {
        // Correspondences at X_k and the distances they measure.
        const Points samples = a * x;
        FittingStep step;
        step.control = to_points(x);
        double sum_s = 0, sum_t = 0;
        for (int i = 0; i < ns; ++i) {
            const TriangleTree::Hit h = target_tree.closest(samples.row(i).transpose());
            closest_on_target.row(i) = h.where.point.transpose();
            sum_s += h.squared_distance;
            step.max_sample_to_target = std::max(step.max_sample_to_target, std::sqrt(h.squared_distance));
        }
        const std::vector<Vec3> sample_points = to_points(samples);
        const TriangleTree surface_tree(sample_points, sampling.triangles);
        b_terms.clear();
        for (int j = 0; j < nt; ++j) {
            const TriangleTree::Hit h = surface_tree.closest(target.positions[j]);
            sum_t += h.squared_distance;
            step.max_target_to_surface = std::max(step.max_target_to_surface, std::sqrt(h.squared_distance));
            const Triangle& tri = sampling.triangles[h.triangle];
            for (int c = 0; c < 3; ++c)
                for (RowMatrix::InnerIterator it(a, tri[c]); it; ++it)
                    b_terms.emplace_back(j, static_cast<int>(it.col()), h.where.barycentric[c] * it.value());
        }
        step.energy = sum_s + sum_t;
        step.rms_sample_to_target = std::sqrt(sum_s / ns);
        step.rms_target_to_surface = std::sqrt(sum_t / nt);
        result.steps.push_back(std::move(step));
        if (k == options.iterations) break;

        // The least-squares X for these correspondences.
        RowMatrix b(nt, sampling.num_control());
        b.setFromTriplets(b_terms.begin(), b_terms.end());
        const Eigen::SparseMatrix<double> bt = b.transpose();
        const Eigen::SparseMatrix<double> normal = ata + Eigen::SparseMatrix<double>(bt * b);
        const Points rhs = at * closest_on_target + bt * t;
        x = solve_normal_equations(normal, rhs, [&](const Points& y) -> Points {
            return Points(at * (closest_on_target - a * y)) + Points(bt * (t - b * y));
        }, "fitting");
    }
    return result;
}

}  // namespace crossdiv
