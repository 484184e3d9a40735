#pragma once
// The refinement of whatever a mesh reader accepts: Loop (triangle meshes) and Catmull-Clark
// (any polygon mesh), two levels, and the checks, on meshes small enough that one input
// costs milliseconds (the fuzzer's throughput is its coverage).

#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "fuzz_input.h"

namespace crossdiv::fuzz {

/// At most this many corners are refined (two levels multiply them by 16).
inline constexpr size_t kMaxRefinedCorners = 4096;

inline void refine_what_parses(const PolyMesh& mesh) {
    (void)check_mesh(mesh);
    if (mesh.face_vertices.size() > kMaxRefinedCorners) return;
    refuse_or_answer([&] { (void)catmull_clark_subdivide(mesh, {CatmullClarkBoundary::EdgeAndCorner}, 2); });
    refuse_or_answer([&] { (void)loop_subdivide(mesh, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2); });
}

}  // namespace crossdiv::fuzz
