#include "crossdiv/surfaces/sweep_mesh.h"

#include <algorithm>
#include <cmath>

#include "crossdiv/error.h"

namespace crossdiv {

namespace {

/// The cells of the grid as (ring, sample) corner indices, the closed directions wrapped.
template <class F>
void for_each_cell(const SweepGrid& g, F&& f) {
    const int ring_cells = g.closed_sweep ? g.rings : g.rings - 1;
    const int profile_cells = g.closed_profile ? g.ring_size : g.ring_size - 1;
    for (int i = 0; i < ring_cells; ++i)
        for (int j = 0; j < profile_cells; ++j) f(i, j, (i + 1) % g.rings, (j + 1) % g.ring_size);
}

}  // namespace

SurfaceMesh mesh_sweep(const SweepGrid& g) {
    if (g.rings < 2 || g.ring_size < 2 || g.positions.size() != static_cast<size_t>(g.rings) * g.ring_size ||
        g.normals.size() != g.positions.size())
        throw InputError("a swept surface needs at least 2 rings of 2 samples (got " + std::to_string(g.rings) + " x " +
                         std::to_string(g.ring_size) + ")");
    SurfaceMesh s;
    s.mesh.positions = g.positions;
    s.normals = g.normals;
    auto id = [&](int i, int j) { return i * g.ring_size + j; };
    double agreement = 0;
    for_each_cell(g, [&](int i, int j, int i1, int j1) {
        const Triangle t0{id(i, j), id(i1, j), id(i1, j1)}, t1{id(i, j), id(i1, j1), id(i, j1)};
        for (const Triangle& t : {t0, t1}) {
            const Vec3 n = (g.positions[t[1]] - g.positions[t[0]]).cross(g.positions[t[2]] - g.positions[t[0]]);
            agreement += n.dot(g.normals[t[0]] + g.normals[t[1]] + g.normals[t[2]]);
            s.mesh.triangles.push_back(t);
        }
    });
    if (agreement < 0)
        for (Triangle& t : s.mesh.triangles) std::swap(t[1], t[2]);
    weld(s);
    return s;
}

double point_triangle_distance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return ap.norm();
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return bp.norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return cp.norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
    const double denom = 1 / (va + vb + vc);
    return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

double grid_deviation(const SweepGrid& g, const ExactSurface& exact, int k) {
    auto pp = [&](int j) { return g.profile_params[j]; };
    auto sp = [&](int i) { return g.sweep_params[i]; };
    double worst = 0;
    for_each_cell(g, [&](int i, int j, int i1, int j1) {
        // Parameters of the cell's corners; a wrapped index takes the end parameter.
        const double s0 = sp(i), s1 = sp(i1 == 0 ? g.rings : i1), t0 = pp(j), t1 = pp(j1 == 0 ? g.ring_size : j1);
        const Vec3 &a = g.at(i, j), &b = g.at(i1, j), &c = g.at(i1, j1), &d = g.at(i, j1);
        // Every parameter sample of the cell, measured against the nearer of the cell's two
        // triangles: a cell's parameters do not split along its diagonal the way its points
        // do (nor at all where a pole collapses one triangle).
        auto cell_distance = [&](double t, double s) {
            const Vec3 p = exact(t, s);
            return std::min(point_triangle_distance(p, a, b, c), point_triangle_distance(p, a, c, d));
        };
        for (int x = 0; x <= k; ++x)
            for (int y = 0; y <= k; ++y) {
                const double ft = static_cast<double>(x) / k, fs = static_cast<double>(y) / k;
                worst = std::max(worst, cell_distance(t0 + ft * (t1 - t0), s0 + fs * (s1 - s0)));
            }
    });
    return worst;
}

}  // namespace crossdiv
