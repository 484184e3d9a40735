#pragma once
// The face-varying topology of one level, as OpenSubdiv's Vtr::FVarLevel reads it from the
// value indices: which edges are discontinuous, which vertices match, and each value's kind
// (matched, corner, crease) with a crease's ends and semi-sharpness. Read by the refinement of
// the channels (face_varying_refinement.cpp) and by their limit (face_varying_limit.cpp).
// Internal to core.

#include <array>
#include <stdexcept>
#include <vector>

#include "crossdiv/mesh/face_varying.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/crease_level.h"
#include "crossdiv/subdiv/crease_mask.h"
#include "crossdiv/subdiv/face_varying_refinement.h"

namespace crossdiv::face_varying_topology {

/// What happens to one value of a vertex at the next level.
enum class ValueKind : unsigned char {
    Matched,  ///< the vertex matches: the vertex's own mask
    Corner,   ///< kept
    Crease,   ///< 3/4 itself, 1/8 each end of its span
};

/// The face-varying topology of one level (OpenSubdiv's FVarLevel): the values of every
/// vertex, each value's kind, and each corner's value among its vertex's.
struct Topology {
    std::vector<char> edge_discontinuous;  ///< per edge: its faces give an end different values
    std::vector<char> vertex_matches;      ///< per vertex
    std::vector<int> first_slot;           ///< per vertex (and one past the last): its values' slots
    std::vector<int> slot_value;           ///< per slot: the value index in the channel
    std::vector<ValueKind> slot_kind;
    std::vector<std::array<int, 2>> slot_ends;  ///< a crease's end values
    std::vector<SemiSharpTag> slot_semi;  ///< a crease's semi-sharpness (FaceVaryingSemiSharp)
    std::vector<std::array<int, 2>> slot_span;  ///< a crease's first and last face, as one-ring walk indices
    std::vector<int> corner_slot;               ///< per corner: the slot of its value
};

/// The spans of the values around a vertex that does not match, walked in one-ring order:
/// faces k = 0 .. F-1 (conn.vertex_corner, then next_around_vertex), face k and k+1 sharing
/// the outgoing edge of corner k.
struct Span {
    int size = 0;            ///< faces
    int first = -1;          ///< the walk index of its first face
    int last = -1;           ///< and of its last
    bool disjoint = false;   ///< two runs, or a discontinuous or infinitely sharp edge inside
    bool semi_sharp = false; ///< a semi-sharp edge inside
};

class Analyzer {
public:
    Analyzer(const PolyMesh& mesh, const PolyConnectivity& conn, const FaceVaryingChannel& ch,
             const FaceVaryingOptions& options, const FaceVaryingSemiSharp* carried)
        : mesh_(mesh), conn_(conn), value_(ch.corner_values), options_(options),
          sharpness_(mesh, conn, options.creasing, options.geometry_corners_sharp), carried_(carried) {
        if (carried_ && carried_->tag.size() != static_cast<size_t>(ch.num_values()))
            throw std::logic_error("refine_face_varying: semi-sharp tags for another channel");
    }

