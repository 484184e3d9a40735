#pragma once
/// @file
/// OpenSubdiv 3.5 (Far) adapter: uniform Loop refinement through Far::TopologyRefiner and
/// Far::PrimvarRefinerReal<double>.

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::opensubdiv {

using adapters::LimitSample;  // reference.h
using adapters::LimitEvaluation;  // reference.h
using adapters::LimitPoints;  // reference.h

/// OpenSubdiv's Loop has Loop's 1987 weights only; both boundary rules map to Sdc options
/// (EdgeOnly -> VTX_BOUNDARY_EDGE_ONLY, EdgeAndCorner -> VTX_BOUNDARY_EDGE_AND_CORNER; the
/// library default, VTX_BOUNDARY_NONE, would make boundary faces holes and is never used).
bool supports(const LoopOptions& options);

/// `levels` uniform Loop levels. Vertex positions are interpolated level by level in double
/// precision; the last level has full topology (fullTopologyInLastLevel), so its edges and
/// Limit() are available to later checks. Refined vertices: the parent level's vertices keep
/// their indices, then one per edge (nv + edge index), as the trace shows.
/// @throws Rejected for Warren weights or when Far's factory reports a topology error.
LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels, LevelBirths* births = nullptr);

/// Loop refinement of a polygon mesh of triangles with its crease and corner tags (the
/// descriptor's creaseVertexIndexPairs/cornerVertexIndices) and options.creasing
/// (CREASE_UNIFORM or CREASE_CHAIKIN). Far's factory rejects a face that is not a triangle.
/// @throws Rejected as loop(), and when a tag names an edge the mesh does not have.
LevelTrace loop(const PolyMesh& mesh, const LoopOptions& options, int levels, LevelBirths* births = nullptr);

/// The same refinement in the library's own structures, with nothing converted back: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as loop().
size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels);

/// Loop at fixed topology, OpenSubdiv's way (what `crossdiv bench` times against core's
/// ComposedStencils): the topology refined once, then each frame's positions from the base
/// vertices, either through Far's stencil table (StencilTableFactoryReal<double>, intermediate
/// levels factorized to the base vertices, StencilTableReal::UpdateValues) or through
/// PrimvarRefinerReal<double> level by level. Output: the last level's vertices in Far's order.
class LoopFrames {
public:
    /// @throws Rejected as loop().
    LoopFrames(const TriMesh& mesh, const LoopOptions& options, int levels);
    ~LoopFrames();
    LoopFrames(const LoopFrames&) = delete;
    LoopFrames& operator=(const LoopFrames&) = delete;

    int num_stencils() const;
    /// Stored weights of the stencil table, summed over its stencils.
    size_t num_stencil_terms() const;
    /// The last level through the stencil table.
    void by_stencils(const std::vector<Vec3>& base, std::vector<Vec3>& out) const;
    /// The last level through PrimvarRefiner, every level interpolated in turn.
    void by_levels(const std::vector<Vec3>& base, std::vector<Vec3>& out) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// Loop or Catmull-Clark at fixed topology on every core, OpenSubdiv's way: the topology
/// refined once into Far's float stencil table (the last level, factorized to the base
/// vertices), then each frame's positions through Osd::OmpEvaluator::EvalStencils, OpenMP over
/// the stencils. Float positions, three per vertex, as Osd's evaluators take them. Output in
/// Far's order.
class OmpStencils {
public:
    /// @throws Rejected as loop().
    OmpStencils(const TriMesh& mesh, const LoopOptions& options, int levels);
    /// @throws Rejected as catmull_clark().
    OmpStencils(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels);
    ~OmpStencils();
    OmpStencils(const OmpStencils&) = delete;
    OmpStencils& operator=(const OmpStencils&) = delete;

