#pragma once
/// @file
/// Parsing the name of a rule variant back into its enum: the inverse of each rule's
/// to_string, with one error that lists the names a user may give.

#include <string>
#include <string_view>

#include "crossdiv/error.h"

namespace crossdiv {

/// "a, b, c": the names of the members of `all`, for messages.
template <class All>
std::string variant_names(const All& all) {
    std::string names;
    for (const auto& v : all) names += (names.empty() ? "" : ", ") + std::string(to_string(v));
    return names;
}

/// The member of `all` whose to_string is `name`.
/// @throws InputError "unknown WHAT 'name' (known: a, b, c)".
template <class Enum, class All>
Enum variant_from_string(std::string_view name, const All& all, const char* what) {
    for (Enum v : all)
        if (to_string(v) == name) return v;
    throw InputError("unknown " + std::string(what) + " '" + std::string(name) + "' (known: " + variant_names(all) + ")");
}

}  // namespace crossdiv