    Topology run() {
        const int nv = mesh_.num_vertices(), ne = conn_.num_edges();
        Topology t;
        t.edge_discontinuous.assign(static_cast<size_t>(ne), 0);
        t.vertex_matches.assign(static_cast<size_t>(nv), 1);
        for (int e = 0; e < ne; ++e) {
            const int c = conn_.edge_corner[e], w = conn_.twin[c];
            if (w < 0) continue;
            if (value_[c] != value_[conn_.next[w]] || value_[conn_.next[c]] != value_[w]) {
                t.edge_discontinuous[e] = 1;
                t.vertex_matches[conn_.edge_vertices[e][0]] = 0;
                t.vertex_matches[conn_.edge_vertices[e][1]] = 0;
            }
        }
        const bool linear_boundaries = options_.rule == FaceVaryingRule::Boundaries || options_.rule == FaceVaryingRule::All;
        const bool sharpen_smooth_corners = !options_.geometry_corners_sharp && options_.rule != FaceVaryingRule::None;
        for (int v = 0; v < nv; ++v) {
            if (!t.vertex_matches[v] || !conn_.is_boundary_vertex(v)) continue;
            const int faces = conn_.fan(v).faces;
            if (linear_boundaries || (faces == 1 && sharpen_smooth_corners)) t.vertex_matches[v] = 0;
        }
        vertex_sharpness_.assign(static_cast<size_t>(nv), 0.0f);
        for (const SharpVertex& s : mesh_.creases.vertices) vertex_sharpness_[static_cast<size_t>(s.v)] = s.sharpness;

        t.first_slot.reserve(static_cast<size_t>(nv) + 1);
        t.corner_slot.assign(value_.size(), -1);
        slot_of_value_.assign(static_cast<size_t>(max_value() + 1), -1);
        for (int v = 0; v < nv; ++v) {
            t.first_slot.push_back(static_cast<int>(t.slot_value.size()));
            add_values(t, v);
        }
        t.first_slot.push_back(static_cast<int>(t.slot_value.size()));
        return t;
    }

private:
    int max_value() const {
        int m = -1;
        for (int x : value_) m = x > m ? x : m;
        return m;
    }

    /// The corners of v's one-ring walk into walk_ (from conn.vertex_corner: on a boundary,
    /// where the boundary comes in).
    void walk_around(int v) {
        walk_.clear();
        const int start = conn_.vertex_corner[v];
        for (int c = start; c >= 0;) {
            walk_.push_back(c);
            c = conn_.next_around_vertex(c);
            if (c == start) break;
        }
    }

    /// The slots of vertex v: its distinct values in walk order, classified.
    void add_values(Topology& t, int v) {
        const int start = conn_.vertex_corner[v];
        const int base = static_cast<int>(t.slot_value.size());
        if (start < 0) {  // isolated: no value
            return;
        }
        walk_around(v);
        for (int c : walk_) {
            int& s = slot_of_value_[static_cast<size_t>(value_[c])];
            if (s < 0) {
                s = static_cast<int>(t.slot_value.size());
                t.slot_value.push_back(value_[c]);
                t.slot_kind.push_back(ValueKind::Corner);
                t.slot_ends.push_back({-1, -1});
                t.slot_semi.push_back(SemiSharpTag::None);
                t.slot_span.push_back({-1, -1});
            }
            t.corner_slot[c] = s;
        }
        for (int c : walk_) slot_of_value_[static_cast<size_t>(value_[c])] = -1;
        if (t.vertex_matches[v]) {
            t.slot_kind[base] = ValueKind::Matched;
            return;
        }
        classify(t, v, base, static_cast<int>(t.slot_value.size()) - base);
    }

public:
    /// OpenSubdiv's FVarRefinement::getFractionalWeight: the transition weight, between this
    /// level and the next, of vertex v and of the edges inside the span of `slot`.
    double fractional_weight(const Topology& t, int v, int slot) {
        walk_around(v);
        const int faces = static_cast<int>(walk_.size());
        const auto [first, last] = t.slot_span[static_cast<size_t>(slot)];
        parent_edges_.clear();
        child_edges_.clear();
        for (int k = first; k != last; k = (k + 1) % faces) {  // the edge between faces k and k + 1
            const int e = conn_.corner_edge[walk_[k]];
            parent_edges_.push_back(sharpness_.edge_sharpness(e));
            child_edges_.push_back(sharpness_.child_half_sharpness(e, v));
        }
        const float vs = vertex_sharpness_[static_cast<size_t>(v)];
        return transition_weight(vs, decrement_sharpness(vs), parent_edges_, child_edges_);
    }

