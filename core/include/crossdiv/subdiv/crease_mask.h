#pragma once
/// @file
/// Crease rules shared by Loop and Catmull-Clark, the weights only: how sharpness decays
/// from a level to the next, which rule a vertex's sharpness selects, the fractional weight
/// of a rule transition, the sharp masks (crease, corner) and the blend of two masks. As
/// OpenSubdiv's Sdc::Crease and Sdc::Scheme define them (after T. DeRose, M. Kass, T. Truong,
/// "Subdivision Surfaces in Character Animation", SIGGRAPH 1998: semi-sharp creases; Chaikin
/// decay), and beside them Hbr's variants (CreaseRules::Hbr). Scheme-free: each scheme brings
/// its smooth masks; crease_level.h gathers the sharpness of a level; the traversals are
/// catmull_clark.cpp and loop_step.cpp.
///
/// Sharpness is float, as in OpenSubdiv, so that decay and thresholds match the library's bit
/// for bit; mask weights are double.

#include <algorithm>
#include <span>
#include <vector>

#include "crossdiv/mesh/crease_tags.h"

namespace crossdiv {

/// Sharpness at and above which a feature is infinitely sharp (Sdc::Crease::SHARPNESS_INFINITE).
inline constexpr float kSharpnessInfinite = 10.0f;

/// The crease mask (Sdc::Crease, Hoppe et al. 1994): 3/4 on the vertex, 1/8 on each end of
/// its two sharp edges -- the cubic B-spline's vertex rule along the crease.
inline constexpr double kCreaseVertexWeight = 0.75, kCreaseEdgeWeight = 0.125;

inline bool is_sharp(float s) { return s > 0.0f; }
inline bool is_infinitely_sharp(float s) { return s >= kSharpnessInfinite; }
inline bool is_semi_sharp(float s) { return s > 0.0f && s < kSharpnessInfinite; }

/// The subdivision rule a vertex's sharpness neighbourhood selects (Sdc::Crease::Rule).
enum class VertexRule {
    Smooth,  ///< no sharp edge: the scheme's smooth mask
    Dart,    ///< one sharp edge: still the smooth mask (the crease fades out here)
    Crease,  ///< two sharp edges: the curve rule 3/4, 1/8, 1/8 along them
    Corner,  ///< three or more sharp edges, or a sharp vertex: the vertex stays
};

/// Uniform decay: semi-sharp values drop by 1 (to 0 at or below 1); smooth and infinitely
/// sharp values stay.
inline float decrement_sharpness(float s) {
    if (s <= 0.0f) return 0.0f;
    if (is_infinitely_sharp(s)) return kSharpnessInfinite;
    return s > 1.0f ? s - 1.0f : 0.0f;
}

/// Sharpness of the child half of an edge of sharpness `s` at an end vertex whose incident
/// edges have the sharpnesses `around` (s among them): Sdc::Crease::SubdivideEdgeSharpnessAtVertex.
/// The sum runs in the order given, in float, as the library's does.
inline float child_edge_sharpness(CreaseMethod method, float s, std::span<const float> around) {
    if (method == CreaseMethod::Uniform || around.size() < 2) return decrement_sharpness(s);
    if (s <= 0.0f) return 0.0f;
    if (is_infinitely_sharp(s)) return kSharpnessInfinite;
    float sum = 0.0f;
    int count = 0;
    for (float x : around)
        if (is_semi_sharp(x)) {
            ++count;
            sum += x;
        }
    if (count > 1) {  // 3/4 of its own sharpness and 1/4 of the average of the others
        const float others = (sum - s) / static_cast<float>(count - 1);
        s = 0.75f * s + 0.25f * others;
    }
    s -= 1.0f;
    return s > 0.0f ? s : 0.0f;
}

/// The rule of a vertex of sharpness `vertex_sharpness` with `sharp_edges` sharp incident edges.
inline VertexRule vertex_rule(float vertex_sharpness, int sharp_edges) {
    if (is_sharp(vertex_sharpness) || sharp_edges > 2) return VertexRule::Corner;
    return sharp_edges == 2 ? VertexRule::Crease : sharp_edges == 1 ? VertexRule::Dart : VertexRule::Smooth;
}

/// Weight of the parent's (sharper) mask when a vertex's rule changes between a level and
/// the next: the average of the sharpnesses that decayed to zero in this step -- the
/// vertex's own and those of its edges -- clamped to 1 (Sdc::Crease::ComputeFractionalWeightAtVertex).
inline float transition_weight(float parent_vertex, float child_vertex, std::span<const float> parent_edges,
                               std::span<const float> child_edges) {
    int count = 0;
    float sum = 0.0f;
    if (is_sharp(parent_vertex) && !is_sharp(child_vertex)) {
        count = 1;
        sum = parent_vertex;
    }
    for (size_t i = 0; i < parent_edges.size(); ++i)
        if (is_sharp(parent_edges[i]) && !is_sharp(child_edges[i])) {
            sum += parent_edges[i];
            ++count;
        }
    if (count == 0) return 0.0f;
    return std::min(sum / static_cast<float>(count), 1.0f);
}

/// Sharpness of the child half of edge `self` (of sharpness `s`, among the end vertex's edges
/// `around`) under Hbr's rules (CreaseRules::Hbr, HbrSubdivision::SubdivideCreaseWeight): as
/// child_edge_sharpness for the uniform decay; Chaikin's takes 1/4 of the average of every
/// other sharp edge (infinitely sharp ones too) plus 3/4 of its own, then drops by 1, a lone
/// sharp edge 3/4 of its own. In float, in Hbr's order.
inline float hbr_child_edge_sharpness(CreaseMethod method, float s, std::span<const float> around, size_t self) {
    if (method == CreaseMethod::Uniform || s <= 0.0f || is_infinitely_sharp(s)) return decrement_sharpness(s);
    float others = 0.0f;
    int n = 0;
    for (size_t i = 0; i < around.size(); ++i)
        if (i != self && around[i] > 0.0f) {
            others += around[i];
            ++n;
        }
    float child = n ? others * 0.25f / static_cast<float>(n) : 0.0f;
    child += s * 0.75f;
    child -= 1.0f;
    return child > 0.0f ? child : 0.0f;
}

/// Hbr's sharpness of a feature in the child rule (CreaseRules::Hbr): sharp when at least 1.
inline float hbr_child_rule_sharpness(float s) { return s >= 1.0f ? s : 0.0f; }

/// Hbr's weight of the parent rule (HbrVertex::GetFractionalMask): the average of the vertex's
/// and its edges' sharpnesses strictly between 0 and 1, in float as Hbr sums them; 0 when
/// there is none (the rules then do not differ).
inline float hbr_transition_weight(float parent_vertex, std::span<const float> parent_edges) {
    float sum = 0.0f, n = 0.0f;
    if (parent_vertex > 0.0f && parent_vertex < 1.0f) {
        sum += parent_vertex;
        n += 1.0f;
    }
    for (float s : parent_edges)
        if (s > 0.0f && s < 1.0f) {
            sum += s;
            n += 1.0f;
        }
    return n > 0.0f ? sum / n : 0.0f;
}

/// A vertex-point mask in OpenSubdiv's form: a weight on the vertex, one per incident edge
/// (applied to the edge's other end) and one per incident face (Catmull-Clark: its new face
/// point; Loop has none). `has_edges` is false for a corner mask, which has no edge weights
/// at all (not zero ones) -- the distinction the blend below depends on.
struct VertexPointMask {
    double vertex = 0.0;
    bool has_edges = false;
    std::vector<double> edge;
    std::vector<double> face;

