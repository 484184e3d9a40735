#pragma once
/// @file
/// Refinement of face-varying channels (texture coordinates) under OpenSubdiv's six linear
/// interpolation rules (face_varying_rule.h), for Loop, Catmull-Clark and bilinear.
///
/// The face-varying topology of each level is read from the value indices (as OpenSubdiv's
/// Vtr::FVarLevel reads it, vtr/fvarLevel.cpp): an edge is discontinuous when its two faces
/// give one of its ends different values (a seam); a vertex *matches* when no edge at it is
/// discontinuous, no rule makes its boundary linear and no rule sharpens it as a corner. A
/// matching vertex has one value, refined with the vertex's own mask -- the scheme's stencil
/// with every vertex replaced by its value in the faces around (creases, corners and
/// boundaries included). A vertex that does not match has one value per region of faces
/// around it (a *span*), and each value is either a *corner*, kept, or a *crease*, refined
/// with the crease mask 3/4, 1/8, 1/8 along the span's two bounding edges: the rule decides
/// which (see FaceVaryingRule). Points of discontinuous edges take the midpoint of each side;
/// face points the average of the face's values. Under `all` (and for bilinear) every value
/// is refined linearly.
///
/// A crease value whose span holds a semi-sharp edge, or at a semi-sharp vertex, takes the
/// crease mask until its sharpness runs out, and at that level the crease mask blended toward
/// the corner's by the transition weight of the span's edges and the vertex (OpenSubdiv's
/// FVarRefinement::getFractionalWeight); under corners-plus1 and corners-plus2 the other value
/// of such a vertex follows it.
///
/// The classification is made afresh at every level from that level's values and sharpness,
/// which is what OpenSubdiv's propagation of the value tags amounts to (a value's span keeps
/// its faces, and so its kind, from level to level). A mesh that is not a manifold is refused
/// (build_poly_connectivity's NonManifoldInput).
///
/// Where OpenSubdiv's reading depends on the order of the faces, core's does not: at a vertex
/// whose faces alternate between two values (a UV region touching itself at a vertex only),
/// both values are corners, kept; OpenSubdiv splits one of them -- which, depends on which face
/// comes first -- into two values that `none` then smooths (measured; the harness names it
/// face-order-dependence).

#include <functional>
#include <vector>

#include "crossdiv/mesh/crease_tags.h"
#include "crossdiv/mesh/face_varying.h"
#include "crossdiv/mesh/face_varying_rule.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv {

/// The schemes whose face-varying refinement is implemented, and which child faces and
/// points each makes (the traversals' documented numbering).
enum class FaceVaryingScheme {
    Loop,          ///< loop_step: triangle f becomes 4f .. 4f + 3 = (v0 m0 m2) (v1 m1 m0) (v2 m2 m1) (m0 m1 m2)
    CatmullClark,  ///< catmull_clark_step: corner c becomes quad c = (v_c, E(c), F(f), E(prev c))
    Bilinear,      ///< bilinear_step: Catmull-Clark's faces, every value linear
};

/// What, besides the rule, decides whether a value is sharp.
struct FaceVaryingOptions {
    FaceVaryingRule rule = FaceVaryingRule::All;
    /// The geometry's boundary rule is edge-and-corner (a boundary vertex with one face is an
    /// infinitely sharp corner). Under edge-only, a rule other than `none` still makes such a
    /// value a face-varying corner (OpenSubdiv's makeSmoothCornersSharp).
    bool geometry_corners_sharp = true;
    /// How the geometry's semi-sharp creases decay: a semi-sharp value off a seam is blended
    /// toward a corner at the level where its sharpness runs out.
    CreaseMethod creasing = CreaseMethod::Uniform;
    /// Whose face-varying rules: OpenSubdiv 3's (Far: this file's), or Hbr's (OpenSubdiv 2's
    /// and RenderMan's, the rules OpenSubdiv's compatibility notes say Far corrected: an edge
    /// that is sharp at all is a face-varying boundary, and its halves stay so at every later
    /// level; a dart takes the boundary rule; every other value the smooth rule, without
    /// creases; see face_varying_legacy_rules.cpp). Under Hbr's rules the rule `corners-only`,
    /// new in OpenSubdiv 3, has no counterpart and is refused.
    CreaseRules rules = CreaseRules::OpenSubdiv;
};

