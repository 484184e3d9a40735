#pragma once
/// @file
/// Whether an implementation refines by a named Loop rule as its authors published it, checked
/// by an oracle that does not read core's masks (loop_mask.h): the stencils are written out
/// here from their sources, applied by hand to small fans, and compared with what the
/// implementation makes of the same fans, matched by provenance (topology alone).
///
/// A rule difference (`weight-family`, `corner-rule`) explains a divergence only if the rule
/// the implementation under test claims is the published rule; without this check a wrong
/// weight in core would be reported as a known rule difference wherever no reference has the
/// rule (Warren's weights have none).
///
/// The stencils, at level 1 of a fan with centre c and spoke ends r_0 .. r_{n-1}:
/// - interior vertex of valence n: (1 - n beta) c + beta sum r_k, with Loop's
///   beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n (Loop 1987, sec. 3.3) or Warren's
///   beta = 3 / (8 n), 3/16 at n = 3 (Warren 1995);
/// - boundary vertex: 3/4 on itself, 1/8 on each boundary neighbour; under edge-and-corner a
///   boundary vertex of one face stays (OpenSubdiv's VTX_BOUNDARY_EDGE_AND_CORNER);
/// - interior edge: 3/8 on each end, 1/8 on each opposite vertex; boundary edge: its midpoint.
/// The Barthe-Kobbelt families have no published closed form to write out (their weights
/// are a fitted table); MeshLab refines by them and is their reference.

#include <string>
#include <vector>

#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/verification/implementations/implementation.h"
#include "crossdiv/verification/properties/rule_oracle.h"

namespace crossdiv::verification {

/// The fans of the oracle: closed-centre discs of valence 3..12 and of each of `valences`
/// (interior valences of an input, so that a rule is checked where it is used), and open fans
/// of 1..4 faces (their end spokes make the one-face corners of the edge-and-corner rule).
/// One level of `impl` under `rule` on each, against the stencils above. A refusal, an
/// exception or a result whose order cannot be derived fails, with the reason.
RuleVerdict check_loop_rule(const Implementation& impl, const LoopOptions& rule, const std::vector<int>& valences = {});

/// check_loop_rule of core's implementation, remembered per rule and valence for the process.
RuleVerdict check_core_loop_rule(const LoopOptions& rule, const std::vector<int>& valences = {});

}  // namespace crossdiv::verification
