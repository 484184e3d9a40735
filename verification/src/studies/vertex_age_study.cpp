#include "crossdiv/verification/studies/studies.h"

#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/subdiv/vertex_age.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {

using nlohmann::json;

CheckReport vertex_age_study() {
    CheckReport out;
    json rows = json::array();
    const PolyMesh input = datasets::bundled_mesh("icosahedron");
    constexpr int kLevels = 3;
    for (Scheme scheme : all_schemes()) {
        const adapters::LevelTrace levels = core_implementation().refine(input, {scheme, SchemeRule{}, kLevels});
        std::vector<size_t> counts;
        for (const PolyMesh& m : levels) counts.push_back(m.positions.size());
        const bool dual = scheme == Scheme::DooSabin;
        const std::vector<int> born = vertex_birth_levels(counts, dual);
        // The vertices each level adds, from the level before's topology (the icosahedron and
        // its refinements are closed, so E is half the face corners): Loop and the Butterflies
        // one per edge, Catmull-Clark one per edge and face, sqrt3 one per face; Doo-Sabin
        // one per face corner, every vertex new.
        std::vector<long> expected(kLevels + 1, 0), measured(kLevels + 1, 0);
        expected[0] = dual ? 0 : static_cast<long>(counts[0]);
        for (int l = 1; l <= kLevels; ++l) {
            const PolyMesh& before = levels[l - 1];
            const long corners = static_cast<long>(before.face_vertices.size()), faces = before.num_faces();
            const long edges = corners / 2;
            switch (scheme) {
                case Scheme::CatmullClark:
                case Scheme::Bilinear: expected[l] = edges + faces; break;
                case Scheme::Sqrt3: expected[l] = faces; break;
                case Scheme::DooSabin: expected[l] = l == kLevels ? corners : 0; break;
                default: expected[l] = edges;
            }
        }
        for (int b : born) ++measured[b];
        long mismatch = 0;
        for (int l = 0; l <= kLevels; ++l) mismatch += std::abs(measured[l] - expected[l]);
        const std::string who = std::string(to_string(scheme)) + " icosahedron L3";
        out.checks.push_back(count_check(who, "vertex-age counts", "topology", static_cast<double>(mismatch),
                                         "vertices born at each level vs the input's, then E, E + F, F (sqrt3) or "
                                         "every face corner (Doo-Sabin) of the level before"));
        json row = {{"scheme", to_string(scheme)}, {"input", "icosahedron"}, {"levels", kLevels},
                    {"vertex_counts", counts}, {"born", measured}, {"expected", expected}};
        if (scheme == Scheme::Butterfly || scheme == Scheme::ModifiedButterfly || scheme == Scheme::Bilinear ||
            scheme == Scheme::Midpoint) {
            // Interpolating (bilinear and midpoint too: a vertex point is the vertex): the oldest vertices
            // are where the input put them, exactly.
            double moved = 0;
            for (size_t v = 0; v < counts[0]; ++v)
                moved = std::max(moved, (levels.back().positions[v] - input.positions[v]).norm());
            out.checks.push_back(measured_check("analytic", "age-0 vertices fixed", who, moved, 0.0, "abs",
                                       "the input's vertices, age 0, at their input positions after 3 levels"));
        }
        if (scheme == Scheme::Loop || scheme == Scheme::CatmullClark) {
            row["mesh"] = mesh_json(levels.back());
            row["ages"] = born;
        }
        rows.push_back(row);
    }
    out.tables = {{"vertex_age", rows}};
    return out;
}

}  // namespace crossdiv::verification
