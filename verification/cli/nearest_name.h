#pragma once
/// @file
/// The valid name nearest to a mistyped one, for "did you mean" in the command line's errors.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace crossdiv::cli {

/// The edit distance of `a` and `b` (insertions, deletions, substitutions, and transpositions
/// of two neighbouring characters, each costing 1: the optimal string alignment distance).
int edit_distance(std::string_view a, std::string_view b);

/// The name of `names` nearest to `typed` when it is close enough to be a slip: at most 2
/// edits, and at most a third of the typed length (so "-o" suggests nothing), or `typed` a
/// prefix of exactly one name. The first of equally near names; nothing when none is near.
std::optional<std::string> nearest_name(std::string_view typed, const std::vector<std::string>& names);

}  // namespace crossdiv::cli
