#pragma once
// Point-set helpers of the tests that perturb positions and measure how far they moved.

#include <algorithm>
#include <random>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::test {

/// Each point moved by a pseudo-random offset in [-amount, amount]^3 from `seed` (mt19937).
inline std::vector<Vec3> perturbed(std::vector<Vec3> p, double amount, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amount, amount);
    for (Vec3& x : p) x += Vec3(u(rng), u(rng), u(rng));
    return p;
}

/// The largest distance between corresponding points.
inline double largest_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
}

}  // namespace crossdiv::test
