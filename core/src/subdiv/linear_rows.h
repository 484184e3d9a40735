#pragma once
// The stencil rows the linear schemes share (bilinear.cpp, midpoint.cpp), with the masks of
// bilinear_mask.h: every old vertex kept, every edge point its edge's midpoint.

#include <array>
#include <vector>

#include "crossdiv/subdiv/bilinear_mask.h"
#include "crossdiv/subdiv/refinement.h"

namespace crossdiv::detail {

/// One row per old vertex 0 .. nv-1: the vertex itself.
inline void add_kept_vertex_rows(StencilTable& st, int nv) {
    for (int v = 0; v < nv; ++v) {
        st.add(v, kBilinearVertexSelf);
        st.end_row();
    }
}

/// One row per edge, in the order given: the midpoint of its two ends.
inline void add_edge_midpoint_rows(StencilTable& st, const std::vector<std::array<int, 2>>& edges) {
    for (const auto& [a, b] : edges) {
        st.add(a, kBilinearEdgeEnd);
        st.add(b, kBilinearEdgeEnd);
        st.end_row();
    }
}

}  // namespace crossdiv::detail
