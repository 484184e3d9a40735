// OpenSubdiv (Far, Bfr) as an implementation: Loop and Catmull-Clark with their boundary
// rules and crease tags, bilinear, limit positions (PrimvarRefiner::Limit) and Bfr's limit surface.
#include "crossdiv/adapters/opensubdiv.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

namespace osd = adapters::opensubdiv;

class OpenSubdiv final : public Implementation {
public:
    OpenSubdiv()
        : Implementation("opensubdiv", osd::version(), ImplementationKind::Library,
                         {.schemes = {with_face_varying(supports(Scheme::Loop,
                                                                 {loop_rule(LoopWeights::Loop, LoopBoundary::EdgeOnly),
                                                                  loop_rule(LoopWeights::Loop, LoopBoundary::EdgeAndCorner)},
                                                                 true)),
                                      with_face_varying(supports(Scheme::CatmullClark,
                                                                 {catmull_clark_rule(CatmullClarkBoundary::EdgeOnly),
                                                                  catmull_clark_rule(CatmullClarkBoundary::EdgeAndCorner),
                                                                  catmull_clark_rule(CatmullClarkBoundary::EdgeOnly, true),
                                                                  catmull_clark_rule(CatmullClarkBoundary::EdgeAndCorner, true)},
                                                                 true)),
                                      with_face_varying(supports(Scheme::Bilinear, {SchemeRule{}}))},
                          .limit_positions = true,
                          .limit_surface = true,
                          .defines_nonmanifold_rules = true}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        return levels(mesh, r, nullptr);
    }

    /// Far's own provenance, from its child queries.
    Refinement refine_with_provenance(const PolyMesh& mesh, const RefineRequest& r) const override {
        Refinement out;
        out.levels = levels(mesh, r, &out.births);
        return out;
    }

private:
    adapters::LevelTrace levels(const PolyMesh& mesh, const RefineRequest& r, adapters::LevelBirths* births) const {
        check_refinable(r.scheme);
        const SchemeRule rule = closest_rule(r.scheme, r.rule);
        if (r.face_varying && !mesh.face_varying.empty()) {  // PrimvarRefiner::InterpolateFaceVarying too
            if (r.scheme == Scheme::CatmullClark)
                return osd::catmull_clark_face_varying(mesh, rule.catmull_clark, *r.face_varying, r.levels, births);
            if (r.scheme == Scheme::Bilinear) return osd::bilinear_face_varying(mesh, *r.face_varying, r.levels, births);
            return osd::loop_face_varying(mesh, rule.loop, *r.face_varying, r.levels, births);
        }
        if (r.scheme == Scheme::CatmullClark) return osd::catmull_clark(mesh, rule.catmull_clark, r.levels, births);
        if (r.scheme == Scheme::Bilinear) return osd::bilinear(mesh, r.levels, births);
        // Untagged triangle meshes go through Far's triangle path, tagged ones carry their tags.
        if (!mesh.creases.empty()) return osd::loop(mesh, rule.loop, r.levels, births);
        return osd::loop(triangles_for(mesh, r.scheme), rule.loop, r.levels, births);
    }

public:
    size_t refine_native(const TriMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::Loop) return Implementation::refine_native(mesh, r);
        return osd::loop_native(mesh, closest_rule(r.scheme, r.rule).loop, r.levels);
    }

    size_t refine_polygons_native(const PolyMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::CatmullClark) return Implementation::refine_polygons_native(mesh, r);
        check_refinable(r.scheme);
        return osd::catmull_clark_native(mesh, closest_rule(r.scheme, r.rule).catmull_clark, r.levels);
    }

    adapters::LimitPoints limit_points(const PolyMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        adapters::LimitPoints out = r.scheme == Scheme::Loop
                                        ? osd::loop_limit(triangles_for(mesh, r.scheme), r.rule.loop, r.levels)
                                        : osd::catmull_clark_limit(mesh, r.rule.catmull_clark, r.levels);
        // Texture coordinates: LimitFaceVarying on the same refinement's last level (Far numbers
        // the two runs' vertices and faces alike).
        if (r.face_varying && !mesh.face_varying.empty()) {
            const PolyMesh uv = r.scheme == Scheme::Loop
                                    ? osd::loop_face_varying_limit(mesh, r.rule.loop, *r.face_varying, r.levels)
                                    : osd::catmull_clark_face_varying_limit(mesh, r.rule.catmull_clark, *r.face_varying, r.levels);
            if (uv.face_vertices != out.level.face_vertices)
                throw adapters::Rejected("Far's face-varying refinement made other faces than its vertex refinement");
            out.uv = uv.face_varying.front();
        }
        return out;
    }

    adapters::LimitEvaluation limit_surface(const PolyMesh& mesh, Scheme scheme, int face,
                                            std::span<const std::array<double, 2>> uv) const override {
        if (scheme == Scheme::Loop) return osd::loop_limit_surface(mesh, face, uv);
        if (scheme == Scheme::CatmullClark) return osd::catmark_limit(mesh, face, uv);
        return Implementation::limit_surface(mesh, scheme, face, uv);
    }
};

}  // namespace

std::unique_ptr<Implementation> make_opensubdiv_implementation() { return std::make_unique<OpenSubdiv>(); }

}  // namespace crossdiv::verification::detail
