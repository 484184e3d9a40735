#include "crossdiv/verification/studies/studies.h"

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/comparisons/crease_comparison.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {

using nlohmann::json;

CheckReport creases_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
    for (const CreaseComparison& c : compare_crease_catalog()) {
        rows.push_back(to_json(c));
        runs.push_back(decided_check("opensubdiv", std::string("creases ") + to_string(c.scheme) + " " + c.method + " L" + std::to_string(c.levels),
                               c.input, c.max_rel, tolerances::kAgreementRelative, "rel", c.explanation,
                               {c.verdict, c.divergence_class}));
    }
    // The seed's question, as a figure: the cube refined three times, smooth, with its top
    // edges infinitely sharp, and with every edge of sharpness 2.
    json figure = json::array();
    for (auto [key, variant] : {std::pair{"no tags", datasets::CreaseCubeVariant::Smooth},
                                {"top edges infinitely sharp", datasets::CreaseCubeVariant::SharpTop},
                                {"all edges sharpness 2", datasets::CreaseCubeVariant::SemiSharp}}) {
        json m = mesh_json(catmull_clark_subdivide(datasets::crease_cube(variant), {CatmullClarkBoundary::EdgeOnly}, 3));
        m["name"] = key;
        figure.push_back(m);
    }
    out.tables = {{"creases", rows}, {"crease_cube", figure}};
    return out;
}

}  // namespace crossdiv::verification
