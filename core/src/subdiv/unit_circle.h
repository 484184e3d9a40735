#pragma once
// The angles of a ring or polygon of n elements, for the masks stated through Fourier sums
// (doo_sabin.cpp's faces of many sides, butterfly.cpp's vertices of large valence).

#include <cmath>
#include <numbers>
#include <vector>

namespace crossdiv::detail {

/// Appends cos and sin of 2 pi m / n for m = 0 .. n-1, each from its own angle (no rotation
/// recurrence, whose error grows with m). A mask's cos(2 m t) is entry (2 m) mod n.
inline void append_unit_circle(int n, std::vector<double>& cosines, std::vector<double>& sines) {
    for (int m = 0; m < n; ++m) {
        const double a = 2.0 * std::numbers::pi * m / n;
        cosines.push_back(std::cos(a));
        sines.push_back(std::sin(a));
    }
}

}  // namespace crossdiv::detail
