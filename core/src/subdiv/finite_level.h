#pragma once
// The check every refinement driver makes after a level: a finite input can still overflow in
// the masks (coordinates near DBL_MAX summed with positive weights, or extrapolated by the
// Butterflies' negative ones), and a NaN or inf written as a result is a silent wrong answer.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::detail {

/// @throws InputError naming the first vertex of `level` whose position is not finite, with
///         the largest coordinate magnitude of the level before it (`coarse`).
inline void require_finite_level(std::span<const Vec3> fine, std::span<const Vec3> coarse, int level) {
    for (size_t v = 0; v < fine.size(); ++v) {
        if (fine[v].allFinite()) continue;
        double largest = 0;
        for (const Vec3& p : coarse) largest = std::max(largest, p.cwiseAbs().maxCoeff());
        char value[96];
        std::snprintf(value, sizeof value, "(%g, %g, %g)", fine[v].x(), fine[v].y(), fine[v].z());
        char magnitude[32];
        std::snprintf(magnitude, sizeof magnitude, "%.3g", largest);
        throw InputError("level " + std::to_string(level) + ", vertex " + std::to_string(v) + ": the refined position " +
                         value + " is not finite; the coordinates (up to " + magnitude +
                         " in magnitude) overflow double in the masks, so scale the input down");
    }
}

}  // namespace crossdiv::detail
