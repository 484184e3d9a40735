#include "crossdiv/subdiv/butterfly.h"

#include <climits>
#include <string>
#include <tuple>

#include "crossdiv/error.h"
#include "level_loop.h"
#include "unit_circle.h"

namespace crossdiv {
namespace {

/// The stencil terms of one edge point, written into the row being built.
class EdgeStencil {
public:
    EdgeStencil(const PolyConnectivity& conn, const std::vector<int>& valence, ButterflyWings wings, StencilTable& st)
        : conn_(conn), valence_(valence), wings_(wings), st_(st) {}

    /// The four-point rule along the boundary polygon; c is the boundary edge's corner.
    void boundary(int c) {
        const int a0 = conn_.corner_vertex[c], a1 = conn_.head(c);
        st_.add(conn_.boundary_neighbors(a0).before, kFourPointOuter);
        st_.add(a0, kFourPointInner);
        st_.add(a1, kFourPointInner);
        st_.add(conn_.boundary_neighbors(a1).after, kFourPointOuter);
    }

    /// The eight-point stencil of the interior edge of corner c (a0 -> a1, twin t), scaled.
    void eight_point(int c, double scale = 1.0) {
        const int t = conn_.twin[c];
        const int a0 = conn_.corner_vertex[c], a1 = conn_.head(c);
        const int apex_c = conn_.corner_vertex[conn_.prev[c]], apex_t = conn_.corner_vertex[conn_.prev[t]];
        st_.add(a0, scale * kButterflyA);
        st_.add(a1, scale * kButterflyA);
        st_.add(apex_c, scale * kButterflyB);
        st_.add(apex_t, scale * kButterflyB);
        // The wing edges of both triangles, each with the endpoint opposite it and the other
        // triangle's apex.
        wing(conn_.next[c], a0, apex_t, scale);
        wing(conn_.prev[c], a1, apex_t, scale);
        wing(conn_.next[t], a1, apex_c, scale);
        wing(conn_.prev[t], a0, apex_c, scale);
    }

    /// Zorin's K-point stencil around endpoint v of the edge of corner c_out (v -> w), scaled.
    void extraordinary(int c_out, double scale) {
        const int v = conn_.corner_vertex[c_out], K = valence_[v];
        if (K > kFourierValence) {
            by_fourier_sums(c_out, scale);
            return;
        }
        std::vector<double>& s = stencil_by_valence_[K];
        if (s.empty()) s = modified_butterfly_stencil(K);
        int j = 0;
        for (int c = c_out;;) {
            st_.add(conn_.head(c), scale * s[j++]);
            c = conn_.next_around_vertex(c);
            if (c == c_out) break;
        }
        st_.add(v, scale * s[K]);
    }

private:
    /// Above this valence the K-point stencil is stated through its Fourier sums: K edges
    /// each reading K neighbours would make O(K^2) terms (146 s and 24 GB at K = 100000).
    static constexpr int kFourierValence = 32;

    /// The K-point stencil of edge i around v (its other endpoint the i-th neighbour p_i
    /// of v's ring) is sum_m s_(m-i) p_m + s_K v with s_j = (1/4 + cos(j t) + 1/2 cos(2 j t)) / K,
    /// t = 2 pi / K; expanding cos((m - i) t) = cos(m t) cos(i t) + sin(m t) sin(i t) makes it
    /// five sums over the ring, each weighted by cos or sin of i t or 2 i t: auxiliary points
    /// of the stencil table, made once per vertex.
    void by_fourier_sums(int c_out, double scale) {
        const int v = conn_.corner_vertex[c_out], K = valence_[v];
        const int sums = fourier_sums(v);
        const size_t angles = static_cast<size_t>(circle_first_[v]);
        const int i = ring_index_[c_out];
        st_.add_auxiliary(sums, scale);
        st_.add_auxiliary(sums + 1, scale * cosines_[angles + i]);
        st_.add_auxiliary(sums + 2, scale * sines_[angles + i]);
        st_.add_auxiliary(sums + 3, scale * cosines_[angles + (2 * i) % K]);
        st_.add_auxiliary(sums + 4, scale * sines_[angles + (2 * i) % K]);
        st_.add(v, scale * self_weight_[v]);
    }

