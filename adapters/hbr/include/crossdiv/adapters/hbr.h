#pragma once
/// @file
/// OpenSubdiv's Hbr adapter: the hierarchical boundary representation that OpenSubdiv 3 still
/// ships (deprecated) and that its own regression tests compare Far against. An independent
/// implementation of the same rules: Catmull-Clark, Loop and bilinear with crease and corner
/// sharpness, both creasing methods, holes, and the edge-only and edge-and-corner boundaries.
/// One translation unit includes Hbr's headers (hbr_subdivision.cpp).
///
/// Hbr computes its weights in single precision (a float 1/n^2, 3/(8n), 0.75f ...) while this
/// adapter accumulates positions in double: results agree with Far's double refinement to
/// about 1e-7 of the mesh's size, the float tier.
///
/// Each level is read from Hbr's faces: level k+1 is the children of level k's faces, face
/// by face, in child order; vertices numbered in order of first use there, so the numbering is
/// Hbr's own, and every refined vertex's parent (face, edge or vertex) is reported.

#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/face_varying_rule.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::hbr {

/// `levels` uniform Catmull-Clark levels (HbrCatmarkSubdivision) of a polygon mesh with its
/// crease, corner and hole tags. smooth_triangles is Hbr's k_New triangle rule; crease_rules
/// must be CreaseRules::Hbr, the only ones Hbr has (crease_tags.h).
/// @throws Rejected for the midpoint-average boundary, and for a mesh Hbr cannot hold: an
///         edge with more than two faces, an edge used twice in one direction (a flipped
///         face), a face naming a vertex twice, a vertex without faces.
LevelTrace catmull_clark(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels,
                         LevelBirths* births = nullptr);

/// `levels` uniform Loop levels (HbrLoopSubdivision), likewise.
/// @throws Rejected as catmull_clark(), for Warren's weights, for crease rules other than Hbr's,
///         and for a face that is not a triangle.
LevelTrace loop(const PolyMesh& mesh, const LoopOptions& options, int levels, LevelBirths* births = nullptr);

/// `levels` uniform bilinear levels (HbrBilinearSubdivision). @throws Rejected as catmull_clark(),
/// and for crease, corner or hole tags (bilinear has no crease rules, as in OpenSubdiv's Far).
LevelTrace bilinear(const PolyMesh& mesh, int levels, LevelBirths* births = nullptr);

/// The same levels with the mesh's first face-varying channel refined by Hbr (HbrFVarData, in
/// float) under `rule`, each level's channel numbered by Hbr's data: corners share a value
/// where Hbr gives them one datum. Hbr's settings for each rule are those OpenSubdiv's
/// compatibility notes give (documentation/compatibility.rst): none is Hbr's edge-only method,
/// corners-plus1 and corners-plus2 edge-and-corner without and with propagated corners,
/// boundaries always-sharp, all Hbr's "none".
/// @throws Rejected as catmull_clark(), for corners-only (new in OpenSubdiv 3.0, not in Hbr)
///         and for a mesh without a channel.
LevelTrace catmull_clark_face_varying(const PolyMesh& mesh, const CatmullClarkOptions& options, FaceVaryingRule rule,
                                      int levels, LevelBirths* births = nullptr);
/// Loop, as catmull_clark_face_varying; @throws as loop() too.
LevelTrace loop_face_varying(const PolyMesh& mesh, const LoopOptions& options, FaceVaryingRule rule, int levels,
                             LevelBirths* births = nullptr);
/// Bilinear, as catmull_clark_face_varying; @throws as bilinear() too.
LevelTrace bilinear_face_varying(const PolyMesh& mesh, FaceVaryingRule rule, int levels, LevelBirths* births = nullptr);

/// "OpenSubdiv Hbr 3.5.0" (the version of the OpenSubdiv headers it comes with).
std::string version();

}  // namespace crossdiv::adapters::hbr
