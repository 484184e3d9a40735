#include "crossdiv/verification/implementations/tag_rules.h"

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/hole_faces.h"

namespace crossdiv::verification {

TagRules resolve_tag_rules(Scheme scheme, const std::string& boundary_flag, PolyMesh& mesh) {
    TagRules out;
    const bool osd_rules = traits(scheme).sdc_tags;
    const std::string file = mesh.source.file.empty() ? std::string("the mesh") : mesh.source.file;
    const std::optional<BoundaryTag>& tag = mesh.creases.boundary;
    std::string asked = boundary_flag;
    if (tag) {
        const std::string tagged(to_string(*tag));
        if (!boundary_flag.empty()) {
            if (boundary_flag != tagged)
                out.notes.push_back("--boundary " + boundary_flag + " wins over " + file +
                                    "'s 't interpolateboundary' (" + tagged + ")");
        } else if (!osd_rules) {
            throw InputError(file + " asks for OpenSubdiv's boundary rule " + tagged +
                             " ('t interpolateboundary'); " + std::string(to_string(scheme)) +
                             " has its own boundary rules: name one with --boundary");
        } else {
            asked = tagged;
        }
    }
    if (asked == "none") {
        if (!osd_rules)
            throw InputError("the boundary rule 'none' (OpenSubdiv's VTX_BOUNDARY_NONE) is Loop's and Catmull-Clark's");
        tag_boundary_faces_as_holes(mesh, build_poly_connectivity(mesh));
        asked = "edge-only";
    }
    out.boundary = asked;
    if (const std::optional<bool>& t = mesh.creases.smooth_triangles) {
        if (scheme == Scheme::CatmullClark)
            out.smooth_triangles = *t;
        else if (*t)
            out.notes.push_back(file + "'s 't smoothtriangles smooth' applies to Catmull-Clark only; " +
                                std::string(to_string(scheme)) + " refines without it");
    }
    return out;
}

CreaseMethod crease_method(const std::string& flag, const PolyMesh& mesh) {
    if (flag == "uniform") return CreaseMethod::Uniform;
    if (flag == "chaikin") return CreaseMethod::Chaikin;
    if (!flag.empty()) throw InputError("crease method '" + flag + "' is not uniform or chaikin");
    return mesh.creases.method.value_or(CreaseMethod::Uniform);
}

std::optional<FaceVaryingRule> face_varying_rule(Scheme scheme, const std::string& flag, const PolyMesh& mesh,
                                                 std::vector<std::string>& notes) {
    const std::optional<FaceVaryingRule> named =
        flag.empty() ? std::nullopt : std::optional<FaceVaryingRule>(face_varying_rule_from_string(flag));
    const std::string file = mesh.source.file.empty() ? "the input" : mesh.source.file;
    if (mesh.face_varying.empty()) {
        if (named)
            notes.push_back(file + " has no texture coordinates (face-varying data); the face-varying rule asked for (" + flag +
                            ") changes nothing");
        return std::nullopt;
    }
    if (scheme != Scheme::Loop && scheme != Scheme::CatmullClark && scheme != Scheme::Bilinear) {
        notes.push_back(file + "'s texture coordinates are not refined: " + to_string(scheme) +
                        " has no face-varying rules here (loop, catmull-clark and bilinear have)");
        return std::nullopt;
    }
    if (named && mesh.creases.face_varying && *mesh.creases.face_varying != *named)
        notes.push_back("the face-varying rule asked for (" + flag + ") overrides " + file +
                        "'s facevaryinginterpolateboundary tag (" + std::string(to_string(*mesh.creases.face_varying)) + ")");
    return named ? named : mesh.creases.face_varying.value_or(FaceVaryingRule::All);
}

SchemeRule rule_with_tags(Scheme scheme, const RuleFlags& flags, PolyMesh& mesh, std::vector<std::string>& notes) {
    const TagRules tags = resolve_tag_rules(scheme, flags.boundary, mesh);
    notes.insert(notes.end(), tags.notes.begin(), tags.notes.end());
    SchemeRule rule = rule_from_boundary_name(scheme, tags.boundary);
    rule.catmull_clark.creasing = crease_method(flags.creasing, mesh);
    rule.catmull_clark.smooth_triangles = tags.smooth_triangles;
    if (!flags.triangles.empty()) {
        if (flags.triangles != "catmark" && flags.triangles != "smooth")
            throw InputError("triangle rule '" + flags.triangles + "' is not catmark or smooth");
        if (scheme != Scheme::CatmullClark)
            throw InputError("the triangle rule (catmark or smooth: OpenSubdiv's TRI_SUB_CATMARK or TRI_SUB_SMOOTH) is "
                             "Catmull-Clark's; " + std::string(to_string(scheme)) + " has none");
        const bool smooth = flags.triangles == "smooth";
        if (mesh.creases.smooth_triangles && *mesh.creases.smooth_triangles != smooth)
            notes.push_back("--triangles " + flags.triangles + " wins over " +
                            (mesh.source.file.empty() ? std::string("the mesh") : mesh.source.file) +
                            "'s 't smoothtriangles' (" + (*mesh.creases.smooth_triangles ? "smooth" : "catmark") + ")");
        rule.catmull_clark.smooth_triangles = smooth;
    }
    rule.catmull_clark.nonmanifold = flags.nonmanifold;
    return rule;
}

}  // namespace crossdiv::verification
