#pragma once
/// @file
/// The named rules for a mesh that is not a manifold (the rules themselves: nonmanifold.h).

#include <array>
#include <string_view>

#include "crossdiv/named_variant.h"

namespace crossdiv {

/// What Loop and Catmull-Clark do with a mesh that is not a manifold.
enum class NonManifoldRule {
    OpenSubdiv,  ///< refine it with OpenSubdiv's rules (nonmanifold.h)
    Refuse,      ///< refuse it, naming the element (InputError)
};

/// "opensubdiv" / "refuse".
constexpr std::string_view to_string(NonManifoldRule r) { return r == NonManifoldRule::OpenSubdiv ? "opensubdiv" : "refuse"; }
/// @throws InputError listing the names.
inline NonManifoldRule nonmanifold_rule_from_string(std::string_view name) {
    return variant_from_string<NonManifoldRule>(name, std::array{NonManifoldRule::OpenSubdiv, NonManifoldRule::Refuse},
                                                "non-manifold rule");
}

}  // namespace crossdiv
