#include "crossdiv/verification/studies/studies.h"

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/properties/butterfly_properties.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/properties/rule_oracle.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {

using nlohmann::json;

/// The Butterfly properties of both variants on the bundled meshes, and the rules no library
/// has in full (Doo-Sabin's Chaikin boundary, sqrt3's parities, the classic Butterfly's wings)
/// against the points written out from their sources. The comparisons of each scheme with its
/// references are the per-input cases of its own operation.
CheckReport schemes_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json properties = json::array();
    for (const auto& b : datasets::bundled_meshes())
        for (ButterflyVariant v : {ButterflyVariant::Classic, ButterflyVariant::Modified}) {
            const ButterflyProperties p = check_butterfly_properties(b.mesh, "bundled:" + b.name, v, 2);
            properties.push_back(to_json(p));
            const std::string who = std::string(to_string(v)) + " L2";
            const std::string input = "bundled:" + b.name;
            runs.push_back(measured_check("property", "interpolation " + who, input, p.max_interpolation_move, 0.0, "abs",
                                 "largest move of an existing vertex at a later level" +
                                     (p.core_error.empty() ? "" : "; core refused: " + p.core_error)));
            runs.push_back(measured_check("property", "plane reproduction " + who, input, p.max_plane_residual,
                                 tolerances::kPlaneReproduction, "rel", "residual of a planar copy of the mesh"));
            runs.push_back(measured_check("property", "published stencil " + who, input,
                                 p.regular_edges - p.regular_edges_published, 0.0, "edges",
                                 std::to_string(p.regular_edges_published) + " of " + std::to_string(p.regular_edges) +
                                     " regular interior edges have exactly 1/2, 1/2, 1/8, 1/8, 4 x -1/16"));
        }
    // Doo-Sabin's Chaikin boundary has no reference (CGAL drops the border faces): both rules
    // against the points written out from their sources (rule_oracle.h).
    for (DooSabinBoundary b : {DooSabinBoundary::ChaikinBoundary, DooSabinBoundary::DropBorderFaces}) {
        const RuleVerdict v = check_doo_sabin_rule(core_implementation(), {b});
        runs.push_back(oracle_check("published points", "doo-sabin rule oracle", std::string(to_string(b)), v));
    }
    // sqrt3's parities: which generations refine the boundary, against Kobbelt's rules.
    for (Sqrt3Parity parity : {Sqrt3Parity::CountFromInput, Sqrt3Parity::RestartEachLevel}) {
        const RuleVerdict v = check_sqrt3_rule(core_implementation(), {parity});
        runs.push_back(oracle_check("published points", "sqrt3 rule oracle", std::string(to_string(parity)), v));
    }
    // The classic Butterfly's wing rules: MeshLab's is the one reference, and only when the
    // manifest registers it.
    for (ButterflyWings w : kAllButterflyWings) {
        const RuleVerdict v = check_butterfly_rule(core_implementation(), w);
        runs.push_back(oracle_check("published points", "butterfly rule oracle", std::string(to_string(w)), v));
    }
    out.tables = {{"butterfly_properties", properties}};
    return out;
}

}  // namespace crossdiv::verification
