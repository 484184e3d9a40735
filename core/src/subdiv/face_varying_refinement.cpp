#include "crossdiv/subdiv/face_varying_refinement.h"

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/crease_level.h"
#include "crossdiv/subdiv/crease_mask.h"
#include "finite_level.h"

namespace crossdiv {
namespace {

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

/// Where each child vertex comes from, read off the step's faces (so that no scheme's vertex
/// numbering is assumed beyond "old vertices keep their index").
struct ChildOrigins {
    std::vector<int> edge_of_child;  ///< the parent edge of an edge point, else -1
    std::vector<int> face_of_child;  ///< the parent face of a face point, else -1
    std::vector<int> parent_face;    ///< per child face
    /// Per child face, the parent corner whose vertex it keeps (-1 for Loop's middle
    /// triangle, which keeps none): an old vertex's corner in a child face is that one's.
    std::vector<int> parent_corner;
};

ChildOrigins child_origins(const PolyMesh& parent, const PolyConnectivity& conn, const RefinementStep& step,
                           FaceVaryingScheme scheme) {
    ChildOrigins o;
    const size_t child_nv = static_cast<size_t>(step.stencils.num_rows());
    o.edge_of_child.assign(child_nv, -1);
    o.face_of_child.assign(child_nv, -1);
    const int nc = conn.num_corners();
    const int child_faces = static_cast<int>(step.face_start.size()) - 1;
    o.parent_face.resize(static_cast<size_t>(child_faces));
    o.parent_corner.assign(static_cast<size_t>(child_faces), -1);
    if (scheme == FaceVaryingScheme::Loop) {
        if (child_faces != 4 * parent.num_faces())
            throw std::logic_error("refine_face_varying: a Loop step with " + std::to_string(child_faces) + " faces");
        for (int f = 0; f < parent.num_faces(); ++f) {
            const int c = parent.face_start[f];
            for (int k = 0; k < 3; ++k) {
                o.parent_face[static_cast<size_t>(4 * f + k)] = f;
                o.parent_corner[static_cast<size_t>(4 * f + k)] = c + k;
                const int m = step.face_vertices[static_cast<size_t>(3 * (4 * f + k) + 1)];
                o.edge_of_child[static_cast<size_t>(m)] = conn.corner_edge[c + k];
            }
            o.parent_face[static_cast<size_t>(4 * f + 3)] = f;
        }
    } else {
        if (child_faces != nc)
            throw std::logic_error("refine_face_varying: a quad step with " + std::to_string(child_faces) + " faces");
        for (int c = 0; c < nc; ++c) {
            o.parent_face[static_cast<size_t>(c)] = conn.corner_face[c];
            o.parent_corner[static_cast<size_t>(c)] = c;
            o.edge_of_child[static_cast<size_t>(step.face_vertices[static_cast<size_t>(4 * c + 1)])] = conn.corner_edge[c];
            o.face_of_child[static_cast<size_t>(step.face_vertices[static_cast<size_t>(4 * c + 2)])] = conn.corner_face[c];
        }
    }
    return o;
}

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
    Analyzer analyzer(parent, conn, channel, options, semi_in);
    const Topology t = analyzer.run();
    const ChildOrigins origin = child_origins(parent, conn, step, scheme);
    const int nv = parent.num_vertices();
    const int child_nv = step.stencils.num_rows();
    const bool linear = options.rule == FaceVaryingRule::All || scheme == FaceVaryingScheme::Bilinear;

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
    const std::function<RefinementStep(const PolyMesh&, const PolyConnectivity&)>& step) {
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
