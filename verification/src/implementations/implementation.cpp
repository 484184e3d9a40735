#include "crossdiv/verification/implementations/implementation.h"

#include <algorithm>

namespace crossdiv::verification {
namespace {

/// Whether `support` has the variant of `rule` (its boundary rule and weights; the creasing
/// method is a property of the tags, honoured when `creases` is declared).
bool has_variant(Scheme scheme, const SchemeSupport& support, const SchemeRule& rule) {
    return std::any_of(support.rules.begin(), support.rules.end(),
                       [&](const SchemeRule& r) { return rule_name(scheme, r) == rule_name(scheme, rule); });
}

/// `requested` with the variant of `from` (the creasing method of `requested` kept).
SchemeRule with_variant(Scheme scheme, SchemeRule requested, const SchemeRule& from) {
    switch (scheme) {
        case Scheme::Loop:
            requested.loop.weights = from.loop.weights;
            requested.loop.boundary = from.loop.boundary;
            requested.loop.crease_rules = from.loop.crease_rules;
            break;
        case Scheme::CatmullClark:
            requested.catmull_clark.boundary = from.catmull_clark.boundary;
            requested.catmull_clark.smooth_triangles = from.catmull_clark.smooth_triangles;
            requested.catmull_clark.vertex = from.catmull_clark.vertex;
            requested.catmull_clark.crease_rules = from.catmull_clark.crease_rules;
            break;
        case Scheme::DooSabin: requested.doo_sabin = from.doo_sabin; break;
        case Scheme::Sqrt3: requested.sqrt3 = from.sqrt3; break;
        case Scheme::Butterfly:
        case Scheme::ModifiedButterfly: requested.butterfly_wings = from.butterfly_wings; break;
        case Scheme::Bilinear:
        case Scheme::Midpoint: break;  // no variant
    }
    return requested;
}

}  // namespace

const char* to_string(ImplementationKind kind) {
    switch (kind) {
        case ImplementationKind::Core: return "core";
        case ImplementationKind::Library: return "library";
        case ImplementationKind::Program: return "program";
        case ImplementationKind::Callback: return "callback";
    }
    return "unknown";
}
const char* to_string(Precision precision) { return precision == Precision::Double ? "double" : "float"; }

Implementation::Implementation(std::string name, std::string version, ImplementationKind kind, Capabilities capabilities)
    : name_(std::move(name)), version_(std::move(version)), kind_(kind), capabilities_(std::move(capabilities)) {}

const SchemeSupport* Implementation::support(Scheme scheme) const {
    for (const SchemeSupport& s : capabilities_.schemes)
        if (s.scheme == scheme) return &s;
    return nullptr;
}

SchemeRule Implementation::closest_rule(Scheme scheme, const SchemeRule& asked) const {
    const SchemeSupport* s = support(scheme);
    if (!s || s->rules.empty() || has_variant(scheme, *s, asked)) return asked;
    // Crease rules of their own (Hbr's) are the ones it applies, whatever else is asked.
    SchemeRule requested = asked;
    if (scheme == Scheme::Loop &&
        std::none_of(s->rules.begin(), s->rules.end(), [&](const SchemeRule& r) { return r.loop.crease_rules == asked.loop.crease_rules; }))
        requested.loop.crease_rules = s->rules.front().loop.crease_rules;
    if (scheme == Scheme::CatmullClark &&
        std::none_of(s->rules.begin(), s->rules.end(),
                     [&](const SchemeRule& r) { return r.catmull_clark.crease_rules == asked.catmull_clark.crease_rules; }))
        requested.catmull_clark.crease_rules = s->rules.front().catmull_clark.crease_rules;
    if (has_variant(scheme, *s, requested)) return requested;
    if (scheme == Scheme::Loop) {
        // Keep the weight family before the boundary rule: Loop's weights are what every
        // library has, the corner rule is what some lack.
        for (const auto& [weights, boundary] : {std::pair{LoopWeights::Loop, requested.loop.boundary},
                                                std::pair{requested.loop.weights, LoopBoundary::EdgeOnly},
                                                std::pair{LoopWeights::Loop, LoopBoundary::EdgeOnly}}) {
            SchemeRule candidate = requested;
            candidate.loop.weights = weights;
            candidate.loop.boundary = boundary;
            if (has_variant(scheme, *s, candidate)) return candidate;
        }
        // A family of its own and not Loop's (Open3D has Warren's only): that family, with the
        // requested boundary rule where it has it.
        for (const SchemeRule& r : s->rules) {
            SchemeRule candidate = requested;
            candidate.loop.weights = r.loop.weights;
            if (has_variant(scheme, *s, candidate)) return candidate;
        }
    }
    return with_variant(scheme, requested, s->rules.front());
}

bool Implementation::applies(Scheme scheme, const SchemeRule& rule) const {
    const SchemeSupport* s = support(scheme);
    return s && (s->rules.empty() || has_variant(scheme, *s, rule));
}

void Implementation::lacks(const std::string& what) const { throw adapters::Rejected(name_ + " has no " + what); }

void Implementation::check_refinable(Scheme scheme) const {
    if (!support(scheme)) lacks(to_string(scheme));
}

adapters::LevelTrace Implementation::refine(const PolyMesh&, const RefineRequest& request) const {
    lacks(to_string(request.scheme));
}

Refinement Implementation::refine_with_provenance(const PolyMesh& mesh, const RefineRequest& request) const {
    return {refine(mesh, request), {}};
}

PolyMesh Implementation::refine_last(const PolyMesh& mesh, const RefineRequest& request) const {
    return refine(mesh, request).back();
}

size_t Implementation::refine_native(const TriMesh& mesh, const RefineRequest& request) const {
    return refine(to_poly_mesh(mesh), request).back().num_faces();
}

size_t Implementation::refine_polygons_native(const PolyMesh& mesh, const RefineRequest& request) const {
    return refine_last(mesh, request).num_faces();
}

TriMesh Implementation::isosurface(const ScalarGrid&, const IsosurfaceOptions&, const std::string&) const {
    lacks("isosurfaces");
}

adapters::LimitPoints Implementation::limit_points(const PolyMesh&, const RefineRequest&) const { lacks("limit positions"); }

adapters::LimitEvaluation Implementation::limit_surface(const PolyMesh&, Scheme scheme, int,
                                                        std::span<const std::array<double, 2>>) const {
    lacks(std::string(to_string(scheme)) + " limit-surface evaluation");
}

std::vector<NamedNormals> Implementation::vertex_normals(const TriMesh&) const { lacks("vertex normals"); }

std::unique_ptr<EditSession> Implementation::open_edit(const TriMesh&) const { lacks("edge flips and splits"); }

adapters::SplineSamples Implementation::evaluate_spline(SplineKind, std::span<const Vec3>, std::span<const double>) const {
    lacks("spline evaluation");
}

adapters::ClosedMeshReport Implementation::closed_mesh_report(const TriMesh&) const { lacks("closed-mesh report"); }
PrincipalCurvatures Implementation::curvatures(const TriMesh&) const { lacks("curvature estimator"); }
double Implementation::hausdorff_distance(const TriMesh&, const TriMesh&) const { lacks("Hausdorff distance"); }
TriMesh Implementation::simplify(const TriMesh&, int) const { lacks("mesh simplification"); }

std::string hierarchical_edits_refusal(const Implementation& impl, Scheme scheme, const PolyMesh& mesh) {
    if (mesh.creases.edits.empty()) return "";
    const SchemeSupport* s = impl.support(scheme);
    if (s && s->hierarchical_edits) return "";
    return impl.name() + " has no hierarchical edits (" + std::to_string(mesh.creases.edits.size()) +
           " here, the first: " + describe(mesh.creases.edits.front()) + "); it would refine the mesh without them";
}

IsolatedTrace refine_isolated(const Implementation& impl, const PolyMesh& mesh, const RefineRequest& request,
                              double timeout_seconds, bool isolate, int heap_fill) {
    if (std::string refusal = hierarchical_edits_refusal(impl, request.scheme, mesh); !refusal.empty())
        return {RunOutcome{RunStatus::Rejected, std::move(refusal)}, std::nullopt};
    IsolatedTrace r = run_isolated([&] { return impl.refine(mesh, request); }, timeout_seconds,
                                   isolate && !impl.confines_itself(), heap_fill);
    if (r.outcome.status != RunStatus::Ok || !r.trace) return r;
    // A library that reads past a table (OpenMesh's sqrt3 weights beyond its largest valence)
    // can return NaN or inf: an answer that is no answer, never a distance to compare. The
    // trace stays, so that a comparison can still tell where the coordinates went wrong.
    for (size_t level = 1; level < r.trace->size(); ++level) {
        const std::vector<Vec3>& p = (*r.trace)[level].positions;
        for (size_t v = 0; v < p.size(); ++v)
            if (!p[v].allFinite()) {
                r.outcome.status = RunStatus::NonFiniteOutput;
                r.outcome.message = "vertex " + std::to_string(v) + " of level " + std::to_string(level) +
                                    " is not finite (" + std::to_string(p[v].x()) + ", " + std::to_string(p[v].y()) +
                                    ", " + std::to_string(p[v].z()) + ")";
                return r;
            }
    }
    return r;
}

}  // namespace crossdiv::verification