    int num_stencils() const;
    /// The last level from `base` (x, y, z per base vertex) on `threads` OpenMP threads.
    void evaluate(const std::vector<float>& base, std::vector<float>& out, int threads) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The Catmull-Clark limit surface of one face of a polygon mesh, evaluated by Bfr
/// (Bfr::RefinerSurfaceFactory, Surface<double>::Evaluate) at each (u, v). For a quad, u runs
/// from its corner 0 to corner 1 and v from corner 0 to corner 3. Boundary rule EDGE_ONLY.
/// @throws Rejected when Far refuses the mesh or the face has no limit surface.
LimitEvaluation catmark_limit(const PolyMesh& mesh, int face, std::span<const std::array<double, 2>> uv);

/// The Loop limit surface of one triangle, likewise (corner 0 at (0, 0), corner 1 at (1, 0),
/// corner 2 at (0, 1)). @throws Rejected as catmark_limit(), and for a non-triangle face.
LimitEvaluation loop_limit_surface(const PolyMesh& mesh, int face, std::span<const std::array<double, 2>> uv);

/// OpenSubdiv's Catmull-Clark (SCHEME_CATMARK) has our EdgeOnly and EdgeAndCorner boundary
/// rules (VTX_BOUNDARY_EDGE_ONLY, VTX_BOUNDARY_EDGE_AND_CORNER), not OpenMesh's midpoint-average.
bool supports(const CatmullClarkOptions& options);

/// `levels` uniform bilinear levels (Sdc::SCHEME_BILINEAR) of a polygon mesh, every level kept
/// in Far's order (as catmull_clark()). Bilinear is compared without tags: its crease rules
/// would change nothing and its holes no position.
/// @throws Rejected for a tagged mesh or when Far's factory reports an error.
LevelTrace bilinear(const PolyMesh& mesh, int levels, LevelBirths* births = nullptr);

/// `levels` uniform Catmull-Clark levels of a polygon mesh (any face sizes), every level kept
/// in Far's order (old vertices first, then one per face, then one per edge). Crease and
/// corner tags and options.creasing go to Far as for loop(const PolyMesh&, ...).
/// @throws Rejected for the midpoint-average rule or when Far's factory reports an error.
/// With `births`, Far's own provenance of every refined vertex (its child queries).
LevelTrace catmull_clark(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels, LevelBirths* births = nullptr);

/// The same refinement in the library's own structures (Far's topology without the last
/// level's edges, PrimvarRefinerReal<double> level by level into one buffer), nothing
/// converted back: what `crossdiv bench` times. Returns the number of output faces.
/// @throws as catmull_clark().
size_t catmull_clark_native(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels);

/// Limit positions and limit normals of every vertex of a refined level, by
/// PrimvarRefinerReal<double>::Limit (with its two tangents; the normal is their normalized
/// cross product, zero where they are parallel). `level` is that level's mesh in Far's order.
/// Loop: `levels` uniform levels (0: the input itself), then Limit() on the last one.
/// @throws Rejected for Warren weights or a topology Far refuses.
LimitPoints loop_limit(const TriMesh& mesh, const LoopOptions& options, int levels);
/// Catmull-Clark, as loop_limit. @throws Rejected for the midpoint-average rule.
LimitPoints catmull_clark_limit(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels);

/// The base faces Far makes holes under Sdc VTX_BOUNDARY_NONE (the mesh's own hole and
/// sharpness tags given too), sorted: the reference for core's reading of that rule
/// (tag_boundary_faces_as_holes). @throws Rejected when Far's factory refuses the mesh.
std::vector<int> boundary_none_holes(const PolyMesh& mesh, bool loop);

/// `levels` uniform levels with the mesh's first face-varying channel refined by
/// PrimvarRefinerReal<double>::InterpolateFaceVarying under `rule` (Sdc
/// FVarLinearInterpolation), level by level in double: every level in Far's order (positions,
/// faces, hole faces as hole tags), each with the channel in Far's value numbering
/// (GetFaceFVarValues). Tags, options and `births` as catmull_clark() and loop().
/// @throws Rejected for a mesh without a channel, options Far lacks, or a topology Far refuses.
LevelTrace catmull_clark_face_varying(const PolyMesh& mesh, const CatmullClarkOptions& options, FaceVaryingRule rule,
                                      int levels, LevelBirths* births = nullptr);
/// Loop, as catmull_clark_face_varying. @throws Rejected also for a face that is not a triangle.
LevelTrace loop_face_varying(const PolyMesh& mesh, const LoopOptions& options, FaceVaryingRule rule, int levels,
                             LevelBirths* births = nullptr);
/// The last of `levels` levels (as catmull_clark_face_varying) with its channel's values
/// replaced by their limits, PrimvarRefinerReal<double>::LimitFaceVarying: the reference for
/// core's face_varying_limit. @throws as catmull_clark_face_varying.
PolyMesh catmull_clark_face_varying_limit(const PolyMesh& mesh, const CatmullClarkOptions& options, FaceVaryingRule rule,
                                          int levels);
/// Loop, as catmull_clark_face_varying_limit.
PolyMesh loop_face_varying_limit(const PolyMesh& mesh, const LoopOptions& options, FaceVaryingRule rule, int levels);
/// Bilinear (SCHEME_BILINEAR): every rule refines linearly there.
LevelTrace bilinear_face_varying(const PolyMesh& mesh, FaceVaryingRule rule, int levels, LevelBirths* births = nullptr);

/// "OpenSubdiv 3.5.0" (from opensubdiv/version.h).
std::string version();

}  // namespace crossdiv::adapters::opensubdiv
