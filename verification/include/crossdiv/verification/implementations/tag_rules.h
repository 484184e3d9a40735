#pragma once
/// @file
/// The rules a shape file's tags ask for (`t interpolateboundary`, `t smoothtriangles`),
/// resolved against a command's flags: an explicit flag wins, and says so when the file
/// asked for something else.

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"
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

}  // namespace crossdiv::verification
