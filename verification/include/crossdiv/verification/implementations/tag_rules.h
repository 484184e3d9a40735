#pragma once
/// @file
/// The rules a shape file's tags ask for (`t interpolateboundary`, `t smoothtriangles`),
/// resolved against a command's flags: an explicit flag wins, and says so when the file
/// asked for something else.

#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/nonmanifold_rule.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

/// What a run uses after the tags are read.
struct TagRules {
    std::string boundary;           ///< the boundary rule's name; "" for the scheme's default
    bool smooth_triangles = false;  ///< Catmull-Clark: OpenSubdiv's TRI_SUB_SMOOTH edge weights
    std::vector<std::string> notes; ///< a flag that overrode a tag; a tag that does not apply
};

/// Resolves the boundary rule and the triangle rule for `scheme`: `boundary_flag` when
/// given, else the file's interpolateboundary tag (Loop and Catmull-Clark, the schemes whose
/// rules are OpenSubdiv's), else the default. The rule `none` (from the flag or the tag) is
/// Sdc's VTX_BOUNDARY_NONE as Far applies it: the edge-only rule, with the faces at the
/// boundary made holes in `mesh` (tag_boundary_faces_as_holes). smoothtriangles applies to
/// Catmull-Clark only; elsewhere it is noted and left, as OpenSubdiv's own reader does.
/// @throws InputError for an interpolateboundary tag on a scheme without OpenSubdiv's
///         boundary rules, when no flag names the rule; for `none` on such a scheme; and
///         for a mesh `none` cannot tag (build_poly_connectivity's errors).
TagRules resolve_tag_rules(Scheme scheme, const std::string& boundary_flag, PolyMesh& mesh);

/// The crease decay a run uses: `flag` ("uniform" or "chaikin") when given, else the input's
/// `t creasemethod` tag, else uniform (OpenSubdiv's default).
/// @throws InputError for another flag.
CreaseMethod crease_method(const std::string& flag, const PolyMesh& mesh);

/// The face-varying rule a run refines `mesh`'s channels with: `flag` (a FaceVaryingRule name)
/// when given, else the file's `t facevaryinginterpolateboundary` tag, else OpenSubdiv's
/// default (`all`); nothing for a mesh without channels (a flag is then noted in `notes`), or
/// for a scheme without face-varying rules (Loop, Catmull-Clark and bilinear have them; the
/// channels are then noted as dropped).
/// @throws InputError for an unknown rule name.
std::optional<FaceVaryingRule> face_varying_rule(Scheme scheme, const std::string& flag, const PolyMesh& mesh,
                                                 std::vector<std::string>& notes);

/// What a command's flags or a manifest case's keys say of a polygon scheme's rule; an empty
/// name leaves it to the file's tags, then to the default.
struct RuleFlags {
    std::string boundary;  ///< rule_from_boundary_name's names
    std::string creasing;  ///< crease_method's flag
    NonManifoldRule nonmanifold = NonManifoldRule::OpenSubdiv;
    std::string face_varying = {};  ///< face_varying_rule's flag (a FaceVaryingRule name)
    /// Catmull-Clark's edge weights at triangles: "catmark" (the scheme's own), "smooth"
    /// (OpenSubdiv's TRI_SUB_SMOOTH), or "" for the file's `t smoothtriangles` tag, else catmark.
    std::string triangles = {};
};

/// The rule a run uses on `mesh`: the flags, the file's tags where no flag is given
/// (resolve_tag_rules; `none` tags the boundary faces of `mesh` as holes), and the notes to
/// show the user.
/// @throws InputError as resolve_tag_rules, rule_from_boundary_name and crease_method; for a
///         `triangles` flag on a scheme other than Catmull-Clark, or one not catmark or smooth.
SchemeRule rule_with_tags(Scheme scheme, const RuleFlags& flags, PolyMesh& mesh, std::vector<std::string>& notes);

}  // namespace crossdiv::verification
