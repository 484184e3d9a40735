#pragma once
/// @file
/// Randomized differential testing of the half-edge operations: one seeded sequence of flips
/// and splits applied to our HalfedgeMesh and, in lockstep, to OpenMesh (TriConnectivity::flip
/// and split) and CGAL (Euler::flip_edge; Euler::split_edge + split_face). After every
/// operation each side passes its own validity check and all have the same faces on the same
/// vertex numbers. A failing sequence is shrunk by delta debugging to a minimal one.
///
/// An operation names its edge by a random selector taken modulo our current edge count, so
/// any subsequence of a sequence is again a valid sequence: that is what lets ddmin drop
/// operations freely. The edge is passed to the references by its two endpoints.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {

enum class EditKind { Flip, Split };

/// One random operation: its kind and the selector that picks the edge.
struct EditOp {
    EditKind kind;
    uint64_t selector;
};

/// An operation as applied: the edge by its endpoints (our half-edge 2e's origin, then target).
struct ResolvedEdit {
    EditKind kind;
    int a, b;
};
/// "flip 3-7", "split 2-5": the syntax of `crossdiv edit --flip 3-7 --split 2-5`.
std::string to_string(const ResolvedEdit& op);

/// Faces rotated to start at their smallest vertex (orientation kept), then sorted: two meshes
/// on the same vertex numbers have the same connectivity exactly when these are equal.
std::vector<Triangle> canonical_faces(std::vector<Triangle> faces);

/// `count` operations from a seeded std::mt19937_64; a share `flip_share` of them are flips.
std::vector<EditOp> random_edit_ops(uint64_t seed, int count, double flip_share);

/// A reference's copy of the mesh, edited in lockstep with ours.
struct EditReference {
    std::string name;
    std::unique_ptr<EditSession> session;
};

/// The references built with this binary ("openmesh", "cgal"), each holding `base`.
/// @param names which ones; unknown or unavailable names throw InputError.
std::vector<EditReference> make_edit_references(const TriMesh& base, const std::vector<std::string>& names);
/// The reference names this binary has, in a fixed order.
std::vector<std::string> available_edit_references();

/// Our flip as the harness calls it; tests substitute a deliberately broken one.
using FlipFunction = std::function<FlipRefusal(HalfedgeMesh&, EdgeId)>;
/// HalfedgeMesh::flip.
FlipFunction our_flip();
/// Our split likewise: splits the edge, appends the new vertex's position, returns it.
using SplitFunction = std::function<VertexId(HalfedgeMesh&, std::vector<Vec3>&, EdgeId)>;
/// split_at_midpoint.
SplitFunction our_split();

/// The operations under test: ours unless a test stands a double in.
struct OurEdits {
    FlipFunction flip = our_flip();
    SplitFunction split = our_split();
};

/// The first disagreement of a run.
struct EditDisagreement {
    int op_index = -1;       ///< 0-based index into the sequence
    ResolvedEdit op{};
    std::string subject;     ///< "ours" or the reference's name
    std::string kind;        ///< "invalid", "refusal", "faces", "positions", "vertex-index", "euler", "threw"
    std::string detail;      ///< the first validity message, or what differs, with elements named
};

struct EditRunResult {
    int ops_run = 0;  ///< operations applied before the run stopped (all, when it agrees)
    int flips = 0, refused_flips = 0, splits = 0;
    int vertices = 0, faces = 0;  ///< our mesh at the end
    std::optional<EditDisagreement> disagreement;
};

/// Applies `ops` to `base` (which must be a manifold, consistently oriented triangle mesh) and
/// to fresh copies in each reference named, checking after every operation; stops at the
/// first disagreement. @throws InputError when a side cannot take `base`.
EditRunResult run_edit_differential(const TriMesh& base, const std::vector<EditOp>& ops,
                                    const std::vector<std::string>& references, const OurEdits& ours = {});

/// A failing sequence shrunk to a minimal one that fails in the same way.
struct ShrunkEdits {
    std::vector<EditOp> ops;             ///< 1-minimal: dropping any one makes the failure go away
    std::vector<ResolvedEdit> resolved;  ///< the same operations by endpoints, as applied
    EditDisagreement disagreement;       ///< of the shrunk sequence
    int runs = 0;                        ///< sequences tried while shrinking
};

/// Cuts `ops` after the first disagreement, then runs ddmin while the run still disagrees
/// with the same subject and kind. @throws InputError when `ops` does not fail.
ShrunkEdits shrink_edit_sequence(const TriMesh& base, const std::vector<EditOp>& ops,
                                 const std::vector<std::string>& references, const OurEdits& ours = {});


}  // namespace crossdiv::verification
