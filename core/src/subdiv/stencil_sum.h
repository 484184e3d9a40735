#pragma once
// The one way Loop stencils are summed, shared by the index-based driver and the
// split-and-flip method so that both give bit-identical points.

#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::detail {

/// wa * (sum of p over group a) + wb * (sum of p over group b) [+ wc * (sum over group c)]:
/// Loop's and Warren's masks are two groups of equally weighted sources (self + ring, or ends
/// + opposites), so each group is summed before it is scaled, in the order given. A third
/// group (the tuned families' second edge end) is added last, so that the two-group sums
/// keep their bits.
inline Vec3 stencil_sum(const std::vector<Vec3>& p, const int* a, int na, double wa, const int* b, int nb, double wb,
                        const int* c = nullptr, int nc = 0, double wc = 0.0) {
    Vec3 sa = p[a[0]];
    for (int k = 1; k < na; ++k) sa += p[a[k]];
    if (nb == 0) return wa * sa;
    Vec3 sb = p[b[0]];
    for (int k = 1; k < nb; ++k) sb += p[b[k]];
    if (nc == 0) return wa * sa + wb * sb;
    Vec3 sc = p[c[0]];
    for (int k = 1; k < nc; ++k) sc += p[c[k]];
    return wa * sa + wb * sb + wc * sc;
}

}  // namespace crossdiv::detail
