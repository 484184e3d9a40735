#include "crossdiv/datasets/implicit_surfaces.h"

#include <cmath>
#include <numbers>

#include "crossdiv/error.h"

namespace crossdiv::datasets {

namespace {

constexpr double kPi = std::numbers::pi;

ImplicitSurface sphere() {
    // Off the grid's symmetry, so that no sample lies on the surface by construction.
    static const Vec3 c(0.0123, -0.0234, 0.0345);
    return {"sphere", "unit sphere", [](const Vec3& p) { return (p - c).norm() - 1; },
            [](const Vec3& p) { return Vec3((p - c).normalized()); }, Vec3(-1.25, -1.25, -1.25), Vec3(1.25, 1.25, 1.25),
            true, 2, 4 * kPi / 3};
}

ImplicitSurface torus() {
    constexpr double R = 1, r = 0.4;
    return {"torus", "torus R 1, r 0.4",
            [](const Vec3& p) { return std::hypot(std::hypot(p.x(), p.y()) - R, p.z()) - r; },
            [](const Vec3& p) {
                const double rho = std::hypot(p.x(), p.y());
                const Vec3 axial(p.x() / rho, p.y() / rho, 0);
                return Vec3(((rho - R) * axial + Vec3(0, 0, p.z())).normalized());
            },
            Vec3(-1.55, -1.55, -0.55), Vec3(1.55, 1.55, 0.55), true, 0, 2 * kPi * kPi * R * r * r};
}

ImplicitSurface genus2() {
    // A tube round the figure eight (x^2 + y^2)^2 = x^2 - y^2: each lobe's hole holds L^2 up to
    // 0.0625 (L = -1/4 at (+-1/sqrt 2, 0)), so eps = 0.04 leaves both holes open; L's critical
    // points are off the surface, which is therefore smooth.
    constexpr double eps = 0.04;
    const auto L = [](double x, double y) { const double q = x * x + y * y; return q * q - x * x + y * y; };
    return {"genus2", "genus 2: tube round the lemniscate, L^2 + z^2 = 0.04",
            [L](const Vec3& p) { const double l = L(p.x(), p.y()); return l * l + p.z() * p.z() - eps; },
            [L](const Vec3& p) {
                const double x = p.x(), y = p.y(), q = x * x + y * y, l = L(x, y);
                return Vec3(2 * l * (4 * x * q - 2 * x), 2 * l * (4 * y * q + 2 * y), 2 * p.z());
            },
            Vec3(-1.2, -0.6, -0.3), Vec3(1.2, 0.6, 0.3), false, -2, std::nullopt};
}

ImplicitSurface gyroid() {
    return {"gyroid", "gyroid over one period (open, cut by the box)",
            [](const Vec3& p) {
                return std::sin(p.x()) * std::cos(p.y()) + std::sin(p.y()) * std::cos(p.z()) + std::sin(p.z()) * std::cos(p.x());
            },
            [](const Vec3& p) {
                const double sx = std::sin(p.x()), cx = std::cos(p.x()), sy = std::sin(p.y()), cy = std::cos(p.y());
                const double sz = std::sin(p.z()), cz = std::cos(p.z());
                return Vec3(cx * cy - sz * sx, -sx * sy + cy * cz, -sy * sz + cz * cx);
            },
            Vec3(0.1, 0.2, 0.3), Vec3(0.1 + 2 * kPi, 0.2 + 2 * kPi, 0.3 + 2 * kPi), false, std::nullopt, std::nullopt};
}

}  // namespace

const std::vector<ImplicitSurface>& implicit_surfaces() {
    static const std::vector<ImplicitSurface> all{sphere(), torus(), genus2(), gyroid()};
    return all;
}

const ImplicitSurface& implicit_surface(std::string_view name) {
    for (const ImplicitSurface& s : implicit_surfaces())
        if (s.name == name) return s;
    throw InputError("unknown implicit surface '" + std::string(name) + "' (sphere, torus, genus2, gyroid)");
}

ScalarGrid sample(const ImplicitSurface& s, int resolution) {
    if (resolution < 3) throw InputError("the resolution must be at least 3 samples");
    const Vec3 extent = s.hi - s.lo;
    const double h = extent.maxCoeff() / (resolution - 1);
    std::array<int, 3> n{};
    for (int a = 0; a < 3; ++a) {
        const double cells = std::ceil(extent[a] / h - 1e-9);  // the box's far side sampled, not rounded away
        if (cells + 1 > double(kMaxGridSamples)) throw InputError("resolution " + std::to_string(resolution) + " is too large");
        n[a] = static_cast<int>(cells) + 1;
    }
    return sample_grid(s.f, s.lo, s.lo + h * Vec3(n[0] - 1, n[1] - 1, n[2] - 1), n);
}

double distance_to(const ImplicitSurface& s, const Vec3& p) {
    if (s.signed_distance) return std::abs(s.f(p));
    Vec3 q = p;
    for (int step = 0; step < 60; ++step) {
        const double value = s.f(q);
        const Vec3 g = s.gradient(q);
        const Vec3 move = value / g.squaredNorm() * g;
        q -= move;
        if (move.norm() <= 1e-15 * (1 + q.norm())) break;
    }
    return (p - q).norm();
}

ScalarGrid ambiguous_field(int n) {
    if (n < 3) throw InputError("the ambiguous field needs at least 3 samples along each axis");
    ScalarGrid g;
    g.size = {n, n, n};
    g.spacing = Vec3::Constant(1.0 / (n - 1));
    g.values.resize(g.num_samples());
    uint32_t state = 12345;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG: the same field every run
                const bool shell = i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
                g.values[g.index(i, j, k)] = shell ? 1.0 : (state >> 8) / double(1 << 24) * 2 - 1;
            }
    check_grid(g, "ambiguous field");
    return g;
}

}  // namespace crossdiv::datasets
