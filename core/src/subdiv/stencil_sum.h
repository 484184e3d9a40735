#pragma once
// The one way Loop stencils are summed, shared by the index-based driver and the
// split-and-flip method so that both give bit-identical points.

#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::detail {

/// wa * (sum of p over group a) + wb * (sum of p over group b): every Loop mask is two groups
/// of equally weighted sources (self + ring, or ends + opposites), so each group is summed
/// before it is scaled, in the order given.
inline Vec3 stencil_sum(const std::vector<Vec3>& p, const int* a, int na, double wa, const int* b, int nb, double wb) {
    Vec3 sa = p[a[0]];
    for (int k = 1; k < na; ++k) sa += p[a[k]];
    if (nb == 0) return wa * sa;
    Vec3 sb = p[b[0]];
    for (int k = 1; k < nb; ++k) sb += p[b[k]];
    return wa * sa + wb * sb;
}

}  // namespace crossdiv::detail
