#pragma once
/// @file
/// A subdivision surface fitted to a target mesh (core's limit_fitting.h) and measured the way
/// the command and the study report it: the distance energy and one-sided distances of each
/// iteration from core, the two-sided Hausdorff distance of each iteration's limit surface from
/// a reference (CGAL), and the coarse control mesh made by a reference's simplification.

#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/limit_fitting.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {

/// The limit sampling of `control` under `scheme`'s default rule (Loop's weights, edge-only
/// boundary; Catmull-Clark edge-only), `levels` levels deep.
/// @throws InputError for a scheme other than Loop and Catmull-Clark, or as the core sampling.
LimitSampling fitting_sampling(Scheme scheme, const TriMesh& control, int levels);

/// The largest distance of recovered control points from the true ones, relative to their
/// bounding-box diagonal, when the samples are exactly the true limit surface's.
double recovery_error(Scheme scheme, const TriMesh& control, int levels);

/// Euler characteristic and boundary loops, what "the same topology type" compares.
struct TopologyType {
    int euler = 0, boundary_loops = 0;
    friend bool operator==(const TopologyType&, const TopologyType&) = default;
};
TopologyType topology_type(const TriMesh& mesh);

/// A control mesh for `target`: the reference's edge collapse down to fewer than `edges` edges.
/// @throws InputError when the result has another topology type than the target (naming both).
TriMesh coarse_control(const TriMesh& target, int edges, const Implementation& simplifier);

struct FittingRun {
    FittingResult result;
    /// Per step: the two-sided Hausdorff distance between the step's sampled limit surface and
    /// the target, by `hausdorff_by`; empty without a reference, or when it refused (`hausdorff_error`).
    std::vector<double> hausdorff;
    std::string hausdorff_by, hausdorff_error;
    LimitSampling sampling;  ///< the control mesh's limit surface, as fitted

    /// The last step's sampled limit surface.
    TriMesh fitted_surface() const { return sampling.surface(result.steps.back().control); }
};

/// The steps whose distance energy exceeds the previous one's beyond rounding
/// (tolerances::kFittingEnergyRounding and kFittingDistanceUlps); the method promises none.
int energy_increases(const FittingResult& result, const TriMesh& target, int samples);

/// Fits `control`'s limit surface to `target` from the control mesh's own positions.
/// @throws InputError as fit_limit_surface, or when the topology types differ.
FittingRun run_fitting(Scheme scheme, const TriMesh& control, const TriMesh& target, int levels, int iterations,
                       const Implementation* hausdorff_reference);

}  // namespace crossdiv::verification
