#pragma once
// One level of a face-varying channel under Hbr's rules (OpenSubdiv 2's and RenderMan's),
// for Loop and Catmull-Clark: called by refine_face_varying when FaceVaryingOptions::rules is
// CreaseRules::Hbr. Internal to core.

#include "crossdiv/mesh/face_varying.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/face_varying_refinement.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv::face_varying_legacy_rules {

/// `channel` refined one level by Hbr's rules (HbrCatmarkSubdivision and
/// HbrLoopSubdivision::transferFVarToChild), `scheme` Loop or Catmull-Clark and `options.rule`
/// any but `all` (linear under either rules) and `corners-only` (refused by the caller).
/// `carried`: what the level before left (null at the first level); `next`, when given,
/// receives what this one leaves for the next.
FaceVaryingChannel refine(const PolyMesh& parent, const PolyConnectivity& conn, const RefinementStep& step,
                          const FaceVaryingChannel& channel, FaceVaryingScheme scheme, const FaceVaryingOptions& options,
                          const FaceVaryingSemiSharp* carried, FaceVaryingSemiSharp* next);

}  // namespace crossdiv::face_varying_legacy_rules
