#pragma once
/// @file
/// Which of OpenSubdiv's six face-varying rules (`none`, `corners-only`, `corners-plus1`,
/// `corners-plus2`, `boundaries`, `all`) an implementation under test refines its texture
/// coordinates by, measured class by class of UV vertex. The subject's values, at the corners
/// of core's last level (its vertices already renumbered into core's), are compared with core's
/// values under every rule. The rules differ only where a class of value is treated linearly or
/// smoothly, so each class of corner tells its own part:
///
///   interior   one value inside the mesh: every rule but `all` smooths it
///   boundary   one value on the mesh's boundary: `boundaries` and `all` keep it linear
///   seam       two values at a vertex: `none` smooths them, the corner rules and `all` do not
///   junction   three or more values: linear under every rule but `none`
///   corner     a value on one face: sharp under every rule but `none`
///
/// A subject that mixes (a seam made linear, a boundary smoothed) shows as no rule fitting the
/// whole mesh while each class has its fit: the classes then say what it does.

#include <optional>
#include <vector>

#include "crossdiv/mesh/face_varying_rule.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/harness/corner_values.h"

namespace crossdiv::verification {

/// One class of UV vertex at the last level.
struct UvClassFit {
    UvVertexClass cls = UvVertexClass::Interior;
    int corners = 0;  ///< corners of the class
    /// Per rule of kFaceVaryingRules, the largest distance of the subject's value from core's
    /// under it over the corners of the class, relative to the UV box (INFINITY: a corner has
    /// no value to compare, or core refused the rule).
    std::vector<double> max_rel;
    int worst_corner = -1;  ///< core's corner (index into face_vertices) farthest from the best-fitting rule
    /// The rules that fit every corner of the class, in kFaceVaryingRules order.
    std::vector<FaceVaryingRule> fitting(double tolerance) const;
};

struct FaceVaryingIdentification {
    double tolerance = 0;         ///< relative to the UV box, as the face-varying comparison's
    std::vector<UvClassFit> rows; ///< the classes present, in UvVertexClass order
    /// Per rule of kFaceVaryingRules, the largest distance over every corner.
    std::vector<double> whole;
    /// The rule that fits every corner (the requested one first, then kFaceVaryingRules order),
    /// when one does.
    std::optional<FaceVaryingRule> rule;
    /// "the none rule", or per class "interior: none, corners-only; seam: all; ..." when no
    /// rule fits the whole mesh.
    std::string summary() const;
};

/// Measures `subject` (the implementation under test's last level, in core's vertex
/// numbering, with its first channel) against `core_by_rule[r]`, core's last level under rule
/// kFaceVaryingRules[r] (nullptr where core refused it). Every core level has the same faces in
/// the same order (the face-varying rule changes no vertex or face); the subject's faces are
/// matched to them by their vertices. Nothing when the subject gave no channel or one whose
/// faces cannot be matched.
std::optional<FaceVaryingIdentification> identify_face_varying_rule(const PolyMesh& subject,
                                                                    const std::vector<const PolyMesh*>& core_by_rule,
                                                                    FaceVaryingRule requested, double tolerance);

}  // namespace crossdiv::verification