    /// The tag a semi-sharp crease value of vertex v (slot `slot`) has at the next level, as
    /// OpenSubdiv's FVarRefinement::reclassifySemisharpValues gives it: unchanged while the
    /// vertex stays sharp; a plain crease once no edge at the vertex is semi-sharp; else its
    /// own while an edge inside its span stays semi-sharp -- and a dependent value stays
    /// dependent while the one it depends on stays semi-sharp, and is then semi-sharp in its
    /// own name (until the edges at the vertex decay).
    SemiSharpTag child_tag(const Topology& t, int v, int slot) {
        const SemiSharpTag parent = t.slot_semi[static_cast<size_t>(slot)];
        if (parent == SemiSharpTag::None) return parent;
        if (is_sharp(decrement_sharpness(vertex_sharpness_[static_cast<size_t>(v)]))) return parent;
        bool any = false;
        for_each_edge_around(conn_, v, [&](int e, int) { any = any || is_semi_sharp(sharpness_.child_half_sharpness(e, v)); });
        if (!any) return SemiSharpTag::None;
        auto span_stays = [&](int s) {
            walk_around(v);
            const int faces = static_cast<int>(walk_.size());
            const auto [first, last] = t.slot_span[static_cast<size_t>(s)];
            for (int k = first; k != last; k = (k + 1) % faces)
                if (is_semi_sharp(sharpness_.child_half_sharpness(conn_.corner_edge[walk_[k]], v))) return true;
            return false;
        };
        if (parent == SemiSharpTag::Own) return span_stays(slot) ? SemiSharpTag::Own : SemiSharpTag::None;
        const int other = other_value(t, v, slot);
        const bool other_stays = other >= 0 && t.slot_semi[static_cast<size_t>(other)] == SemiSharpTag::Own && span_stays(other);
        return other_stays ? SemiSharpTag::Dependent : SemiSharpTag::Own;
    }

    /// The other slot of a vertex with two values (-1 otherwise).
    static int other_value(const Topology& t, int v, int slot) {
        const int base = t.first_slot[static_cast<size_t>(v)];
        if (t.first_slot[static_cast<size_t>(v) + 1] - base != 2) return -1;
        return slot == base ? base + 1 : base;
    }

private:

    bool edge_inf_sharp(int e) const { return is_infinitely_sharp(sharpness_.edge_sharpness(e)); }
    bool edge_semi_sharp(int e) const { return is_sharp(sharpness_.edge_sharpness(e)) && !edge_inf_sharp(e); }

