#pragma once
/// @file
/// A scalar field sampled on a regular, axis-aligned grid: the input of isosurface extraction
/// (volume/marching_cubes.h), read from a volume file (io/volume_io.h) or sampled from an
/// implicit function.

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// Samples at origin + spacing * (i, j, k), i < size[0], j < size[1], k < size[2]; the value of
/// sample (i, j, k) is values[i + size[0] (j + size[1] k)] (x fastest, as volume files store it).
struct ScalarGrid {
    std::array<int, 3> size{0, 0, 0};
    Vec3 origin = Vec3::Zero();
    Vec3 spacing = Vec3::Ones();
    std::vector<double> values;

    int64_t num_samples() const { return int64_t{size[0]} * size[1] * size[2]; }
    int64_t index(int i, int j, int k) const { return i + int64_t{size[0]} * (j + int64_t{size[1]} * k); }
    double at(int i, int j, int k) const { return values[index(i, j, k)]; }
    Vec3 position(int i, int j, int k) const {
        return origin + Vec3(spacing.x() * i, spacing.y() * j, spacing.z() * k);
    }
};

/// The most samples a grid may have (2^28, 2 GiB of doubles): a volume header asking for more
/// is refused before anything is allocated.
inline constexpr int64_t kMaxGridSamples = int64_t{1} << 28;

/// Refuses (InputError naming `what`) a grid of more than kMaxGridSamples samples, before
/// anything is allocated for it.
void check_sample_count(const std::array<int, 3>& size, const std::string& what);

/// Checks what every grid must be: each size >= 2, at most kMaxGridSamples samples, finite
/// origin, spacing finite and > 0, one finite value per sample.
/// @param what names the grid in messages (a file name).
/// @throws InputError naming the first fault (the sample (i, j, k) of a non-finite value).
void check_grid(const ScalarGrid& grid, const std::string& what);

/// f sampled at n[0] x n[1] x n[2] points spanning the box [lo, hi] (both corners sampled).
/// @throws InputError for a bad box or count, or where f is not finite (naming the sample).
ScalarGrid sample_grid(const std::function<double(const Vec3&)>& f, const Vec3& lo, const Vec3& hi,
                       std::array<int, 3> n);

}  // namespace crossdiv
