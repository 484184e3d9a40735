#pragma once
// The refinement of whatever a mesh reader accepts: Loop (triangle meshes) and Catmull-Clark
// (any polygon mesh), two levels, and the checks, on meshes small enough that one input
// costs milliseconds (the fuzzer's throughput is its coverage).

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "fuzz_input.h"

namespace crossdiv::fuzz {

/// At most this many corners are refined (two levels multiply them by 16).
inline constexpr size_t kMaxRefinedCorners = 4096;

/// The streaming Loop driver refuses what the ring-walk driver refuses and otherwise makes the
/// same triangles (loop_streaming.h); a difference aborts, which the fuzzer reports.
inline void streaming_matches_ring_walk(const PolyMesh& mesh) {
    if (!mesh.all_triangles()) return;
    const TriMesh tri = to_tri_mesh(mesh, "fuzz");
    const LoopOptions o{LoopWeights::Loop, LoopBoundary::EdgeAndCorner};
    std::optional<TriMesh> ring, stream;
    std::string refusal;
    try {
        ring = loop_subdivide(tri, o, 2);
    } catch (const InputError& e) {
        refusal = e.what();
    }
    try {
        stream = loop_subdivide_streaming(tri, o, 2);
    } catch (const InputError& e) {
        refusal = e.what();
    }
    // Coordinates near the limit of double may overflow in one summation order and not in the
    // other: a refusal for a non-finite result is not a difference of rules.
    if (ring.has_value() != stream.has_value() && refusal.find("not finite") != std::string::npos) return;
    if (ring.has_value() != stream.has_value() || (ring && ring->triangles != stream->triangles)) {
        std::fprintf(stderr, "streaming Loop %s where the ring walk %s\n", stream ? "refined" : "refused",
                     ring ? "refined" : "refused");
        std::abort();
    }
}

inline void refine_what_parses(const PolyMesh& mesh) {
    (void)check_mesh(mesh);
    if (mesh.face_vertices.size() > kMaxRefinedCorners) return;
    refuse_or_answer([&] { (void)catmull_clark_subdivide(mesh, {CatmullClarkBoundary::EdgeAndCorner}, 2); });
    refuse_or_answer([&] { (void)loop_subdivide(mesh, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2); });
    streaming_matches_ring_walk(mesh);
}

}  // namespace crossdiv::fuzz
