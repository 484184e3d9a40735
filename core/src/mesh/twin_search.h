#pragma once
// The twin search both connectivity builders share (tri_connectivity.cpp,
// poly_connectivity.cpp): for every directed edge a -> b, the corner of b that leads back to a.

#include <string>
#include <vector>

#include "crossdiv/error.h"

namespace crossdiv::detail {

/// The first corner, in corner order, whose edge is shared by more than two faces or run the
/// same way by two of them; corner -1 when there is none.
struct EdgeFault {
    int corner = -1;
    int same = 0;      ///< corners heading the same way along the edge (the corner itself among them)
    int opposite = 0;  ///< corners heading the other way
};

/// Throws the error `fault` describes (fault.corner >= 0): the corner's edge a -> b shared by more
/// than two of the mesh's `faces_word` ("triangles", "faces"), or run the same way by two;
/// `face` is the corner's face as the mesh's source describes it.
[[noreturn]] inline void throw_edge_fault(const EdgeFault& fault, int a, int b, const char* faces_word, const std::string& face) {
    const std::string edge = "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
    if (fault.same + fault.opposite > 2)
        throw NonManifoldInput(edge + " is shared by " + std::to_string(fault.same + fault.opposite) + " " + faces_word +
                               " (non-manifold edge; first seen in " + face + ")");
    throw NonManifoldInput(edge + ": two " + faces_word + " traverse it in the same direction (inconsistent orientation; one of them is " +
                           face + ")");
}

/// Fills twin[c] for every corner c (the corner of the opposite half-edge, the last in corner
/// order when there are several; -1 on a boundary) in O(corners), whatever the valences.
///
/// Vertex by vertex: each face at v has one half-edge leaving v (its corner c, to head(c))
/// and one entering it (incoming(c), from origin(incoming(c))). Tallying both by the
/// neighbour at their other end, in an array indexed by vertex and stamped with v (so never
/// cleared), finds each half-edge's twin among the half-edges entering v. Searching each
/// half-edge's twin among its head's corners instead costs O(valence) per half-edge, which
/// made a fan with one vertex of valence 100000 take 40 s.
///
/// The outgoing corners of v are out_corners[out_start[v] .. out_start[v+1]), in increasing
/// corner order.
template <class Head, class Incoming, class Origin>
EdgeFault find_twins(const std::vector<int>& out_start, const std::vector<int>& out_corners, const Head& head,
                     const Incoming& incoming, const Origin& origin, std::vector<int>& twin) {
    struct Tally {
        int stamp = -1;    ///< the vertex whose half-edges are being tallied
        int leaving = 0;   ///< its half-edges to this neighbour
        int entering = 0;  ///< its half-edges from this neighbour
        int last_entering = -1;
    };
    const int nv = static_cast<int>(out_start.size()) - 1;
    std::vector<Tally> tally(static_cast<size_t>(nv));
    EdgeFault fault;
    for (int v = 0; v < nv; ++v) {
        const int begin = out_start[v], end = out_start[v + 1];
        const auto at = [&](int u) -> Tally& {
            Tally& t = tally[static_cast<size_t>(u)];
            if (t.stamp != v) t = Tally{v, 0, 0, -1};
            return t;
        };
        for (int k = begin; k < end; ++k) ++at(head(out_corners[k])).leaving;
        for (int k = begin; k < end; ++k) {
            const int p = incoming(out_corners[k]);
            Tally& t = at(origin(p));
            ++t.entering;
            if (p > t.last_entering) t.last_entering = p;
        }
        for (int k = begin; k < end; ++k) {
            const int c = out_corners[k];
            const Tally& t = at(head(c));
            twin[static_cast<size_t>(c)] = t.entering ? t.last_entering : -1;
            const bool bad = t.leaving + t.entering > 2 || t.leaving == 2;
            if (bad && (fault.corner < 0 || c < fault.corner)) fault = {c, t.leaving, t.entering};
        }
    }
    return fault;
}

}  // namespace crossdiv::detail
