#include "crossdiv/volume/scalar_grid.h"

#include <cmath>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv {

namespace {
std::string sample_name(const ScalarGrid& g, int64_t s) {
    const int64_t i = s % g.size[0], j = s / g.size[0] % g.size[1], k = s / (int64_t{g.size[0]} * g.size[1]);
    return "sample (" + std::to_string(i) + ", " + std::to_string(j) + ", " + std::to_string(k) + ")";
}
}  // namespace

void check_sample_count(const std::array<int, 3>& size, const std::string& what) {
    if (double(size[0]) * size[1] * size[2] > double(kMaxGridSamples))
        throw InputError(what + ": " + std::to_string(size[0]) + " x " + std::to_string(size[1]) + " x " +
                         std::to_string(size[2]) + " samples are more than the " + std::to_string(kMaxGridSamples) +
                         " a grid may have");
}

void check_grid(const ScalarGrid& g, const std::string& what) {
    for (int a = 0; a < 3; ++a)
        if (g.size[a] < 2)
            throw InputError(what + ": a grid needs at least 2 samples along each axis (axis " + std::to_string(a) + " has " +
                             std::to_string(g.size[a]) + ")");
    check_sample_count(g.size, what);
    if (!g.origin.allFinite()) throw InputError(what + ": the grid origin is not finite");
    for (int a = 0; a < 3; ++a)
        if (!(std::isfinite(g.spacing[a]) && g.spacing[a] > 0))
            throw InputError(what + ": the grid spacing along axis " + std::to_string(a) + " must be finite and > 0");
    if (!g.position(g.size[0] - 1, g.size[1] - 1, g.size[2] - 1).allFinite())
        throw InputError(what + ": the grid's far corner leaves the range of double");
    if (static_cast<int64_t>(g.values.size()) != g.num_samples())
        throw InputError(what + ": " + std::to_string(g.values.size()) + " values for " + std::to_string(g.num_samples()) +
                         " samples");
    for (int64_t s = 0; s < g.num_samples(); ++s)
        if (!std::isfinite(g.values[s])) throw InputError(what + ": " + sample_name(g, s) + " is not finite");
}

ScalarGrid sample_grid(const std::function<double(const Vec3&)>& f, const Vec3& lo, const Vec3& hi,
                       std::array<int, 3> n) {
    ScalarGrid g;
    g.size = n;
    g.origin = lo;
    for (int a = 0; a < 3; ++a) {
        if (n[a] < 2) throw InputError("sampling a function needs at least 2 samples along each axis");
        g.spacing[a] = (hi[a] - lo[a]) / (n[a] - 1);
    }
    check_sample_count(n, "sampled grid");
    g.values.resize(g.num_samples());
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i) {
                // At position(), where marching cubes places the sample, not at lo + (hi - lo) i / (n - 1).
                const Vec3 p = g.position(i, j, k);
                g.values[g.index(i, j, k)] = f(p);
            }
    check_grid(g, "sampled grid");
    return g;
}

}  // namespace crossdiv
