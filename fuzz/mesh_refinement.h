#pragma once
// The refinement of whatever a mesh reader accepts: Loop (triangle meshes) and Catmull-Clark
// (any polygon mesh), two levels, and the checks, on meshes small enough that one input
// costs milliseconds (the fuzzer's throughput is its coverage).

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/catmull_clark_streaming.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "fuzz_input.h"

namespace crossdiv::fuzz {

/// At most this many corners are refined (two levels multiply them by 16).
inline constexpr size_t kMaxRefinedCorners = 4096;

/// What `refine` makes, or its refusal of bad input (`refusal` gets the message); any other
/// exception escapes, which the fuzzer reports.
template <class Refine>
auto refined_or_refusal(Refine&& refine, std::string& refusal) -> std::optional<decltype(refine())> {
    try {
        return refine();
    } catch (const InputError& e) {
        refusal = e.what();
        return std::nullopt;
    }
}

/// The streaming Loop driver refuses what the ring-walk driver refuses and otherwise makes the
/// same triangles (loop_streaming.h); a difference aborts, which the fuzzer reports.
inline void streaming_matches_ring_walk(const PolyMesh& mesh) {
    if (!mesh.all_triangles()) return;
    const TriMesh tri = to_tri_mesh(mesh, "fuzz");
    const LoopOptions o{LoopWeights::Loop, LoopBoundary::EdgeAndCorner};
    std::string refusal;
    const std::optional<TriMesh> ring = refined_or_refusal([&] { return loop_subdivide(tri, o, 2); }, refusal);
    const std::optional<TriMesh> stream = refined_or_refusal([&] { return loop_subdivide_streaming(tri, o, 2); }, refusal);
    // Coordinates near the limit of double may overflow in one summation order and not in the
    // other: a refusal for a non-finite result is not a difference of rules.
    if (ring.has_value() != stream.has_value() && refusal.find("not finite") != std::string::npos) return;
    if (ring.has_value() != stream.has_value() || (ring && ring->triangles != stream->triangles)) {
        std::fprintf(stderr, "streaming Loop %s where the ring walk %s\n", stream ? "refined" : "refused",
                     ring ? "refined" : "refused");
        std::abort();
    }
}

/// The streaming Catmull-Clark driver makes what the stencil driver makes, bit for bit, or
/// refuses with the same message (catmull_clark_streaming.h); a difference aborts. It is also
/// the fuzzers' Catmull-Clark refinement of every input that parses.
inline void streaming_matches_stencils(const PolyMesh& mesh) {
    const CatmullClarkOptions o{CatmullClarkBoundary::EdgeAndCorner};
    std::string stencil_refusal, stream_refusal;
    const std::optional<PolyMesh> stencils =
        refined_or_refusal([&] { return catmull_clark_subdivide(mesh, o, 2); }, stencil_refusal);
    const std::optional<PolyMesh> stream =
        refined_or_refusal([&] { return catmull_clark_subdivide_streaming(mesh, o, 2); }, stream_refusal);
    // Bits, not values: a NaN color (the positions are checked finite) is the same NaN.
    const auto same_bits = [](const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
        return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
    };
    const bool same = stencils ? stream && stream->face_vertices == stencils->face_vertices &&
                                     same_bits(stream->positions, stencils->positions) &&
                                     same_bits(stream->colors, stencils->colors)
                               : !stream && stream_refusal == stencil_refusal;
    if (!same) {
        std::fprintf(stderr, "streaming Catmull-Clark %s where the stencil driver %s\n",
                     stream ? "refined" : stream_refusal.c_str(), stencils ? "refined" : stencil_refusal.c_str());
        std::abort();
    }
}

inline void refine_what_parses(const PolyMesh& mesh) {
    (void)check_mesh(mesh);
    if (mesh.face_vertices.size() > kMaxRefinedCorners) return;
    streaming_matches_stencils(mesh);
    refuse_or_answer([&] { (void)loop_subdivide(mesh, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2); });
    streaming_matches_ring_walk(mesh);
}

}  // namespace crossdiv::fuzz
