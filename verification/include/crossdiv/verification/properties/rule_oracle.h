#pragma once
/// @file
/// Oracles of the named rules that no reference has in full, each written out from its
/// source and applied by hand to small meshes, never read from core's masks: a rule
/// difference (weight-family, corner-rule, border-faces-dropped, ...) explains a divergence
/// only when the rule under test passes its oracle (comparisons/classification.h).
///
/// - Loop: Loop's and Warren's weights, both boundary rules (loop_rule_oracle.h).
/// - Doo-Sabin: the corner points (Doo and Sabin 1978: alpha_0 = 1/4 + 5/(4n),
///   alpha_k = (3 + 2 cos(2 pi k / n)) / (4n)) and, under chaikin-boundary, Chaikin's points
///   3/4 a + 1/4 b, 1/4 a + 3/4 b on each boundary edge (a, b): the refined level's vertices
///   are exactly those, compared as a set (one to one, by position); and its boundary edges are
///   Chaikin's polyline (each edge's two points joined, the second to the next edge's first),
///   which the set alone cannot tell from one with each edge's near and far points swapped.
/// - sqrt3: on a disc of six triangles, level 1 (generation 0) smooths the interior vertex
///   with Kobbelt's alpha_n = (4 - 2 cos(2 pi / n)) / 9, keeps the boundary and adds the
///   centroids; at level 2 the boundary is trisected by Kobbelt's ternary rule (old vertex
///   (4 p_prev + 19 p + 4 q) / 27, edge points (p_prev + 16 p + 10 q) / 27 and
///   (10 p + 16 q + q_next) / 27) when generations count from the input, and kept when they
///   restart at each level. Vertex sets compared, one to one.
/// - The classic Butterfly (Dyn, Levin, Gregory 1990): old vertices kept; on an interior
///   edge a 1/2, b 1/8, the four wings -1/16, a wing beyond the boundary across edge (x, y)
///   of a triangle with third vertex t taken as x + y - t (reflected-wings) or t
///   (opposite-vertex-wings); a boundary edge by the four-point rule 9/16, -1/16. On a disc
///   of seven triangles, whose every spoke has two wings beyond the boundary.
/// Other rules have no oracle yet (`known` false): their classes rest on the references.

#include <string>
#include <vector>

#include "crossdiv/subdiv/butterfly_mask.h"
#include "crossdiv/subdiv/doo_sabin_mask.h"
#include "crossdiv/subdiv/sqrt3_mask.h"
#include "crossdiv/verification/implementations/implementation.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// What an oracle found for one rule.
struct RuleVerdict {
    bool known = false;    ///< an oracle exists for the rule
    bool passed = false;   ///< every mesh within tolerances::kAgreementRelative of the oracle
    double worst_rel = 0;  ///< largest distance / the mesh's diagonal
    int meshes = 0;        ///< meshes refined and compared
    /// What was tried, or the first mesh that failed and how ("closed fan of valence 5:
    /// differs from the published stencils by 1.2e-3 of the diagonal").
    std::string detail;
};

/// The study check of an oracle's verdict, passed or failed as the oracle decided (never from
/// worst_rel alone: a vertex count the rule does not make has no distance, and was once recorded
/// as "agree, measured 0"). `measured` is the worst distance, infinite where no distance exists.
Check oracle_check(const std::string& reference, const std::string& name, const std::string& subject, const RuleVerdict& v);

/// One level of `impl`'s Doo-Sabin under `rule` on an open mesh of a triangle, quads and a
/// pentagon and on a closed triangular prism, against the vertex set written out above.
RuleVerdict check_doo_sabin_rule(const Implementation& impl, const DooSabinOptions& rule);

/// Two levels of `impl`'s sqrt3 under `rule` on a disc of six triangles, against the points
/// written out above.
RuleVerdict check_sqrt3_rule(const Implementation& impl, const Sqrt3Options& rule);

/// One level of `impl`'s classic Butterfly under `wings` on the disc, against the points
/// written out above.
RuleVerdict check_butterfly_rule(const Implementation& impl, ButterflyWings wings);

/// The oracle of `scheme` under `rule` applied to core's implementation (the Loop one at the
/// input's interior `valences` too); `known` false for a rule without one.
RuleVerdict check_core_rule(Scheme scheme, const SchemeRule& rule, const std::vector<int>& valences = {});

}  // namespace crossdiv::verification
