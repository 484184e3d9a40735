// The face-varying identity: texture coordinates taken from x and y refine, under the smooth
// rule, as the positions do -- for core and for each reference with face-varying rules. A
// reference that computes in float is held to the float tier of the values; one that misses the
// identity by more is compared with core value by value (refinement_comparison.h), whose class
// (Hbr's own face-varying rules, which do not keep the identity at creases: legacy-fvar-rules) is
// the check's outcome, or unexplained.
#include <algorithm>
#include <cmath>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/corner_values.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/studies/studies.h"

namespace crossdiv::verification {
namespace {

/// `mesh` with one channel whose value at each vertex is its (x, y), shared by every corner of
/// the vertex: the face-varying topology is the vertex topology.
PolyMesh with_xy_channel(const PolyMesh& mesh) {
    PolyMesh m = mesh;
    FaceVaryingChannel xy;
    xy.name = "xy";
    for (const Vec3& p : mesh.positions) xy.values.insert(xy.values.end(), {p.x(), p.y()});
    xy.corner_values = mesh.face_vertices;
    m.face_varying = {std::move(xy)};
    return m;
}

/// The largest difference, over every face corner of `m`, between its value and its vertex's
/// (x, y), relative to the values' box; NaN when `m` has no channel.
double xy_identity_error(const PolyMesh& m) {
    if (m.face_varying.empty()) return NAN;
    const FaceVaryingChannel& ch = m.face_varying.front();
    double worst = 0;
    for (size_t c = 0; c < m.face_vertices.size(); ++c) {
        const double* uv = ch.value(ch.corner_values[c]);
        const Vec3& p = m.positions[static_cast<size_t>(m.face_vertices[c])];
        worst = std::max({worst, std::abs(uv[0] - p.x()), std::abs(uv[1] - p.y())});
    }
    const double box = uv_box_diagonal(ch);
    return box > 0 ? worst / box : worst;
}

}  // namespace

CheckReport face_varying_study() {
    CheckReport out;
    std::vector<const Implementation*> impls{&core_implementation()};
    for (const Implementation* r : references_for(Scheme::CatmullClark))
        if (r->support(Scheme::CatmullClark)->face_varying) impls.push_back(r);
    std::vector<datasets::BundledMesh> meshes = datasets::catalog_meshes();
    for (datasets::BundledMesh& c : datasets::crease_meshes()) meshes.push_back(std::move(c));
    nlohmann::json rows = nlohmann::json::array();
    for (const datasets::BundledMesh& bm : meshes) {
        const PolyMesh mesh = with_xy_channel(bm.mesh);
        for (Scheme scheme : {Scheme::CatmullClark, Scheme::Loop}) {
            if (scheme == Scheme::Loop && !mesh.all_triangles()) continue;
            for (bool corners : {false, true}) {
                RefineRequest r{scheme, {}, 2, FaceVaryingRule::None};
                r.rule.loop.boundary = corners ? LoopBoundary::EdgeAndCorner : LoopBoundary::EdgeOnly;
                r.rule.catmull_clark.boundary = corners ? CatmullClarkBoundary::EdgeAndCorner : CatmullClarkBoundary::EdgeOnly;
                const std::string row = std::string(to_string(scheme)) + (corners ? " edge-and-corner" : " edge-only");
                for (const Implementation* impl : impls) {
                    double measured = NAN, tolerance = tolerances::kAgreementRelative;
                    std::string note;
                    std::optional<Outcome> decided;
                    const IsolatedTrace t = refine_isolated(*impl, mesh, r, 120, impl->kind() != ImplementationKind::Core);
                    if (t.outcome.status != RunStatus::Ok || !t.trace) {
                        note = impl->name() + " did not refine the mesh: " + t.outcome.summary();
                    } else {
                        measured = xy_identity_error(t.trace->back());
                        note = std::isnan(measured) ? impl->name() + " gave no face-varying values"
                                                    : "texture coordinates (x, y) per vertex, rule none, 2 levels: the largest "
                                                      "difference from the refined vertex's (x, y), of the UV box";
                        if (!std::isnan(measured))
                            tolerance = value_agreement_tolerance(t.trace->back(), impl->capabilities().precision == Precision::Float,
                                                                  tolerance, max_valence(mesh), 2);
                        if (impl->kind() != ImplementationKind::Core && !(measured <= tolerance)) {
                            // Missed: is it a rule of its own? Its values against core's.
                            RefinementRequest req;
                            req.scheme = scheme;
                            req.rule = r.rule;
                            req.levels = 2;
                            req.face_varying = FaceVaryingRule::None;
                            req.references = {impl->name()};
                            const RefinementComparison c = compare_refinement(mesh, bm.name, req);
                            const FaceVaryingRun* uv = !c.runs.empty() && c.runs[0].uv ? &*c.runs[0].uv : nullptr;
                            if (uv && uv->compared() && (uv->outcome.verdict == Verdict::Agree ||
                                                         uv->outcome.cls == DivergenceClass::LegacyFaceVaryingRules)) {
                                decided = uv->outcome;
                                note += "; against core's values: " + uv->explanation;
                            }
                        }
                    }
                    out.checks.push_back(decided ? decided_check(impl->name(), "fvar identity " + row, bm.name, measured,
                                                                 tolerance, "rel", note, *decided)
                                                 : measured_check(impl->name(), "fvar identity " + row, bm.name, measured,
                                                                  tolerance, "rel", note));
                    rows.push_back({{"mesh", bm.name}, {"rule", row}, {"implementation", impl->name()},
                                    {"max_rel", std::isnan(measured) ? nlohmann::json(nullptr) : nlohmann::json(measured)}});
                }
            }
        }
    }
    out.tables = {{"face_varying_identity", rows}};
    return out;
}

}  // namespace crossdiv::verification
