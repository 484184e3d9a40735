#pragma once
/// @file
/// How close is close enough: the tiers of every refinement comparison (OpenSubdiv's
/// hbr/far regressions have the first two; the third compares surfaces whose vertices need
/// not correspond).

#include <string>

namespace crossdiv::verification {

enum class Tier {
    Strict,     ///< bitwise: identical topology and every coordinate equal
    Weak,       ///< identical topology, max distance <= tolerance * diagonal at every level compared
    Geometric,  ///< vertex-set Hausdorff distance <= tolerance * diagonal; topology may differ
};
const char* to_string(Tier tier);
/// @throws InputError for a name other than strict, weak, geometric.
Tier tier_from_string(const std::string& name);

}  // namespace crossdiv::verification
