#pragma once
/// @file
/// The half-edge mesh's invariants, checked one by one, every violation reported by element:
/// what points to it and what should. The debugging aid for connectivity code: run it after
/// each local operation and the first message names the element the operation broke.

#include <string>
#include <vector>

#include "crossdiv/mesh/halfedge_mesh.h"

namespace crossdiv {

enum class HalfedgeIssueKind {
    OutOfRange,       ///< a link names an element that does not exist (checking stops there)
    TwinMismatch,     ///< h and twin(h) do not run between the same two vertices in opposite directions
    NextPrevMismatch, ///< prev(next(h)) != h or next(prev(h)) != h
    FaceCycle,        ///< a face's next-cycle is not 3 half-edges that all name the face
    DegenerateFace,   ///< a face uses a vertex twice
    BoundaryLoop,     ///< a boundary loop's next-cycle does not close over exactly its half-edges
    VertexLink,       ///< a vertex's half-edge does not leave it, or its ring misses half-edges leaving it
    EulerCharacteristic,  ///< V - E + F and the boundary loops give no non-negative integer genus
};

struct HalfedgeIssue {
    HalfedgeIssueKind kind;
    std::string message;  ///< "halfedge 17: next(prev(17)) = 22, should be 17 (prev(17) = 9)"
};

/// Every broken invariant of `mesh`, in a deterministic order (empty when the mesh is valid):
/// links in range; twin(twin(h)) = h by construction, and h, twin(h) with swapped endpoints;
/// next/prev inverse; each face a 3-cycle of half-edges naming it, with three distinct
/// vertices; each boundary loop a closed cycle of exactly the half-edges naming it; each
/// vertex's half-edge leaving it and its ring reaching every half-edge that leaves it (one
/// fan: a manifold vertex); per connected component, 2 - (V - E + F) - loops even and >= 0.
std::vector<HalfedgeIssue> check_halfedge_mesh(const HalfedgeMesh& mesh);

/// "out-of-range", "twin", ... stable names for JSON and tests.
const char* to_string(HalfedgeIssueKind kind);

}  // namespace crossdiv
