#include "crossdiv/subdiv/face_varying_limit.h"

#include <cmath>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/limit.h"
#include "face_varying_topology.h"

namespace crossdiv {
namespace {

using face_varying_topology::Analyzer;
using face_varying_topology::Topology;
using face_varying_topology::ValueKind;

/// Accumulates weighted values of a channel into one limit value.
class LimitSum {
public:
    LimitSum(const FaceVaryingChannel& in, FaceVaryingChannel& out) : in_(in), out_(out) {}
    void start(int value) {
        target_ = out_.values.data() + static_cast<size_t>(value) * static_cast<size_t>(in_.dimension);
        for (int d = 0; d < in_.dimension; ++d) target_[d] = 0.0;
    }
    void add(int value, double w) {
        const double* x = in_.value(value);
        for (int d = 0; d < in_.dimension; ++d) target_[d] += w * x[d];
    }

private:
    const FaceVaryingChannel& in_;
    FaceVaryingChannel& out_;
    double* target_ = nullptr;
};

/// Sdc's Catmull-Clark smooth limit weights at valence n: (vertex, edge, face).
struct SmoothWeights {
    double vertex, edge, face;
};
SmoothWeights catmull_clark_limit_weights(int n) {
    if (n == 4) return {4.0 / 9.0, 1.0 / 9.0, 1.0 / 36.0};  // the regular case, as Sdc spells it
    const double face = 1.0 / (n * (n + 5.0)), edge = 4.0 * face;
    return {1.0 - n * (edge + face), edge, face};
}
/// Loop's smooth limit weights at valence n (limit.h's ring weight, Sdc's; the regular case
/// as Sdc spells it): (vertex, edge).
SmoothWeights loop_limit_weights(int n) {
    if (n == 6) return {0.5, 1.0 / 12.0, 0.0};
    const double edge = loop_limit_ring_weight(LoopWeights::Loop, n);
    return {1.0 - edge * n, edge, 0.0};
}

}  // namespace

FaceVaryingChannel face_varying_limit(const PolyMesh& mesh, const FaceVaryingChannel& channel, FaceVaryingScheme scheme,
                                      const FaceVaryingOptions& options, const FaceVaryingSemiSharp* semi) {
    PolyMesh checked = mesh;
    checked.face_varying = {channel};
    check_face_varying(checked);
    const PolyConnectivity conn = build_poly_connectivity(mesh);
    FaceVaryingChannel out = channel;
    if (options.rule == FaceVaryingRule::All || scheme == FaceVaryingScheme::Bilinear) return out;  // linear: kept
    if (options.rules == CreaseRules::Hbr)
        throw InputError("the limit of texture coordinates is computed under OpenSubdiv 3's face-varying rules only (Hbr's "
                         "rules have no limit masks here)");

    const Topology t = Analyzer(mesh, conn, channel, options, semi).run();
    const std::vector<int>& value = channel.corner_values;
    const CreaseLevel sharpness(mesh, conn, options.creasing, options.geometry_corners_sharp);
    std::vector<float> vertex_sharpness(static_cast<size_t>(mesh.num_vertices()), 0.0f);
    for (const SharpVertex& s : mesh.creases.vertices) vertex_sharpness[static_cast<size_t>(s.v)] = s.sharpness;
    LimitSum sum(channel, out);
    // The value at the far end of edge e from v (one value: the edge is continuous at a
    // matching vertex).
    const auto far_value = [&](int e, int v) {
        const int c = conn.edge_corner[e];
        return mesh.face_vertices[static_cast<size_t>(c)] == v ? value[static_cast<size_t>(conn.next[c])]
                                                                : value[static_cast<size_t>(c)];
    };

    for (int v = 0; v < mesh.num_vertices(); ++v) {
        const int first = t.first_slot[static_cast<size_t>(v)], end = t.first_slot[static_cast<size_t>(v) + 1];
        if (first == end) continue;  // isolated
        if (t.slot_kind[static_cast<size_t>(first)] != ValueKind::Matched) {
            for (int s = first; s < end; ++s) {
                const int x = t.slot_value[static_cast<size_t>(s)];
                // A corner, or a crease still semi-sharp (a corner decaying to a crease): kept.
                if (t.slot_kind[static_cast<size_t>(s)] != ValueKind::Crease ||
                    t.slot_semi[static_cast<size_t>(s)] != SemiSharpTag::None)
                    continue;
                const auto [a, b] = t.slot_ends[static_cast<size_t>(s)];
                sum.start(x);
                sum.add(a, 1.0 / 6.0);
                sum.add(b, 1.0 / 6.0);
                sum.add(x, 4.0 / 6.0);
            }
            continue;
        }
        // A matching vertex: its vertex rule at this level, read off the sharpness (Sdc's
        // Crease::DetermineVertexVertexRule: a sharp vertex or 3+ sharp edges a corner, two a
        // crease, fewer smooth or a dart).
        const int x = t.slot_value[static_cast<size_t>(first)];
        const bool boundary = conn.is_boundary_vertex(v);
        const int faces = conn.fan(v).faces;
        int sharp_edges = 0, ends[2] = {-1, -1};
        for_each_edge_around(conn, v, [&](int e, int) {
            if (!(sharpness.edge_sharpness(e) > 0.0f)) return;
            if (sharp_edges < 2) ends[sharp_edges] = far_value(e, v);
            ++sharp_edges;
        });
        const bool corner = vertex_sharpness[static_cast<size_t>(v)] > 0.0f || sharp_edges > 2 ||
                            (boundary && faces == 1 && options.geometry_corners_sharp);
        if (corner) continue;
        if (sharp_edges == 2) {
            sum.start(x);
            sum.add(ends[0], 1.0 / 6.0);
            sum.add(ends[1], 1.0 / 6.0);
            sum.add(x, 4.0 / 6.0);
            continue;
        }
        // Smooth or a dart: an interior vertex (a boundary has two sharp edges).
        if (scheme == FaceVaryingScheme::CatmullClark && faces == 2) continue;  // Sdc: the corner mask
        const SmoothWeights w = scheme == FaceVaryingScheme::CatmullClark ? catmull_clark_limit_weights(faces)
                                                                          : loop_limit_weights(faces);
        sum.start(x);
        const int start = conn.vertex_corner[v];
        for (int c = start; c >= 0;) {
            const int f = conn.corner_face[c];
            const int size = mesh.face_size(f);
            const int wanted = scheme == FaceVaryingScheme::CatmullClark ? 4 : 3;
            if (size != wanted)
                throw InputError("vertex " + std::to_string(v) + " has a face of " + std::to_string(size) + " corners (face " +
                                 std::to_string(f) + "): the " +
                                 (wanted == 4 ? "Catmull-Clark limit mask needs quads around it (refine once first)"
                                              : "Loop limit mask needs triangles"));
            sum.add(value[static_cast<size_t>(conn.next[c])], w.edge);
            if (w.face != 0.0) sum.add(value[static_cast<size_t>(conn.next[conn.next[c]])], w.face);
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
        sum.add(x, w.vertex);
    }
    for (size_t i = 0; i < out.values.size(); ++i)
        if (!std::isfinite(out.values[i]))
            throw InputError("face-varying value " + std::to_string(i / static_cast<size_t>(out.dimension)) +
                             ": its limit is not finite; the values overflow double in the masks, so scale them down");
    return out;
}

}  // namespace crossdiv