    /// OpenSubdiv's completeTopologyFromFaceValues and gatherValueSpans for one vertex that
    /// does not match; the slots start Corner.
    void classify(Topology& t, int v, int base, int n) {
        const FaceVaryingRule rule = options_.rule;
        const bool boundary = conn_.is_boundary_vertex(v);
        const int faces = static_cast<int>(walk_.size());
        const bool linear_boundaries = rule == FaceVaryingRule::Boundaries || rule == FaceVaryingRule::All;
        const bool dependent = rule == FaceVaryingRule::CornersPlus1 || rule == FaceVaryingRule::CornersPlus2;
        const bool sharpen_darts = rule == FaceVaryingRule::CornersPlus2 || linear_boundaries;
        const float vs = vertex_sharpness_[static_cast<size_t>(v)];
        const bool vertex_inf_sharp =
            is_infinitely_sharp(vs) || (boundary && faces == 1 && options_.geometry_corners_sharp);
        if (linear_boundaries || vertex_inf_sharp || (dependent && n > 2) || (sharpen_darts && n == 1 && !boundary))
            return;  // every value a corner

        spans_.assign(static_cast<size_t>(n), Span{});
        if (n == 1) {
            // One value all round: its span starts after the first discontinuous edge; a second
            // one, or any infinitely sharp edge (a boundary edge is one), makes it disjoint.
            Span& s = spans_[0];
            s.size = faces;
            bool found = false;
            for_each_edge_around(conn_, v, [&](int e, int) {
                if (t.edge_discontinuous[e]) {
                    if (found) s.disjoint = true;
                    found = true;
                } else if (edge_inf_sharp(e)) {
                    s.disjoint = true;
                } else if (edge_semi_sharp(e)) {
                    s.semi_sharp = true;
                }
            });
            for (int k = 0; k < faces && found; ++k)
                if (t.edge_discontinuous[conn_.corner_edge[walk_[k]]]) {
                    s.first = (k + 1) % faces;
                    s.last = k;
                    break;
                }
        } else {
            // Runs of equal values; inside, a circle starts at a change of value.
            int k0 = 0;
            if (!boundary)
                while (k0 < faces && t.corner_slot[walk_[k0]] == t.corner_slot[walk_[(k0 + faces - 1) % faces]]) ++k0;
            for (int i = 0; i < faces; ++i) {
                const int k = (k0 + i) % faces;
                const int slot = t.corner_slot[walk_[k]] - base;
                Span& s = spans_[static_cast<size_t>(slot)];
                const bool continues = i > 0 && t.corner_slot[walk_[(k + faces - 1) % faces]] - base == slot;
                if (continues) {
                    const int e = conn_.corner_edge[walk_[(k + faces - 1) % faces]];  // between faces k-1 and k
                    if (t.edge_discontinuous[e] || edge_inf_sharp(e)) s.disjoint = true;
                    else if (edge_semi_sharp(e)) s.semi_sharp = true;
                } else {
                    if (s.size > 0) s.disjoint = true;
                    s.first = k;
                }
                s.last = k;
                ++s.size;
            }
        }
        if (dependent && n == 2) {
            bool all = spans_[0].disjoint || spans_[1].disjoint;
            if (rule == FaceVaryingRule::CornersPlus2) all = all || spans_[0].size == 1 || spans_[1].size == 1;
            if (all) return;
        }
        // With two values of which one is semi-sharp, corners-plus1 and corners-plus2 make the
        // other depend on it (OpenSubdiv's depSharp values). After the first level every value
        // has the tag the level before gave it (carried_).
        const bool vertex_semi_sharp = is_semi_sharp(vs);
        const bool dependent_pair = dependent && n == 2 && spans_[0].semi_sharp != spans_[1].semi_sharp;
        const bool corners_sharp = rule != FaceVaryingRule::None;
        for (int i = 0; i < n; ++i) {
            const Span& s = spans_[static_cast<size_t>(i)];
            if (s.disjoint || (s.size == 1 && corners_sharp)) continue;
            const int slot = base + i;
            t.slot_kind[slot] = ValueKind::Crease;
            // The far ends of the span's bounding edges: the incoming edge of its first face,
            // the outgoing edge of its last.
            t.slot_ends[slot] = {value_[conn_.prev[walk_[s.first]]], value_[conn_.next[walk_[s.last]]]};
            t.slot_span[slot] = {s.first, s.last};
            if (carried_) {
                t.slot_semi[slot] = static_cast<SemiSharpTag>(carried_->tag.at(static_cast<size_t>(t.slot_value[slot])));
            } else if (s.semi_sharp || vertex_semi_sharp) {
                t.slot_semi[slot] = SemiSharpTag::Own;
            } else if (dependent_pair) {
                t.slot_semi[slot] = SemiSharpTag::Dependent;
            }
        }
    }

    const PolyMesh& mesh_;
    const PolyConnectivity& conn_;
    const std::vector<int>& value_;
    FaceVaryingOptions options_;
    CreaseLevel sharpness_;
    std::vector<float> vertex_sharpness_;
    std::vector<int> slot_of_value_;  ///< scratch, -1 between vertices
    std::vector<int> walk_;
    std::vector<Span> spans_;
    std::vector<float> parent_edges_, child_edges_;  ///< scratch of fractional_weight
    const FaceVaryingSemiSharp* carried_;            ///< the tags of the level before, or null at the first
};

}  // namespace crossdiv::face_varying_topology
