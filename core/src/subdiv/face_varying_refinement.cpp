#include "crossdiv/subdiv/face_varying_refinement.h"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/crease_level.h"
#include "crossdiv/subdiv/crease_mask.h"
#include "face_varying_children.h"
#include "face_varying_legacy_rules.h"
#include "face_varying_topology.h"
#include "finite_level.h"

namespace crossdiv {
namespace {

using face_varying_topology::Analyzer;
using face_varying_topology::Topology;
using face_varying_topology::ValueKind;
using face_varying_children::ChildOrigins;
using face_varying_children::child_origins;

/// Sums weighted values into a new value of `out`.
class ValueWriter {
public:
    ValueWriter(const FaceVaryingChannel& in, FaceVaryingChannel& out) : in_(in), out_(out), d_(in.dimension) {}
    /// Starts value `index` of `out` at zero.
    void begin(int index) {
        dst_ = out_.value(index);
        for (int k = 0; k < d_; ++k) dst_[k] = 0.0;
    }
    void add_parent(int value, double w) {
        const double* p = in_.value(value);
        for (int k = 0; k < d_; ++k) dst_[k] += w * p[k];
    }
    void add_child(int value, double w) {
        const double* p = out_.value(value);
        for (int k = 0; k < d_; ++k) dst_[k] += w * p[k];
    }

private:
    const FaceVaryingChannel& in_;
    FaceVaryingChannel& out_;
    int d_;
    double* dst_ = nullptr;
};

}  // namespace

FaceVaryingChannel refine_face_varying(const PolyMesh& parent, const PolyConnectivity& conn, const RefinementStep& step,
                                       const FaceVaryingChannel& channel, FaceVaryingScheme scheme,
                                       const FaceVaryingOptions& options, const FaceVaryingSemiSharp* semi_in,
                                       FaceVaryingSemiSharp* semi_out) {
    const bool linear = options.rule == FaceVaryingRule::All || scheme == FaceVaryingScheme::Bilinear;
    if (options.rules == CreaseRules::Hbr && !linear) {
        if (options.rule == FaceVaryingRule::CornersOnly)
            throw InputError("face-varying rule corners-only has no counterpart among Hbr's face-varying rules (it is new in "
                             "OpenSubdiv 3)");
        return face_varying_legacy_rules::refine(parent, conn, step, channel, scheme, options, semi_in, semi_out);
    }
    Analyzer analyzer(parent, conn, channel, options, semi_in);
    const Topology t = analyzer.run();
    const ChildOrigins origin = child_origins(parent, conn, step, scheme);
    const int nv = parent.num_vertices();
    const int child_nv = step.stencils.num_rows();

    // The child values, numbered per child vertex in order: an old vertex has one per value
    // of its parent, a face point one, an edge point one, or one per face on a discontinuous
    // edge (side k: the face of conn.edge_corner, then its twin's).
    std::vector<int> first(static_cast<size_t>(child_nv) + 1, 0);
    for (int x = 0; x < child_nv; ++x) {
        int count = 1;
        if (x < nv) count = t.first_slot[x + 1] - t.first_slot[x];
        else if (const int e = origin.edge_of_child[x]; e >= 0 && t.edge_discontinuous[e]) count = 2;
        first[x + 1] = first[x] + count;
    }
    FaceVaryingChannel out;
    out.name = channel.name;
    out.dimension = channel.dimension;
    out.values.assign(static_cast<size_t>(first[child_nv]) * channel.dimension, 0.0);
    if (semi_out) semi_out->tag.assign(static_cast<size_t>(first[child_nv]), static_cast<unsigned char>(SemiSharpTag::None));
    ValueWriter w(channel, out);

    // A matching point's value is its stencil with each parent vertex replaced by its value
    // in the faces the point depends on (unique there: no edge among them is a seam).
    std::vector<int> local(static_cast<size_t>(nv), -1);
    auto mark_face = [&](int f, bool set) {
        for (int c = parent.face_start[f]; c < parent.face_start[f + 1]; ++c)
            local[static_cast<size_t>(parent.face_vertices[c])] = set ? channel.corner_values[c] : -1;
    };
    auto mark_fan = [&](int v, bool set) {  // the faces around v
        const int start = conn.vertex_corner[v];
        for (int c = start; c >= 0;) {
            mark_face(conn.corner_face[c], set);
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
    };
    const StencilTable& st = step.stencils;
    auto apply_stencil = [&](int x) {
        w.begin(first[x]);
        for (int k = st.row_begin(x); k < st.row_end(x); ++k) {
            const int s = st.source(k);
            if (s < 0) throw std::logic_error("refine_face_varying: a stencil with auxiliary points");
            if (s < nv) {
                const int value = local[static_cast<size_t>(s)];
                if (value < 0) throw std::logic_error("refine_face_varying: a stencil reads outside its faces");
                w.add_parent(value, st.weight(k));
            } else {
                w.add_child(first[s - nv], st.weight(k));
            }
        }
    };

    // Face points first: edge and vertex stencils read them.
    for (int x = nv; x < child_nv; ++x) {
        const int f = origin.face_of_child[x];
        if (f < 0) continue;
        w.begin(first[x]);
        const double weight = 1.0 / parent.face_size(f);
        for (int c = parent.face_start[f]; c < parent.face_start[f + 1]; ++c) w.add_parent(channel.corner_values[c], weight);
    }
    for (int x = nv; x < child_nv; ++x) {
        const int e = origin.edge_of_child[x];
        if (e < 0) continue;
        const int c = conn.edge_corner[e], tw = conn.twin[c];
        const bool linear_boundary = tw < 0 && (options.rule == FaceVaryingRule::Boundaries || options.rule == FaceVaryingRule::All);
        if (linear || linear_boundary || t.edge_discontinuous[e]) {
            // The midpoint of each side.
            for (int side = 0; side < (t.edge_discontinuous[e] ? 2 : 1); ++side) {
                const int a = side == 0 ? c : tw;
                w.begin(first[x] + side);
                w.add_parent(channel.corner_values[a], 0.5);
                w.add_parent(channel.corner_values[conn.next[a]], 0.5);
            }
            continue;
        }
        mark_face(conn.corner_face[c], true);
        if (tw >= 0) mark_face(conn.corner_face[tw], true);
        apply_stencil(x);
        mark_face(conn.corner_face[c], false);
        if (tw >= 0) mark_face(conn.corner_face[tw], false);
    }
    for (int v = 0; v < nv; ++v) {
        for (int s = t.first_slot[v]; s < t.first_slot[v + 1]; ++s) {
            const int x = first[v] + (s - t.first_slot[v]);
            const ValueKind kind = t.slot_kind[s];
            if (linear || kind == ValueKind::Corner) {
                w.begin(x);
                w.add_parent(t.slot_value[s], 1.0);
            } else if (kind == ValueKind::Crease) {
                // Semi-sharp: a corner while its sharpness lasts; at the level where it runs
                // out, the crease mask blended toward the corner's by the weight of what
                // decays (a value sharpened by the other one takes that one's weight).
                const SemiSharpTag tag = t.slot_semi[s];
                const SemiSharpTag child = analyzer.child_tag(t, v, s);
                if (semi_out) semi_out->tag[static_cast<size_t>(x)] = static_cast<unsigned char>(child);
                if (child != SemiSharpTag::None) {
                    w.begin(x);
                    w.add_parent(t.slot_value[s], 1.0);
                    continue;
                }
                const int from = tag == SemiSharpTag::Dependent ? Analyzer::other_value(t, v, s) : s;
                const double corner = tag == SemiSharpTag::None || from < 0 ? 0.0 : analyzer.fractional_weight(t, v, from);
                w.begin(x);
                w.add_parent(t.slot_ends[s][0], (1.0 - corner) * kCreaseEdgeWeight);
                w.add_parent(t.slot_ends[s][1], (1.0 - corner) * kCreaseEdgeWeight);
                w.add_parent(t.slot_value[s], (1.0 - corner) * kCreaseVertexWeight + corner);
            } else {
                mark_fan(v, true);
                apply_stencil(v);
                mark_fan(v, false);
            }
        }
    }

    // Child corners: the value of their vertex on the side of the parent face.
    out.corner_values.resize(step.face_vertices.size());
    for (size_t cf = 0; cf + 1 < step.face_start.size(); ++cf) {
        const int f = origin.parent_face[cf];
        for (int k = step.face_start[cf]; k < step.face_start[cf + 1]; ++k) {
            const int x = step.face_vertices[static_cast<size_t>(k)];
            int value = first[x];
            if (x < nv) {
                const int pc = origin.parent_corner[cf];
                if (pc < 0 || parent.face_vertices[pc] != x)
                    throw std::logic_error("refine_face_varying: a child face keeps an unexpected vertex");
                value += t.corner_slot[pc] - t.first_slot[x];
            } else if (const int e = origin.edge_of_child[x]; e >= 0 && t.edge_discontinuous[e]) {
                value += conn.corner_face[conn.edge_corner[e]] == f ? 0 : 1;
            }
            out.corner_values[static_cast<size_t>(k)] = value;
        }
    }
    return out;
}

std::vector<PolyMesh> subdivide_levels_with_face_varying(
    const PolyMesh& mesh, FaceVaryingScheme scheme, const FaceVaryingOptions& options, int levels,
    const std::function<RefinementStep(const PolyMesh&, const PolyConnectivity&)>& step,
    std::vector<FaceVaryingSemiSharp>* semi_tags) {
    if (levels < 0) throw InputError("number of levels must be >= 0, got " + std::to_string(levels));
    check_face_varying(mesh);
    std::vector<PolyMesh> out{mesh};
    if (levels == 0) build_poly_connectivity(mesh);  // the same checks as a refinement
    std::vector<FaceVaryingSemiSharp> semi;  // each channel's tags, carried from level to level
    for (int l = 0; l < levels; ++l) {
        const PolyMesh& current = out.back();
        const PolyConnectivity conn = build_poly_connectivity(current);
        const RefinementStep s = step(current, conn);
        PolyMesh next = apply_step(s, current);
        detail::require_finite_level(next.positions, current.positions, l + 1);
        std::vector<FaceVaryingSemiSharp> semi_next(current.face_varying.size());
        for (size_t k = 0; k < current.face_varying.size(); ++k)
            next.face_varying.push_back(refine_face_varying(current, conn, s, current.face_varying[k], scheme, options,
                                                            l == 0 ? nullptr : &semi[k], &semi_next[k]));
        semi = std::move(semi_next);
        out.push_back(std::move(next));
    }
    if (semi_tags) *semi_tags = std::move(semi);
    return out;
}

PolyMesh subdivide_with_face_varying(
    const PolyMesh& mesh, FaceVaryingScheme scheme, const FaceVaryingOptions& options, int levels,
    const std::function<RefinementStep(const PolyMesh&, const PolyConnectivity&)>& step) {
    PolyMesh last = std::move(subdivide_levels_with_face_varying(mesh, scheme, options, levels, step).back());
    last.source = {};
    return last;
}

}  // namespace crossdiv
