// OpenSubdiv's Hbr as an implementation: "hbr", the hierarchical boundary representation
// OpenSubdiv 3 ships beside Far and tests Far against. Catmull-Clark (both boundary rules,
// Hbr's k_New triangle rule as smooth-triangles), Loop (Loop's weights, both boundary rules)
// and bilinear, with crease, corner and hole tags and both creasing methods, and a
// face-varying channel under five of OpenSubdiv's six rules (not corners-only). Where semi-sharp
// features decay it changes rule its own way (CreaseRules::Hbr: a sharpness of exactly 1
// stays sharp one step longer than in Far), declared on every rule, so a difference there is
// measured as crease-rules; the same declaration brings Hbr's face-varying rules to core's run
// (FaceVaryingOptions::rules), so a difference in the texture coordinates is measured as
// legacy-fvar-rules. Its weights are floats (hbr.h): the float tier. It reports
// each vertex's parent.
#include "crossdiv/adapters/hbr.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

namespace hb = adapters::hbr;

/// Loop's weights under both boundary rules, with Hbr's crease rules.
std::vector<SchemeRule> loop_rules() {
    std::vector<SchemeRule> rules;
    for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
        SchemeRule r = loop_rule(LoopWeights::Loop, b);
        r.loop.crease_rules = CreaseRules::Hbr;
        rules.push_back(r);
    }
    return rules;
}

/// Both of OpenSubdiv's boundary rules, with and without smooth triangles (Hbr's k_New), with
/// Hbr's crease rules.
std::vector<SchemeRule> catmull_clark_rules() {
    std::vector<SchemeRule> rules;
    for (bool smooth : {false, true})
        for (CatmullClarkBoundary b : {CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner}) {
            SchemeRule r = catmull_clark_rule(b, smooth);
            r.catmull_clark.crease_rules = CreaseRules::Hbr;
            rules.push_back(r);
        }
    return rules;
}

class Hbr final : public Implementation {
public:
    Hbr()
        : Implementation("hbr", hb::version(), ImplementationKind::Library,
                         {.schemes = {with_face_varying(supports(Scheme::Loop, loop_rules(), true)),
                                      with_face_varying(with_hierarchical_edits(supports(Scheme::CatmullClark, catmull_clark_rules(), true))),
                                      with_face_varying(supports(Scheme::Bilinear, {SchemeRule{}}))},
                          .precision = Precision::Float}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override { return levels(mesh, r, nullptr); }

    /// Hbr's own provenance: each refined vertex's parent face, edge or vertex.
    Refinement refine_with_provenance(const PolyMesh& mesh, const RefineRequest& r) const override {
        Refinement out;
        out.levels = levels(mesh, r, &out.births);
        return out;
    }

private:
    adapters::LevelTrace levels(const PolyMesh& mesh, const RefineRequest& r, adapters::LevelBirths* births) const {
        check_refinable(r.scheme);
        const SchemeRule rule = closest_rule(r.scheme, r.rule);
        if (r.face_varying && !mesh.face_varying.empty()) {  // HbrFVarData, under Hbr's method for the rule
            if (r.scheme == Scheme::CatmullClark)
                return hb::catmull_clark_face_varying(mesh, rule.catmull_clark, *r.face_varying, r.levels, births);
            if (r.scheme == Scheme::Bilinear) return hb::bilinear_face_varying(mesh, *r.face_varying, r.levels, births);
            return hb::loop_face_varying(mesh, rule.loop, *r.face_varying, r.levels, births);
        }
        if (r.scheme == Scheme::CatmullClark) return hb::catmull_clark(mesh, rule.catmull_clark, r.levels, births);
        if (r.scheme == Scheme::Bilinear) return hb::bilinear(mesh, r.levels, births);
        return hb::loop(mesh, rule.loop, r.levels, births);
    }
};

}  // namespace

std::unique_ptr<Implementation> make_hbr_implementation() { return std::make_unique<Hbr>(); }

}  // namespace crossdiv::verification::detail
