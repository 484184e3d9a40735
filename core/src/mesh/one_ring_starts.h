#pragma once
// The last step both connectivity builders share (tri_connectivity.cpp, poly_connectivity.cpp):
// where each vertex's one-ring walk starts, and the bowtie check that comes with it.

#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/mesh/source.h"

namespace crossdiv::detail {

/// Sets conn.vertex_corner[v] (already -1 for every vertex) to the corner whose incoming
/// half-edge is on the boundary, or to any corner of an interior vertex. The outgoing corners
/// of v are out_corners[out_start[v] .. out_start[v+1]); `incoming_on_boundary(c)` says whether
/// the half-edge entering c's vertex in c's face has no twin.
/// @throws InputError naming the vertex when its faces form more than one fan (a bowtie):
///         two boundary entries, or a walk that does not visit every corner.
template <class Connectivity, class IncomingOnBoundary>
void find_one_ring_starts(Connectivity& conn, const std::vector<int>& out_start, const std::vector<int>& out_corners,
                          const IncomingOnBoundary& incoming_on_boundary, const MeshSource& src,
                          const char* faces_word) {
    const int nv = static_cast<int>(out_start.size()) - 1;
    for (int v = 0; v < nv; ++v) {
        const int begin = out_start[v], end = out_start[v + 1];
        if (begin == end) continue;  // isolated
        int start = -1, boundary_fans = 0;
        for (int k = begin; k < end; ++k) {
            const int c = out_corners[k];
            if (incoming_on_boundary(c)) {
                ++boundary_fans;
                if (start < 0) start = c;
            }
        }
        if (start < 0) start = out_corners[begin];
        int visited = 0;
        for (int c = start; c >= 0; c = conn.next_around_vertex(c)) {
            ++visited;
            if (conn.next_around_vertex(c) == start) break;
        }
        if (boundary_fans > 1 || visited != end - begin)
            throw NonManifoldInput(src.describe_vertex(v) + " is non-manifold: its " + std::to_string(end - begin) + " " +
                             faces_word + " form more than one fan (bowtie vertex)");
        conn.vertex_corner[v] = start;
    }
}

}  // namespace crossdiv::detail
