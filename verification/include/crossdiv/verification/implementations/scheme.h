#pragma once
/// @file
/// The schemes every implementation is asked for, and their named rules: the vocabulary in
/// which the harness states what it asks of core, of a library or of a user's code.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "crossdiv/mesh/face_varying_rule.h"
#include "crossdiv/subdiv/butterfly_mask.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/doo_sabin_mask.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/subdiv/sqrt3_mask.h"

namespace crossdiv::verification {

/// A refinement scheme.
enum class Scheme { Loop, CatmullClark, DooSabin, Sqrt3, Butterfly, ModifiedButterfly, Bilinear, Midpoint };

/// "loop", "catmull-clark", "doo-sabin", "sqrt3", "butterfly", "modified-butterfly", "bilinear",
/// "midpoint" (triangles split into four at their edge midpoints, midpoint.h).
const char* to_string(Scheme scheme);
/// @throws InputError naming the unknown scheme and the known ones.
Scheme scheme_from_string(std::string_view name);
/// Every scheme, in the order above.
std::vector<Scheme> all_schemes();
/// The schemes other than Loop.
std::vector<Scheme> polygon_schemes();

/// What the harness needs to know of a scheme's shape, in one place.
struct SchemeTraits {
    /// Keeps the old vertices, first and in their order, and splits each face around new
    /// edge points (and a face point, for a polygon): a triangle into four (Loop, the
    /// Butterflies), an n-gon into n quads (Catmull-Clark). Such levels are matched through
    /// provenance (match_by_provenance), level by level; the others (Doo-Sabin's dual faces,
    /// sqrt3's rotated split) by position.
    bool primal = false;
    /// Refines triangle meshes only, and makes triangles.
    bool triangles = false;
    /// Has OpenSubdiv's crease, corner and hole rules (Sdc semantics; core and Far share them).
    bool sdc_tags = false;
};
/// The traits of `scheme`.
const SchemeTraits& traits(Scheme scheme);

/// The named variant of each scheme; only the member of the scheme at hand is read. The
/// Butterflies have none (the variant is the scheme), bilinear and midpoint none at all
/// ("linear").
struct SchemeRule {
    LoopOptions loop{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    CatmullClarkOptions catmull_clark{CatmullClarkBoundary::EdgeOnly};
    DooSabinOptions doo_sabin{DooSabinBoundary::ChaikinBoundary};
    Sqrt3Options sqrt3{Sqrt3Parity::CountFromInput};
    ButterflyWings butterfly_wings = ButterflyWings::Reflected;  ///< both Butterflies
};

/// The rule's name for `scheme`: "weights=loop boundary=edge-only" for Loop, "edge-only" or
/// "edge-only vertex=edge-point-average" for Catmull-Clark, "chaikin-boundary" or
/// "chaikin-boundary weights=catmull-clark", "count-from-input", "reflected-wings".
std::string rule_name(Scheme scheme, const SchemeRule& rule);
/// The name of the rule's boundary option, as rule_from_boundary_name reads it ("edge-only",
/// "chaikin-boundary", "count-from-input", "reflected-wings", ...).
std::string boundary_name(Scheme scheme, const SchemeRule& rule);
/// Whether the two rules are the same variant of `scheme` (the creasing method included).
bool same_rule(Scheme scheme, const SchemeRule& a, const SchemeRule& b);

/// The rule whose boundary option is named `boundary` for `scheme` (the default when empty):
/// Loop edge-only | edge-and-corner, Catmull-Clark those and midpoint-average, Doo-Sabin
/// chaikin-boundary | drop-border-faces, sqrt3 count-from-input | restart-each-level, the
/// Butterflies reflected-wings | opposite-vertex-wings, bilinear and midpoint linear.
/// @throws InputError for a name the scheme does not have.
SchemeRule rule_from_boundary_name(Scheme scheme, std::string_view boundary);

/// One refinement asked of an implementation.
struct RefineRequest {
    Scheme scheme = Scheme::Loop;
    SchemeRule rule;
    int levels = 1;
    /// Refine the input's face-varying channels (texture coordinates) under this rule, on
    /// every level returned. An implementation that cannot (SchemeSupport::face_varying false,
    /// or a mesh it refines without them) returns positions only, and the comparison says the
    /// values were not compared; unset, no implementation refines them.
    std::optional<FaceVaryingRule> face_varying = std::nullopt;
};

}  // namespace crossdiv::verification