    /// The crease mask: 3/4 on the vertex, 1/8 on the other ends of incident edges `end0`
    /// and `end1` (indices into the vertex's edge order), of `edges` incident edges.
    void set_crease(int edges, int end0, int end1) {
        vertex = kCreaseVertexWeight;
        has_edges = true;
        edge.assign(static_cast<size_t>(edges), 0.0);
        edge[static_cast<size_t>(end0)] = edge[static_cast<size_t>(end1)] = kCreaseEdgeWeight;
        face.clear();
    }
    /// The corner mask: the vertex stays.
    void set_corner() {
        vertex = 1.0;
        has_edges = false;
        edge.clear();
        face.clear();
    }
};

/// Blends the child rule's mask into the parent rule's: parent = p * parent + (1 - p) * child,
/// where a weight list the parent lacks is taken from the child alone
/// (Sdc::Scheme::LocalMask::CombineVertexVertexMasks).
inline void blend_vertex_masks(VertexPointMask& parent, const VertexPointMask& child, double p) {
    const double c = 1.0 - p;
    parent.vertex = p * parent.vertex + c * child.vertex;
    if (child.has_edges) {
        if (!parent.has_edges) {
            parent.edge.assign(child.edge.size(), 0.0);
            for (size_t i = 0; i < child.edge.size(); ++i) parent.edge[i] = c * child.edge[i];
            parent.has_edges = true;
        } else {
            for (size_t i = 0; i < child.edge.size(); ++i) parent.edge[i] = p * parent.edge[i] + c * child.edge[i];
        }
    }
    if (!child.face.empty()) {
        if (parent.face.empty()) {
            parent.face.assign(child.face.size(), 0.0);
            for (size_t i = 0; i < child.face.size(); ++i) parent.face[i] = c * child.face[i];
        } else {
            for (size_t i = 0; i < child.face.size(); ++i) parent.face[i] = p * parent.face[i] + c * child.face[i];
        }
    }
}

/// Edge-point weights: `end` on each endpoint, `other` on each opposite term (Catmull-Clark:
/// the two face points; Loop: the two opposite vertices).
struct EdgePointWeights {
    double end, other;
};

/// The edge point of a sharp edge whose child is no longer a crease: the crease mask (1/2,
/// 1/2) weighted by the edge's sharpness s blended with the smooth mask, as
/// Sdc::Scheme::ComputeEdgeVertexMask does -- without clamping s, as the library does not.
inline EdgePointWeights transition_edge_weights(EdgePointWeights smooth, float s) {
    const double p = s, c = 1.0 - p;
    return {p * 0.5 + c * smooth.end, c * smooth.other};
}

}  // namespace crossdiv