/// How semi-sharp a crease value is (OpenSubdiv's ValueTag _semiSharp and _depSharp).
enum class SemiSharpTag : unsigned char {
    None,       ///< a plain crease (or no crease)
    Own,        ///< its span holds a semi-sharp edge, its vertex is semi-sharp, or it was dependent
    Dependent,  ///< corners-plus1/2: sharpened because its vertex's other value is semi-sharp
};

/// What a channel carries from a level to the next, besides its values.
///
/// Under OpenSubdiv's rules, the semi-sharp tags of its values (one SemiSharpTag per value),
/// carried as OpenSubdiv carries them (FVarRefinement::reclassifySemisharpValues): what a
/// value beside a decaying crease does at a level depends on the levels before (a dependent
/// value released by the other stays sharp while any edge at the vertex is semi-sharp), not
/// on that level's sharpness alone.
///
/// Under Hbr's rules, which vertices of the level are points of a face-varying boundary edge
/// of the level before (HbrHalfedge::CopyFVarInfiniteSharpness: the halves of such an edge
/// are face-varying boundaries too, whatever their own sharpness).
struct FaceVaryingSemiSharp {
    std::vector<unsigned char> tag;
    /// Hbr's rules, per vertex: 0 a vertex of the level before, 1 a new point, 2 the point of
    /// a face-varying boundary edge (an edge from it to a vertex of kind 0 is such a half).
    std::vector<unsigned char> vertex_origin;
};

/// One level of `channel` (on `parent`, whose connectivity is `conn`) through `step`, the
/// scheme's RefinementStep of `parent` (whose positions it refines). `semi_in`: the tags the
/// level before gave the channel's values (null at the first level, where they are read off
/// the sharpness); `semi_out`, when given, receives the refined values' tags for the next.
/// @throws InputError for a channel that does not fit the mesh.
FaceVaryingChannel refine_face_varying(const PolyMesh& parent, const PolyConnectivity& conn, const RefinementStep& step,
                                       const FaceVaryingChannel& channel, FaceVaryingScheme scheme,
                                       const FaceVaryingOptions& options, const FaceVaryingSemiSharp* semi_in = nullptr,
                                       FaceVaryingSemiSharp* semi_out = nullptr);

/// Levels 0..`levels` of a scheme (level 0: `mesh` itself), every face-varying channel
/// refined alongside the positions. `step(m, conn)` is the scheme's traversal. Hole tags are
/// carried, not applied. `semi_tags`, when given, receives the semi-sharp tags of the last
/// level's channels, one per channel (empty after no level: they are then read off the
/// sharpness), for face_varying_limit. @throws as subdivide_with_face_varying.
std::vector<PolyMesh> subdivide_levels_with_face_varying(
    const PolyMesh& mesh, FaceVaryingScheme scheme, const FaceVaryingOptions& options, int levels,
    const std::function<RefinementStep(const PolyMesh&, const PolyConnectivity&)>& step,
    std::vector<FaceVaryingSemiSharp>* semi_tags = nullptr);

/// `levels` levels of a scheme with every face-varying channel of `mesh` refined alongside
/// its positions: `step(m, conn)` is the scheme's traversal. Hole tags are carried, not
/// applied (the caller emits without_hole_faces, which keeps the channels' corners).
/// @throws InputError as build_poly_connectivity (a mesh that is not a manifold included),
///         the step, or refine_face_varying; NonFiniteResult for a level that overflows.
PolyMesh subdivide_with_face_varying(
    const PolyMesh& mesh, FaceVaryingScheme scheme, const FaceVaryingOptions& options, int levels,
    const std::function<RefinementStep(const PolyMesh&, const PolyConnectivity&)>& step);

}  // namespace crossdiv
