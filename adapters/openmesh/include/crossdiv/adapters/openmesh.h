#pragma once
/// @file
/// OpenMesh 9 adapter: Subdivider::Uniform::LoopT on the double-precision OpenMesh::TriMesh;
/// vertex normals and the local operations flip and split, as references for our half-edge mesh.

#include <memory>
#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::adapters::openmesh {

/// LoopT has Loop's weights and one boundary rule, the 1-6-1 boundary vertex and midpoint
/// boundary edge (our EdgeOnly); it has no corner rule.
bool supports(const LoopOptions& options);

/// `levels` LoopT steps, one call per level so that every level can be read. LoopT keeps the
/// old vertices' handles and appends one vertex per split edge; faces are renumbered.
/// LoopT's weight table defaults to valences below 50 and is read unchecked above it, so it
/// is sized to the mesh's largest valence first (init_weights, public API).
/// @throws Rejected for options it lacks, or when OpenMesh refuses a face (complex edge or
///         vertex), naming the face.
LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels);

/// The same refinement in the library's own structures, with nothing converted back: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as loop().
size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels);

/// CatmullClarkT on the double-precision OpenMesh::PolyMesh, one call per level. Its interior
/// rule is OpenSubdiv's; its boundary vertex is the average of the vertex and its two boundary
/// edge midpoints (our CatmullClarkBoundary::MidpointAverage).
/// @throws Rejected naming the face OpenMesh refuses.
LevelTrace catmull_clark(const PolyMesh& mesh, int levels);

/// The same refinement in one call of `levels` steps, kept in OpenMesh's structures: what
/// `crossdiv bench` times. Returns the number of output faces. @throws as catmull_clark().
size_t catmull_clark_native(const PolyMesh& mesh, int levels);

/// Sqrt3T. Its generation counter (boundary refined on odd generations) is a mesh property
/// that lives for one call, so the trace is made of fresh calls of k = 1 .. levels steps when
/// `one_call` is true, and of `levels` calls of one step (boundary never refined) when false.
/// @throws Rejected naming the face OpenMesh refuses.
LevelTrace sqrt3(const TriMesh& mesh, int levels, bool one_call);

/// ModifiedButterflyT (Zorin, Schroeder, Sweldens 1996), one call per level; boundary edges by
/// the four-point rule, missing stencil points reflected. @throws Rejected as sqrt3().
LevelTrace modified_butterfly(const TriMesh& mesh, int levels);

/// "OpenMesh 9.0".
std::string version();


/// OpenMesh's two vertex normals. Both are unit vectors (zero for an isolated vertex).
enum class NormalMethod {
    /// PolyMeshT::calc_vertex_normal_correct: the sum of the cross products of consecutive
    /// edge vectors around the vertex (each twice a face's area times its normal).
    Correct,
    /// PolyMeshT::update_vertex_normals after update_face_normals: calc_vertex_normal_fast,
    /// the sum of the unit face normals.
    Fast,
};

/// One normal per input vertex, in input order (OpenMesh keeps vertex handles in add order).
/// @throws Rejected naming the face OpenMesh refuses.
std::vector<Vec3> vertex_normals(const TriMesh& mesh, NormalMethod method);

/// A triangle mesh held and edited by OpenMesh itself (TriConnectivity::flip and ::split),
/// for differential tests of our half-edge operations. Edges are named by their endpoints,
/// vertices by index; OpenMesh appends each new vertex, so indices match ours.
class EditableMesh {
public:
    /// @throws Rejected naming the face OpenMesh refuses.
    explicit EditableMesh(const TriMesh& mesh);
    ~EditableMesh();
    EditableMesh(EditableMesh&&) noexcept;
    EditableMesh& operator=(EditableMesh&&) noexcept;

    /// TriConnectivity::is_flip_ok for the edge a-b. @throws Rejected if OpenMesh has no such edge.
    bool flip_ok(int a, int b) const;
    /// TriConnectivity::flip. @throws Rejected if OpenMesh has no such edge.
    void flip(int a, int b);
    /// add_vertex(midpoint), then TriConnectivity::split; returns the new vertex's index.
    /// @throws Rejected if OpenMesh has no such edge.
    int split(int a, int b);
    /// What OpenMesh::Utils::MeshCheckerT reports, one line each (empty when it is satisfied).
    std::vector<std::string> check() const;
    /// Faces as vertex triples, in OpenMesh's face order.
    std::vector<Triangle> faces() const;
    std::vector<Vec3> positions() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace crossdiv::adapters::openmesh
