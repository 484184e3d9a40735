#include "crossdiv/subdiv/doo_sabin.h"

#include <climits>
#include <string>

#include "crossdiv/error.h"
#include "level_loop.h"
#include "unit_circle.h"

namespace crossdiv {

namespace {

/// Above this many sides a face's corner points are stated through its Fourier sums: n
/// corner points each reading the n vertices would make O(n^2) terms.
constexpr int kFourierSides = 32;

/// The corner points of an n-gon whose vertices are v[0 .. n-1]. With t = 2 pi / n, corner i
/// is v_i / 4 + sum_k (3 + 2 cos(k t)) / (4n) v_(i+k); expanding cos((m - i) t) makes it
/// v_i / 4 + A + cos(i t) C + sin(i t) S, three auxiliary points of the face: A the sum of
/// 3 v_m / 4n, C and S those of cos(m t) v_m / 2n and sin(m t) v_m / 2n.
void add_corner_points_by_fourier_sums(StencilTable& st, const int* v, int n, std::vector<double>& cosines,
                                       std::vector<double>& sines) {
    cosines.clear();
    sines.clear();
    detail::append_unit_circle(n, cosines, sines);
    for (int m = 0; m < n; ++m) st.add_auxiliary_term(v[m], 3.0 / (4.0 * n));
    const int mean = st.end_auxiliary();
    for (int m = 0; m < n; ++m) st.add_auxiliary_term(v[m], cosines[m] / (2.0 * n));
    const int cosine = st.end_auxiliary();
    for (int m = 0; m < n; ++m) st.add_auxiliary_term(v[m], sines[m] / (2.0 * n));
    const int sine = st.end_auxiliary();
    for (int i = 0; i < n; ++i) {
        st.add(v[i], 0.25);
        st.add_auxiliary(mean, 1.0);
        st.add_auxiliary(cosine, cosines[i]);
        st.add_auxiliary(sine, sines[i]);
        st.end_row();
    }
}

/// The corner points of Catmull and Clark's weights for an n-gon with vertices v[0 .. n-1]:
/// v_i / 2 + (v_(i-1) + v_(i+1)) / 8 + the face's centroid / 4, the centroid stated once as an
/// auxiliary point.
void add_averaged_corner_points(StencilTable& st, const int* v, int n) {
    for (int m = 0; m < n; ++m) st.add_auxiliary_term(v[m], 1.0 / (4.0 * n));
    const int centroid = st.end_auxiliary();
    for (int i = 0; i < n; ++i) {
        st.add(v[i], 0.5);
        st.add(v[(i + n - 1) % n], 0.125);
        st.add(v[(i + 1) % n], 0.125);
        st.add_auxiliary(centroid, 1.0);
        st.end_row();
    }
}

}  // namespace

RefinementStep doo_sabin_step(const PolyMesh& mesh, const PolyConnectivity& conn, const DooSabinOptions& options) {
    const int nv = mesh.num_vertices(), nf = mesh.num_faces(), ne = conn.num_edges(), nc = conn.num_corners();
    const bool chaikin = options.boundary == DooSabinBoundary::ChaikinBoundary;
    if (2LL * nc + nf + ne + nv > INT_MAX)
        throw InputError("the next Doo-Sabin level would have more than 32-bit indices address; use fewer levels");
    RefinementStep step(nv);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nc) + 2 * static_cast<size_t>(ne), 4 * static_cast<size_t>(nc));

    // Corner points: corner c is refined row c. The weights depend on the face size only.
    std::vector<double> weights, cosines, sines;
    for (int f = 0; f < nf; ++f) {
        const int b = mesh.face_start[f], n = mesh.face_size(f);
        if (n > kFourierSides) {
            if (options.weights == DooSabinWeights::CatmullClark) add_averaged_corner_points(st, &conn.corner_vertex[b], n);
            else add_corner_points_by_fourier_sums(st, &conn.corner_vertex[b], n, cosines, sines);
            continue;
        }
        weights.resize(static_cast<size_t>(n));
        for (int k = 0; k < n; ++k) weights[k] = doo_sabin_weight(n, k, options.weights);
        for (int i = 0; i < n; ++i) {
            for (int k = 0; k < n; ++k) st.add(conn.corner_vertex[b + (i + k) % n], weights[k]);
            st.end_row();
        }
    }
    // Chaikin points of the boundary edges (ChaikinBoundary): near[c] is the point of boundary
    // corner c's edge nearer its own vertex; the far one is near[c] + 1.
    std::vector<int> near(chaikin ? static_cast<size_t>(nc) : 0, -1);
    if (chaikin)
        for (int e = 0; e < ne; ++e) {
            if (!conn.is_boundary_edge(e)) continue;
            const int c = conn.edge_corner[e];
            const auto& ends = conn.edge_vertices[e];
            st.add(ends[0], kChaikinNear);
            st.add(ends[1], kChaikinFar);
            near[c] = st.end_row();
            st.add(ends[0], kChaikinFar);
            st.add(ends[1], kChaikinNear);
            st.end_row();
        }

    // F-faces: the corner points in the face's order.
    step.face_vertices.resize(static_cast<size_t>(nc));
    for (int c = 0; c < nc; ++c) step.face_vertices[c] = c;
    step.face_start.assign(mesh.face_start.begin(), mesh.face_start.end());
    // E-faces. Edge a -> b of corner c in face f (f on its left): the quad runs along the
    // other side first, so it is oriented as the faces.
    for (int e = 0; e < ne; ++e) {
        const int c = conn.edge_corner[e], t = conn.twin[c];
        if (t >= 0) {
            step.add_face({conn.next[t], t, conn.next[c], c});
        } else if (chaikin) {
            step.add_face({near[c], near[c] + 1, conn.next[c], c});
        }
    }
    // V-faces: the corner points around the vertex in counter-clockwise order (the fan walk
    // is clockwise), on a boundary closed by the vertex's two nearest Chaikin points.
    std::vector<int> ring;
    for (int v = 0; v < nv; ++v) {
        const int start = conn.vertex_corner[v];
        if (start < 0) continue;
        const bool boundary = conn.is_boundary_vertex(v);
        if (boundary && !chaikin) continue;
        ring.clear();
        for (int c = start; c >= 0;) {
            ring.push_back(c);
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
        if (boundary) {
            const int out = ring.back();                // v -> after, a boundary half-edge: near[out] is v's
            const int in = conn.prev[start];            // before -> v: its far point is v's
            step.face_vertices.push_back(near[out]);
            for (auto it = ring.rbegin(); it != ring.rend(); ++it) step.face_vertices.push_back(*it);
            step.face_vertices.push_back(near[in] + 1);
        } else {
            for (auto it = ring.rbegin(); it != ring.rend(); ++it) step.face_vertices.push_back(*it);
        }
        step.face_start.push_back(static_cast<int>(step.face_vertices.size()));
    }
    return step;
}

PolyMesh doo_sabin_subdivide(const PolyMesh& mesh, const DooSabinOptions& options, int levels) {
    detail::require_no_creases(mesh, "Doo-Sabin");
    return detail::refine_levels(mesh, levels, [&](const PolyMesh& m, const PolyConnectivity& conn, int) {
        return doo_sabin_step(m, conn, options);
    });
}

}  // namespace crossdiv
