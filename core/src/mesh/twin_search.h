#pragma once
// The twin search both connectivity builders share (tri_connectivity.cpp,
// poly_connectivity.cpp): for the directed edge a -> b, the corners of b that lead back to a,
// found among b's outgoing corners, so no edge map is needed.

#include <algorithm>
#include <utility>
#include <vector>

namespace crossdiv::detail {

/// What the outgoing corners of a and b say about the directed edge a -> b.
struct TwinMatch {
    int same = 0;      ///< corners of a heading to b (the edge itself among them)
    int opposite = 0;  ///< corners of b heading to a
    int twin = -1;     ///< the last of those (in corner order), -1 when there is none
};

/// Outgoing corners of each vertex in compressed-row form (those of v are
/// out_corners[out_start[v] .. out_start[v+1]), in increasing corner order) and the head of
/// each corner's outgoing edge. A vertex with few corners is scanned; one with more than
/// kScanLimit gets a copy of its corners sorted by head and is searched by bisection, so the
/// cost per edge is O(log valence) at a pole instead of O(valence), which made a fan with
/// one vertex of valence 100000 take 40 s.
template <class Head>
class TwinSearch {
public:
    /// Above this many outgoing corners a vertex is searched by bisection; below, a scan of
    /// a few contiguous ints is faster than the sorted copy's indirection.
    static constexpr int kScanLimit = 32;

    TwinSearch(const std::vector<int>& out_start, const std::vector<int>& out_corners, const Head& head)
        : out_start_(out_start), out_corners_(out_corners), head_(head) {
        const int nv = static_cast<int>(out_start.size()) - 1;
        for (int v = 0; v < nv; ++v) {
            if (out_start[v + 1] - out_start[v] <= kScanLimit) continue;
            if (sorted_at_.empty()) sorted_at_.assign(static_cast<size_t>(nv), -1);
            sorted_at_[v] = static_cast<int>(sorted_.size());
            for (int k = out_start[v]; k < out_start[v + 1]; ++k) sorted_.emplace_back(head(out_corners[k]), out_corners[k]);
            std::sort(sorted_.begin() + sorted_at_[v], sorted_.end());
        }
    }

    TwinMatch operator()(int a, int b) const {
        TwinMatch m;
        m.same = count_heading(a, b, nullptr);
        m.opposite = count_heading(b, a, &m.twin);
        return m;
    }

private:
    /// How many outgoing corners of v head to `to`; the last of them into *last.
    int count_heading(int v, int to, int* last) const {
        if (!sorted_at_.empty() && sorted_at_[v] >= 0) {
            const auto begin = sorted_.begin() + sorted_at_[v];
            const auto end = begin + (out_start_[v + 1] - out_start_[v]);
            const auto lo = std::lower_bound(begin, end, std::pair{to, -1});
            auto hi = lo;
            while (hi != end && hi->first == to) ++hi;
            if (last && hi != lo) *last = (hi - 1)->second;
            return static_cast<int>(hi - lo);
        }
        int n = 0;
        for (int k = out_start_[v]; k < out_start_[v + 1]; ++k)
            if (head_(out_corners_[k]) == to) {
                ++n;
                if (last) *last = out_corners_[k];
            }
        return n;
    }

    const std::vector<int>& out_start_;
    const std::vector<int>& out_corners_;
    const Head& head_;
    std::vector<int> sorted_at_;               ///< start of v's sorted copy, -1 when scanned; empty when none is
    std::vector<std::pair<int, int>> sorted_;  ///< (head, corner) of the vertices searched by bisection
};

}  // namespace crossdiv::detail
