#pragma once
/// @file
/// Shrinking a disagreement to a small mesh that still shows it: the neighbourhood of the
/// worst vertex (the smallest k-ring of its coarse ancestors that still diverges), then
/// delta debugging over faces (Zeller and Hildebrandt, "Simplifying and Isolating
/// Failure-Inducing Input", IEEE TSE 2002: ddmin, removing complements) while the divergence
/// persists with the same class.

#include <string>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/comparisons/loop_comparison.h"

namespace crossdiv::verification {

struct ShrinkResult {
    LoopComparison original;      ///< the comparison on the whole input
    DivergenceClass divergence_class = DivergenceClass::None;  ///< the class that must persist
    int k = 0;                     ///< ring size of the neighbourhood (0: the whole mesh was needed)
    TriMesh neighbourhood;         ///< faces within k rings of the worst vertex's coarse ancestors
    TriMesh minimal;               ///< after delta debugging
    LoopComparison minimal_comparison;
    int tests = 0;  ///< comparisons run while shrinking
};

/// @param request exactly one reference. @throws InputError if the reference agrees with core
///        on the input (nothing to shrink), or for bad input.
ShrinkResult shrink_divergence(const TriMesh& mesh, const std::string& name, const LoopComparisonRequest& request);

/// The faces of `mesh` listed in `faces`, with unused vertices dropped (order kept).
TriMesh submesh(const TriMesh& mesh, const std::vector<int>& faces);

}  // namespace crossdiv::verification
