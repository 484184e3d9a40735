#include "crossdiv/surfaces/bezier_patch.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/error.h"

namespace crossdiv {

std::string_view to_string(NormalSource s) {
    switch (s) {
        case NormalSource::Derivatives: return "derivatives";
        case NormalSource::Limit: return "limit";
        case NormalSource::ControlNet: return "control-net";
    }
    return "?";
}

namespace {

void require_valid(const BezierPatch& p) {
    if (p.rows < 1 || p.cols < 1 || p.control.size() != static_cast<size_t>(p.rows) * p.cols)
        throw InputError("Bezier patch" + (p.line ? " (line " + std::to_string(p.line) + ")" : std::string()) + ": " +
                         std::to_string(p.control.size()) + " control points for a " + std::to_string(p.rows) + " x " +
                         std::to_string(p.cols) + " grid");
}

std::span<const Vec3> row(const BezierPatch& p, int r) { return {p.control.data() + static_cast<size_t>(r) * p.cols, static_cast<size_t>(p.cols)}; }

double binomial(int n, int k) {
    double b = 1;
    for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
    return b;
}

/// Bernstein values B_i^d(t), i = 0..d.
std::vector<double> bernstein(int d, double t) {
    std::vector<double> b(d + 1);
    for (int i = 0; i <= d; ++i) b[i] = binomial(d, i) * std::pow(t, i) * std::pow(1 - t, d - i);
    return b;
}

}  // namespace

/// Runs f on `rows` scratch points: on the stack for the common degrees (bicubic has 4
/// rows), so evaluating a tessellation allocates nothing per vertex.
template <class F>
auto with_columns(int rows, F&& f) {
    constexpr int kStack = 16;
    if (rows <= kStack) {
        std::array<Vec3, kStack> a, b;
        return f(std::span<Vec3>(a.data(), rows), std::span<Vec3>(b.data(), rows));
    }
    std::vector<Vec3> a(rows), b(rows);
    return f(std::span<Vec3>(a), std::span<Vec3>(b));
}

Vec3 patch_point(const BezierPatch& p, double u, double v) {
    require_valid(p);
    return with_columns(p.rows, [&](std::span<Vec3> column, std::span<Vec3>) {
        for (int r = 0; r < p.rows; ++r) column[r] = bezier_point(row(p, r), u);
        return bezier_point(column, v);
    });
}

Vec3 patch_bernstein_point(const BezierPatch& p, double u, double v) {
    require_valid(p);
    const std::vector<double> bu = bernstein(p.cols - 1, u), bv = bernstein(p.rows - 1, v);
    Vec3 sum = Vec3::Zero();
    for (int r = 0; r < p.rows; ++r)
        for (int c = 0; c < p.cols; ++c) sum += bv[r] * bu[c] * p.at(r, c);
    return sum;
}

PatchJet patch_jet(const BezierPatch& p, double u, double v) {
    require_valid(p);
    // The rows at u give the column of points (whose curve in v is the iso-curve through
    // the point) and the column of u-derivatives (whose curve in v is du along it).
    return with_columns(p.rows, [&](std::span<Vec3> points, std::span<Vec3> du) {
        for (int r = 0; r < p.rows; ++r) {
            const BezierJet j = bezier_jet(row(p, r), u);
            points[r] = j.position;
            du[r] = j.d1;
        }
        const BezierJet along = bezier_jet(points, v);
        const BezierJet du_along = bezier_jet(du, v);
        return PatchJet{along.position, du_along.position, along.d1, du_along.d1};
    });
}

namespace {

/// patch_normal from an evaluated jet; `vanish` = kPatchDegenerateRelative times the
/// control net's diagonal, computed once per patch by the callers.
Vec3 normal_from_jet(const BezierPatch& p, const PatchJet& j, double u, double v, double vanish, NormalSource* source) {
    auto set = [&](NormalSource s) { if (source) *source = s; };
    Vec3 n = j.du.cross(j.dv);
    if (n.norm() > kPatchDegenerateRelative * j.du.norm() * j.dv.norm() && j.du.norm() > vanish && j.dv.norm() > vanish) {
        set(NormalSource::Derivatives);
        return n.normalized();
    }
    // A vanishing du at (u, v) grows as du(u, v + h) ~ h duv when stepping into the patch
    // (h > 0 below v = 0.5, h < 0 above), so du x dv tends to the direction of
    // (sign h) duv x dv; likewise for a vanishing dv.
    Vec3 du = j.du, dv = j.dv;
    if (du.norm() <= vanish) du = (v < 0.5 ? 1.0 : -1.0) * j.duv;
    if (dv.norm() <= vanish) dv = (u < 0.5 ? 1.0 : -1.0) * j.duv;
    n = du.cross(dv);
    if (n.norm() > kPatchDegenerateRelative * du.norm() * dv.norm() && n.norm() > 0) {
        set(NormalSource::Limit);
        return n.normalized();
    }
    const Vec3 a = p.at(p.rows - 1, p.cols - 1) - p.at(0, 0), b = p.at(p.rows - 1, 0) - p.at(0, p.cols - 1);
    set(NormalSource::ControlNet);
    n = a.cross(b);  // a runs along +u+v and b along -u+v, so a x b points like du x dv
    return n.norm() > 0 ? n.normalized() : Vec3(0, 0, 0);
}

}  // namespace

Vec3 patch_normal(const BezierPatch& p, double u, double v, NormalSource* source) {
    const PatchJet j = patch_jet(p, u, v);
    return normal_from_jet(p, j, u, v, kPatchDegenerateRelative * bounding_box_diagonal(p.control), source);
}

SurfaceMesh tessellate_patches(std::span<const BezierPatch> patches, int res, long long max_triangles) {
    if (res < 1) throw InputError("patch resolution must be at least 1, got " + std::to_string(res));
    require_surface_size(2LL * static_cast<long long>(patches.size()) * res * res, max_triangles,
                         "the tessellation of " + std::to_string(patches.size()) + " patches at resolution " +
                             std::to_string(res));
    SurfaceMesh s;
    const int side = res + 1;
    s.mesh.positions.reserve(patches.size() * side * side);
    s.normals.reserve(patches.size() * side * side);
    s.mesh.triangles.reserve(patches.size() * 2 * res * res);
    for (const BezierPatch& p : patches) {
        require_valid(p);
        const int base = s.mesh.num_vertices();
        const double vanish = kPatchDegenerateRelative * bounding_box_diagonal(p.control);
        for (int i = 0; i < side; ++i)
            for (int k = 0; k < side; ++k) {
                const double u = static_cast<double>(k) / res, v = static_cast<double>(i) / res;
                const PatchJet j = patch_jet(p, u, v);
                s.mesh.positions.push_back(j.position);
                s.normals.push_back(normal_from_jet(p, j, u, v, vanish, nullptr));
            }
        for (int i = 0; i < res; ++i)
            for (int k = 0; k < res; ++k) {
                const int a = base + i * side + k, b = a + 1, c = a + side + 1, d = a + side;
                s.mesh.triangles.push_back({a, b, c});
                s.mesh.triangles.push_back({a, c, d});
            }
    }
    weld(s);
    return s;
}

double max_boundary_gap(std::span<const BezierPatch> patches, int samples, int* shared_edges) {
    // The four boundary curves of a patch, each as its control polygon.
    struct Edge {
        std::vector<Vec3> control;
    };
    std::vector<Edge> edges;
    std::vector<Vec3> all;
    for (const BezierPatch& p : patches) {
        require_valid(p);
        Edge e0, e1, e2, e3;
        for (int c = 0; c < p.cols; ++c) e0.control.push_back(p.at(0, c)), e2.control.push_back(p.at(p.rows - 1, c));
        for (int r = 0; r < p.rows; ++r) e1.control.push_back(p.at(r, p.cols - 1)), e3.control.push_back(p.at(r, 0));
        for (Edge* e : {&e0, &e1, &e2, &e3}) edges.push_back(std::move(*e));
        all.insert(all.end(), p.control.begin(), p.control.end());
    }
    const double tol = kWeldRelative * bounding_box_diagonal(all);
    double gap = 0;
    int pairs = 0;
    for (size_t a = 0; a < edges.size(); ++a)
        for (size_t b = a + 1; b < edges.size(); ++b) {
            if (a / 4 == b / 4) continue;  // the same patch
            const auto& ea = edges[a].control;
            const auto& eb = edges[b].control;
            // Shared: the same control polygon, in either direction. Two edges with common
            // end points but other inner points are two different curves (the teapot
            // handle's upper and lower halves), not a crack.
            auto coincide = [&](bool reverse) {
                if (ea.size() != eb.size()) return false;
                for (size_t k = 0; k < ea.size(); ++k)
                    if ((ea[k] - eb[reverse ? eb.size() - 1 - k : k]).norm() > tol) return false;
                return true;
            };
            const bool same = coincide(false), reversed = !same && coincide(true);
            if (!same && !reversed) continue;
            if ((ea.front() - ea.back()).norm() <= tol) continue;  // a collapsed edge (a pole) matches everything
            ++pairs;
            for (int k = 0; k <= samples; ++k) {
                const double t = static_cast<double>(k) / samples;
                gap = std::max(gap, (bezier_point(ea, t) - bezier_point(eb, same ? t : 1 - t)).norm());
            }
        }
    if (shared_edges) *shared_edges = pairs;
    return gap;
}

}  // namespace crossdiv
