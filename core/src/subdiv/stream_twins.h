#pragma once
// The twin search both streaming drivers make on their input (loop_streaming.cpp,
// catmull_clark_streaming.cpp): linear in the half-edges whatever the valences.

#include <vector>

namespace crossdiv::detail {

/// Pairs the half-edges of a mesh with `nv` vertices into twins. Half-edge h has ends lesser[h]
/// < greater; key[h] = 2 * greater + (1 when h runs from the lesser end). The half-edges are
/// bucketed by their lesser end (a counting sort) and matched in each bucket by the greater end
/// (an array stamped with the bucket, never cleared). `twin` (one entry per half-edge, filled
/// with -1 by the caller) gets each pair. False when an edge has a third half-edge or two that
/// run the same way (not a manifold, consistently oriented mesh).
template <class Twins>
bool stream_twins(int nv, const std::vector<int>& lesser, const std::vector<int>& key, Twins& twin) {
    const int nh = static_cast<int>(lesser.size());
    std::vector<int> start(static_cast<size_t>(nv) + 1, 0), order(static_cast<size_t>(nh));
    for (int h = 0; h < nh; ++h) ++start[lesser[h] + 1];
    for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
    {
        std::vector<int> fill(start.begin(), start.end() - 1);
        for (int h = 0; h < nh; ++h) order[fill[lesser[h]]++] = h;
    }
    // In a bucket, the half-edges with the same greater end: one each way, or one alone.
    std::vector<int> stamp(static_cast<size_t>(nv), -1), first(static_cast<size_t>(nv));
    for (int lo = 0; lo < nv; ++lo)
        for (int k = start[lo]; k < start[lo + 1]; ++k) {
            const int h = order[k], hi = key[h] >> 1;
            if (stamp[hi] != lo) {
                stamp[hi] = lo;
                first[hi] = h;
                continue;
            }
            const int g = first[hi];
            if (g < 0 || key[g] == key[h]) return false;  // a third face, or two the same way
            twin[g] = h;
            twin[h] = g;
            first[hi] = -1;  // taken: one more half-edge on this edge is a fault
        }
    return true;
}

}  // namespace crossdiv::detail
