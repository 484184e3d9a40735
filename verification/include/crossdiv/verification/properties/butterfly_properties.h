#pragma once
/// @file
/// The properties an interpolating Butterfly scheme must have, measured on one mesh: the
/// classic scheme (Dyn, Levin, Gregory) has no reference library, so these are its checks,
/// and the modified scheme gets them too.
///   - interpolation: every vertex keeps its position at every later level (exactly);
///   - plane reproduction: a mesh whose vertices lie on a plane stays on it (the stencils
///     are affine combinations);
///   - the published stencil: an interior edge whose endpoints have valence 6 and whose four
///     wing edges are interior has exactly the weights 1/2, 1/2, 1/8, 1/8 and four -1/16.

#include <nlohmann/json.hpp>
#include <string>

#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/butterfly_mask.h"

namespace crossdiv::verification {

struct ButterflyProperties {
    std::string input;
    ButterflyVariant variant = ButterflyVariant::Classic;
    int levels = 0;
    std::string core_error;           ///< non-empty: core refused the input
    double max_interpolation_move = 0;  ///< largest move of a vertex after its level (absolute)
    double max_plane_residual = 0;      ///< relative to the diagonal
    int regular_edges = 0;              ///< edges of the input with a regular, interior stencil
    int regular_edges_published = 0;    ///< ... whose weights are exactly the published ones

    /// Whether all three hold: core refined the input, no old vertex moved, planes are
    /// reproduced within tolerances::kPlaneReproduction, every regular edge has the published
    /// stencil.
    bool hold() const {
        return core_error.empty() && max_interpolation_move == 0.0 && max_plane_residual <= tolerances::kPlaneReproduction &&
               regular_edges_published == regular_edges;
    }
};

/// Measures the three properties over `levels` levels of `variant`.
ButterflyProperties check_butterfly_properties(const PolyMesh& mesh, const std::string& name, ButterflyVariant variant,
                                               int levels);

nlohmann::json to_json(const ButterflyProperties& p);

}  // namespace crossdiv::verification
