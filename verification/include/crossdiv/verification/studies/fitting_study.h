#pragma once
/// @file
/// The fitting study (suite operation "fitting", over the catalog): subdivision surface
/// fitting (subdiv/limit_fitting.h) recovering known control points exactly on every catalog
/// mesh, and fitted by closest-point iterations to the CGAL demo meshes and the course bunny
/// from control meshes CGAL's edge collapse makes, with CGAL's Hausdorff distance per iteration.

#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// A dense mesh to fit.
struct FittingTarget {
    std::string name;
    TriMesh mesh;
};

/// The suite's targets: the CGAL demo meshes and the course bunny when installed; the bundled
/// torus when neither is.
std::vector<FittingTarget> fitting_targets();

/// Exact recovery on the catalog; then each target under Loop and Catmull-Clark from control
/// meshes of fewer than each of `edge_budgets` edges (skipped where the target has fewer than
/// twice as many), `iterations` iterations each.
CheckReport fitting_study(const std::vector<FittingTarget>& targets, const std::vector<int>& edge_budgets, int iterations);
/// fitting_study over fitting_targets(), budgets 300 and 1200 edges, 6 iterations.
CheckReport fitting_study();

/// Whether Catmull-Clark's limit stencils of `mesh` are linearly dependent by the checkerboard
/// mode: closed, every vertex of valence 3, and the vertices 2-colourable along the edges
/// (then every face has an even number of sides). Signs alternating by the colouring give face
/// points 0, edge points 0 and vertex points (n - 3) / n = 0 times the sign: the mode vanishes
/// after one level, and no sample sees it.
bool has_checkerboard_kernel(const PolyMesh& mesh);

}  // namespace crossdiv::verification
