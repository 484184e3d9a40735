#include "crossdiv/verification/studies/studies.h"

#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/comparisons/bfr_comparison.h"
#include "crossdiv/verification/comparisons/limit_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"

namespace crossdiv::verification {

using nlohmann::json;

CheckReport limit_positions_study() {
    CheckReport out;
    std::vector<Check>& runs = out.checks;
    json rows = json::array();
    const auto add = [&](const LimitComparison& c) {
        rows.push_back(to_json(c));
        const std::string what = std::string(to_string(c.scheme)) + " " + c.rule + " L" + std::to_string(c.levels);
        if (c.verdict != Verdict::Agree && c.verdict != Verdict::Diverge) {
            runs.push_back(decided_check("opensubdiv", "limit position " + what, c.input, NAN, tolerances::kLimitAgreementRelative,
                                   "rel", c.explanation, {c.verdict, DivergenceClass::None}));
            return;
        }
        runs.push_back(measured_check("opensubdiv", "limit position " + what, c.input, c.max_rel_position,
                             tolerances::kLimitAgreementRelative, "rel", c.explanation));
        if (c.normals_compared > 0)
            runs.push_back(measured_check("opensubdiv", "limit normal " + what, c.input, c.max_normal_angle,
                                 tolerances::kLimitNormalRad, "rad",
                                 std::to_string(c.normals_compared) + " interior vertices"));
    };
    for (const auto& b : datasets::bundled_meshes())
        for (const char* boundary : {"edge-only", "edge-and-corner"})
            for (int levels : {0, 2})
                add(compare_limit(b.mesh, "bundled:" + b.name, {Scheme::Loop, rule_from_boundary_name(Scheme::Loop, boundary), levels}));
    for (const auto& b : datasets::catalog_meshes())
        for (const char* boundary : {"edge-only", "edge-and-corner"})
            for (int levels : {1, 3})  // level 0 of a mesh with non-quads has no limit mask
                add(compare_limit(b.mesh, "bundled:" + b.name,
                                  {Scheme::CatmullClark, rule_from_boundary_name(Scheme::CatmullClark, boundary), levels}));
    // Bfr at (u, v): exact on regular faces, measured on irregular ones.
    json bfr_rows = json::array();
    for (const auto& b : datasets::catalog_meshes())
        for (const std::string scheme : {"loop", "catmull-clark"}) {
            if (scheme == "loop" && !b.mesh.all_triangles()) continue;
            const BfrComparison c = compare_bfr_limit(b.mesh, "bundled:" + b.name, scheme);
            bfr_rows.push_back(to_json(c));
            if (!c.error.empty()) {
                runs.push_back(decided_check("opensubdiv-bfr", "bfr " + scheme, c.input, NAN, tolerances::kBfrRegularRelative, "rel",
                                       c.error, {Verdict::RefRejected, DivergenceClass::None}));
                continue;
            }
            if (c.regular_faces > 0)
                runs.push_back(measured_check("opensubdiv-bfr", "bfr " + scheme + " regular faces", c.input, c.max_regular,
                                     tolerances::kBfrRegularRelative, "rel",
                                     std::to_string(c.regular_faces) + " regular faces, dyadic points of level 1"));
        }
    out.tables = {{"limit", rows}, {"bfr", bfr_rows}};
    return out;
}

}  // namespace crossdiv::verification