    /// The first of v's five auxiliary points (sum of p_m / 4K, of cos(m t) p_m / K and
    /// sin(m t) p_m / K, of cos(2 m t) p_m / 2K and sin(2 m t) p_m / 2K); made on first use,
    /// with each outgoing corner's ring position m and the ring's angles.
    int fourier_sums(int v) {
        if (fourier_first_.empty()) {
            fourier_first_.assign(valence_.size(), -1);
            circle_first_.assign(valence_.size(), -1);
            self_weight_.assign(valence_.size(), 0.0);
            ring_index_.assign(conn_.corner_vertex.size(), -1);
        }
        if (fourier_first_[v] >= 0) return fourier_first_[v];
        const int K = valence_[v];
        ring_.clear();
        for (int c = conn_.vertex_corner[v];;) {
            ring_index_[c] = static_cast<int>(ring_.size());
            ring_.push_back(conn_.head(c));
            c = conn_.next_around_vertex(c);
            if (c == conn_.vertex_corner[v]) break;
        }
        const size_t angles = cosines_.size();
        circle_first_[v] = static_cast<int>(angles);
        detail::append_unit_circle(K, cosines_, sines_);
        const auto sum = [&](auto weight) {
            for (int m = 0; m < K; ++m) st_.add_auxiliary_term(ring_[m], weight(m) / K);
            return st_.end_auxiliary();
        };
        const int first = sum([](int) { return 0.25; });
        sum([&](int m) { return cosines_[angles + m]; });
        sum([&](int m) { return sines_[angles + m]; });
        sum([&](int m) { return 0.5 * cosines_[angles + (2 * m) % K]; });
        sum([&](int m) { return 0.5 * sines_[angles + (2 * m) % K]; });
        self_weight_[v] = modified_butterfly_stencil(K)[static_cast<size_t>(K)];
        return fourier_first_[v] = first;
    }

    /// The wing point c across the edge of corner w (x -> b), -1/16 (scaled); when that edge
    /// is on the boundary, its stand-in under the wing rule: the reflection x + b - opposite,
    /// opposite itself (the edge's third vertex), or the other triangle's apex.
    void wing(int w, int opposite, int other_apex, double scale) {
        const int t = conn_.twin[w];
        if (t >= 0) {
            st_.add(conn_.corner_vertex[conn_.prev[t]], scale * kButterflyC);
            return;
        }
        switch (wings_) {
            case ButterflyWings::OppositeVertex: st_.add(opposite, scale * kButterflyC); return;
            case ButterflyWings::OtherFaceVertex: st_.add(other_apex, scale * kButterflyC); return;
            case ButterflyWings::Reflected: break;
        }
        st_.add(conn_.corner_vertex[w], scale * kButterflyC);
        st_.add(conn_.head(w), scale * kButterflyC);
        st_.add(opposite, -scale * kButterflyC);
    }

