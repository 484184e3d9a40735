#pragma once
/// @file
/// The order of convergence of a measured error as a step shrinks: the least-squares slope of
/// log(error) against log(step), as the studies report it (error ~ C h^order).

#include <algorithm>
#include <cmath>
#include <vector>

namespace crossdiv::verification {

/// Slope of log(err) on log(h) over the rows; an error of 0 counts as 1e-300 (the fit stays
/// finite and reports a very high order).
inline double fitted_order(const std::vector<double>& h, const std::vector<double>& err) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(h.size());
    for (size_t i = 0; i < h.size(); ++i) {
        const double x = std::log(h[i]), y = std::log(std::max(err[i], 1e-300));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace crossdiv::verification
