#include "crossdiv/verification/comparisons/bfr_comparison.h"

#include <algorithm>
#include <array>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/limit.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {

BfrComparison compare_bfr_limit(const PolyMesh& input, const std::string& name, const std::string& scheme) {
    BfrComparison out;
    out.input = name;
    out.scheme = scheme;
    const std::vector<const Implementation*> refs = references_with(&Capabilities::limit_surface);
    if (refs.empty()) {
        out.error = "built without OpenSubdiv";
        return out;
    }
    const Implementation& bfr_ref = *refs.front();
    const bool loop = scheme == "loop";
    if (!loop && scheme != "catmull-clark") throw InputError("Bfr has loop and catmull-clark, not '" + scheme + "'");
    try {
        // Level 1 and the exact limit of its vertices (edge-only boundary, Loop's weights).
        PolyMesh level;
        LimitResult limit;
        if (loop) {
            const LoopOptions o{LoopWeights::Loop, LoopBoundary::EdgeOnly};
            const TriMesh t = loop_subdivide(to_tri_mesh(input, "Loop subdivision"), o, 1);
            limit = loop_limit(t, o);
            level = to_poly_mesh(t);
        } else {
            const CatmullClarkOptions o{CatmullClarkBoundary::EdgeOnly};
            level = catmull_clark_subdivide(input, o, 1);
            limit = catmull_clark_limit(level, o);
        }
        const double diagonal = bounding_box_diagonal(input.positions);

        // The dyadic points of face f and the level-1 vertex at each (see loop.h and
        // catmull_clark.h for the refined face order).
        std::vector<std::array<double, 2>> uv;
        std::vector<int> at;
        for (int f = 0; f < input.num_faces(); ++f) {
            uv.clear();
            at.clear();
            if (loop) {
                const int* centre = level.face(4 * f + 3);  // (m0, m1, m2), mj on edge (vj, vj+1)
                const int* corner = input.face(f);
                uv = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
                at = {corner[0], corner[1], corner[2], centre[0], centre[1], centre[2]};
            } else {
                if (input.face_size(f) != 4) {
                    ++out.skipped_faces;
                    continue;
                }
                const int c = input.face_start[f];  // child quad of corner k: (v_k, E_k, F, E_k-1)
                const int* q0 = level.face(c);
                const int* q2 = level.face(c + 2);
                uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}, {1, 0.5}, {0.5, 1}, {0, 0.5}, {0.5, 0.5}};
                at = {q0[0], level.face(c + 1)[0], q2[0], level.face(c + 3)[0], q0[1], q2[3], q2[1], q0[3], q0[2]};
            }
            const adapters::LimitEvaluation bfr =
                bfr_ref.limit_surface(input, loop ? Scheme::Loop : Scheme::CatmullClark, f, uv);
            const int corners = loop ? 3 : 4;
            (bfr.regular ? out.regular_faces : out.irregular_faces) += 1;
            for (size_t k = 0; k < uv.size(); ++k) {
                const double d = (bfr.samples[k].position - limit.position[at[k]]).norm() / diagonal;
                double& slot = bfr.regular ? out.max_regular
                               : static_cast<int>(k) < corners ? out.max_irregular_corner
                                                                : out.max_irregular_inner;
                slot = std::max(slot, d);
            }
        }
    } catch (const InputError& e) {
        out.error = e.what();
    } catch (const adapters::Rejected& e) {
        out.error = std::string("Bfr refused: ") + e.what();
    }
    return out;
}

nlohmann::json to_json(const BfrComparison& c) {
    return {{"input", c.input},
            {"scheme", c.scheme},
            {"error", c.error},
            {"regular_faces", c.regular_faces},
            {"irregular_faces", c.irregular_faces},
            {"skipped_faces", c.skipped_faces},
            {"max_regular", c.max_regular},
            {"max_irregular_corner", c.max_irregular_corner},
            {"max_irregular_inner", c.max_irregular_inner}};
}

}  // namespace crossdiv::verification