    const PolyConnectivity& conn_;
    const std::vector<int>& valence_;
    ButterflyWings wings_;
    StencilTable& st_;
    std::vector<std::vector<double>> stencil_by_valence_ = std::vector<std::vector<double>>(kFourierValence + 1);
    std::vector<int> fourier_first_;  ///< per vertex, -1 until its sums are made; empty when none is
    std::vector<int> circle_first_;   ///< per vertex, where its ring's angles start in cosines_ and sines_
    std::vector<double> cosines_, sines_;
    std::vector<double> self_weight_;  ///< per vertex, the K-point stencil's weight on the vertex
    std::vector<int> ring_index_;      ///< per corner, its head's position in its vertex's ring
    std::vector<int> ring_;            ///< the ring being walked
};

}  // namespace

RefinementStep butterfly_step(const PolyMesh& mesh, const PolyConnectivity& conn, ButterflyVariant variant,
                              ButterflyWings wings) {
    detail::require_triangles(mesh, to_string(variant).data());
    const int nv = mesh.num_vertices(), nf = mesh.num_faces(), ne = conn.num_edges();
    if (static_cast<long long>(nv) + ne > INT_MAX || 4LL * nf > INT_MAX)
        throw InputError("the next Butterfly level would have " + std::to_string(4LL * nf) +
                         " faces, more than 32-bit indices address; use fewer levels");
    // Valence as OpenMesh counts it: edges at the vertex (the K of the K-point stencil); VTK
    // tells a regular vertex by its faces.
    std::vector<int> valence(static_cast<size_t>(nv), 0), faces(static_cast<size_t>(nv), 0);
    std::vector<char> on_boundary(static_cast<size_t>(nv), 0);
    for (int v = 0; v < nv; ++v) {
        if (conn.vertex_corner[v] < 0) continue;
        on_boundary[v] = conn.is_boundary_vertex(v);
        faces[v] = conn.fan(v).faces;
        valence[v] = faces[v] + on_boundary[v];
    }
    const bool vtk_choices = wings == ButterflyWings::OtherFaceVertex;

    RefinementStep step(nv);
    StencilTable& st = step.stencils;
    st.reserve(static_cast<size_t>(nv) + ne, static_cast<size_t>(nv) + 12 * static_cast<size_t>(ne));
    for (int v = 0; v < nv; ++v) {  // interpolating: old vertices stay
        st.add(v, 1.0);
        st.end_row();
    }
    EdgeStencil stencil(conn, valence, wings, st);
    for (int e = 0; e < ne; ++e) {
        const int c = conn.edge_corner[e], t = conn.twin[c];
        const int a0 = conn.corner_vertex[c], a1 = conn.head(c);
        if (t < 0) {
            stencil.boundary(c);
        } else if (variant == ButterflyVariant::Classic) {
            stencil.eight_point(c);
        } else if (vtk_choices) {
            // vtkButterflySubdivisionFilter: both endpoints of 6 faces, the eight-point
            // stencil; else the K-point stencil of each endpoint that has not 6 (halved when
            // both have not), where an endpoint on the boundary gives the eight-point stencil.
            const bool regular0 = faces[a0] == 6, regular1 = faces[a1] == 6;
            const double scale = !regular0 && !regular1 ? 0.5 : 1.0;
            if (regular0 && regular1) stencil.eight_point(c);
            for (const auto& [corner, vertex, regular] : {std::tuple{t, a1, regular1}, std::tuple{c, a0, regular0}}) {
                if (regular) continue;
                if (on_boundary[vertex]) stencil.eight_point(c, scale);
                else stencil.extraordinary(corner, scale);
            }
        } else {
            const bool regular0 = valence[a0] == 6, regular1 = valence[a1] == 6;
            const bool b0 = on_boundary[a0], b1 = on_boundary[a1];
            if ((regular0 && regular1) || (b0 && regular1) || (b1 && regular0) || (b0 && b1)) {
                stencil.eight_point(c);
            } else {
                const bool use0 = !regular0 && !b0, use1 = !regular1 && !b1;
                const double scale = use0 && use1 ? 0.5 : 1.0;
                if (use0) stencil.extraordinary(c, scale);
                if (use1) stencil.extraordinary(t, scale);
            }
        }
        st.end_row();
    }

    step.face_vertices.reserve(12 * static_cast<size_t>(nf));
    step.face_start.reserve(4 * static_cast<size_t>(nf) + 1);
    for (int f = 0; f < nf; ++f) {
        const int c0 = mesh.face_start[f], c1 = c0 + 1, c2 = c0 + 2;
        const int e0 = nv + conn.corner_edge[c0], e1 = nv + conn.corner_edge[c1], e2 = nv + conn.corner_edge[c2];
        step.add_face({conn.corner_vertex[c0], e0, e2});
        step.add_face({conn.corner_vertex[c1], e1, e0});
        step.add_face({conn.corner_vertex[c2], e2, e1});
        step.add_face({e0, e1, e2});
    }
    return step;
}

PolyMesh butterfly_subdivide(const PolyMesh& mesh, ButterflyVariant variant, int levels, ButterflyWings wings) {
    detail::require_triangles(mesh, to_string(variant).data());  // also for levels = 0
    detail::require_no_creases(mesh, to_string(variant).data());
    return detail::refine_levels(mesh, levels, [&](const PolyMesh& m, const PolyConnectivity& conn, int) {
        return butterfly_step(m, conn, variant, wings);
    });
}

}  // namespace crossdiv
