#pragma once
/// @file
/// How face-varying values (texture coordinates) are refined: OpenSubdiv's six linear
/// interpolation rules (Sdc::Options::FVarLinearInterpolation), named as OpenSubdiv names
/// them. They differ only where the face-varying topology does not match the vertex
/// topology (seams, UV boundaries, UV corners) or the mesh has a boundary: elsewhere every
/// rule refines a value with the vertex's own mask, except `all`, which is bilinear everywhere.

#include <array>
#include <optional>
#include <string_view>

#include "crossdiv/named_variant.h"

namespace crossdiv {

/// Which face-varying values are kept sharp (interpolated linearly) rather than smoothed
/// (OpenSubdiv vtr/fvarLevel.cpp, completeTopologyFromFaceValues).
enum class FaceVaryingRule {
    /// FVAR_LINEAR_NONE: smooth everywhere; a UV boundary is a smooth crease, and a value
    /// with one face is smoothed too.
    None,
    /// FVAR_LINEAR_CORNERS_ONLY: a value with one face (a UV corner) is sharp.
    CornersOnly,
    /// FVAR_LINEAR_CORNERS_PLUS1: corners, and every value of a vertex with three or more
    /// values (a junction of UV regions), and both values of a vertex whose seam ends in a
    /// sharp edge.
    CornersPlus1,
    /// FVAR_LINEAR_CORNERS_PLUS2: as CornersPlus1, and both values of a vertex with two
    /// values when one of them is a corner, and darts (a seam that ends inside the mesh).
    CornersPlus2,
    /// FVAR_LINEAR_BOUNDARIES: every value on a UV or mesh boundary is sharp, and the
    /// boundary edges are interpolated linearly; inside, values are smoothed.
    Boundaries,
    /// FVAR_LINEAR_ALL: bilinear interpolation of every value (OpenSubdiv's default).
    All,
};

inline constexpr std::array kFaceVaryingRules{FaceVaryingRule::None,         FaceVaryingRule::CornersOnly,
                                              FaceVaryingRule::CornersPlus1, FaceVaryingRule::CornersPlus2,
                                              FaceVaryingRule::Boundaries,   FaceVaryingRule::All};

/// "none", "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all".
constexpr std::string_view to_string(FaceVaryingRule r) {
    switch (r) {
        case FaceVaryingRule::None: return "none";
        case FaceVaryingRule::CornersOnly: return "corners-only";
        case FaceVaryingRule::CornersPlus1: return "corners-plus1";
        case FaceVaryingRule::CornersPlus2: return "corners-plus2";
        case FaceVaryingRule::Boundaries: return "boundaries";
        case FaceVaryingRule::All: return "all";
    }
    return "?";
}

/// The rule named `name`. @throws InputError listing the names.
inline FaceVaryingRule face_varying_rule_from_string(std::string_view name) {
    return variant_from_string<FaceVaryingRule>(name, kFaceVaryingRules, "face-varying rule");
}

/// The rule of shape-file tag `t facevaryinginterpolateboundary 1/0/0 k`, with k as
/// OpenSubdiv's regression reader maps it (regression/common/far_utils.h, GetSdcOptions):
/// 0 none, 1 corners-only, 2 corners-plus1, 3 corners-plus2, 4 boundaries, 5 all; nullopt
/// for any other k.
constexpr std::optional<FaceVaryingRule> face_varying_rule_from_tag(long k) {
    if (k < 0 || k >= static_cast<long>(kFaceVaryingRules.size())) return std::nullopt;
    return kFaceVaryingRules[static_cast<size_t>(k)];
}

/// The tag integer of `r` (the inverse of face_varying_rule_from_tag).
constexpr int face_varying_tag(FaceVaryingRule r) { return static_cast<int>(r); }

}  // namespace crossdiv
