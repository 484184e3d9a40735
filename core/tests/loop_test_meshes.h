#pragma once
// The Loop tests' tiny triangle meshes, whose refined points are computed by hand, and the
// rules they are refined under.

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::test {

inline constexpr LoopOptions kLoopEdge{LoopWeights::Loop, LoopBoundary::EdgeOnly};
inline constexpr LoopOptions kLoopCorner{LoopWeights::Loop, LoopBoundary::EdgeAndCorner};
inline constexpr LoopOptions kWarrenEdge{LoopWeights::Warren, LoopBoundary::EdgeOnly};

/// Regular tetrahedron centred at the origin: the vertices sum to zero.
inline TriMesh tri_tetrahedron() {
    TriMesh m;
    m.positions = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    return m;
}

/// Octahedron: +-x, +-y, +-z; every vertex has valence 4.
inline TriMesh tri_octahedron() {
    TriMesh m;
    m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

}  // namespace crossdiv::test
