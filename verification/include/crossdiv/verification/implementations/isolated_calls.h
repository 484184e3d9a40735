#pragma once
/// @file
/// The library calls besides refinement, each in a forked child (run_isolated_value) as a
/// reference's refinement is: a library that crashes, hangs or allocates without bound on a
/// hostile mesh is a recorded outcome in the words of RunOutcome, not the end of crossdiv.
/// Core's own estimators run in this process.

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {

/// The time one such call may take: the studies' largest (curvature of a 41k-vertex sphere,
/// Hausdorff distance between two 20k-face meshes) take under a second; a user's mesh of
/// millions of faces has room too.
inline constexpr double kLibraryCallTimeoutSeconds = 300;

/// `impl.curvatures(mesh)`, isolated unless `impl` is core.
IsolatedValue<PrincipalCurvatures> curvatures_isolated(const Implementation& impl, const TriMesh& mesh,
                                                       double timeout_seconds = kLibraryCallTimeoutSeconds);

/// `impl.hausdorff_distance(a, b)`, isolated unless `impl` is core.
IsolatedValue<double> hausdorff_isolated(const Implementation& impl, const TriMesh& a, const TriMesh& b,
                                         double timeout_seconds = kLibraryCallTimeoutSeconds);

/// `impl.simplify(mesh, edges)`, isolated unless `impl` is core.
IsolatedValue<TriMesh> simplify_isolated(const Implementation& impl, const TriMesh& mesh, int edges,
                                         double timeout_seconds = kLibraryCallTimeoutSeconds);

}  // namespace crossdiv::verification
