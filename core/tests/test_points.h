#pragma once
// Point helpers of the tests: short points, machine epsilon, closeness, and point sets that
// are perturbed and measured. Shared, so that every test file of one binary (compiled in
// batches, CMake's unity build) names each helper once.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::test {

/// Machine epsilon of double, the unit of the tests' ulp budgets.
inline constexpr double kEps = std::numeric_limits<double>::epsilon();

/// A point written short: v(1, 2) is (1, 2, 0).
inline Vec3 v(double x, double y, double z = 0) { return {x, y, z}; }

/// The corners of face `f` of `m`, as a vector to compare whole.
inline std::vector<int> face_corners(const PolyMesh& m, int f) { return {m.face(f), m.face(f) + m.face_size(f)}; }

/// Expects `got` within `tol` (Euclidean distance) of `want`.
inline void expect_near(const Vec3& got, const Vec3& want, double tol = 1e-15) {
    EXPECT_LE((got - want).norm(), tol) << got.transpose() << " vs " << want.transpose();
}

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
