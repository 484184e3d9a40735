// Face-varying refinement by Hbr's rules, the rules of OpenSubdiv 2 and RenderMan, which
// OpenSubdiv 3's compatibility notes (documentation/compatibility.rst) say Far corrected.
//
// Hbr decides everything per face corner from a vertex's *face-varying mask*: a corner (3) if
// the vertex has a sharpness of at least 1, plus one for each face-varying boundary edge around
// it, at most 3 (HbrVertex::GetFVarMask). A face-varying boundary edge
// (HbrHalfedge::GetFVarSharpness) is a boundary edge, an edge whose two faces give an end
// values more than 0.001 apart (compared as floats, HbrFVarData::Compare), an edge with any
// sharpness at all -- semi-sharp ones included -- or a half of such an edge at the level
// before (CopyFVarInfiniteSharpness): once an edge is sharp at some level, its descendants
// are face-varying boundaries for good. The value of a vertex in a child face is
// (HbrCatmarkSubdivision / HbrLoopSubdivision::transferFVarToChild):
// - kept, if the vertex has any sharpness, or under always-sharp (Far's `boundaries`) its mask
//   is at least 1, or under edge-and-corner (Far's `corners-plus1/2`) it is a face-varying
//   corner: a mask of 3, or with propagated corners (plus2) a dart or two face-varying
//   boundary edges side by side anywhere around it, without (plus1) the two edges of this
//   face at the vertex being face-varying boundaries;
// - a dart (mask 1): 3/4 itself and 1/8 each of the values the far end of its one boundary
//   edge has on the edge's two sides;
// - any other mask but 0: 3/4 itself and 1/8 each of the far ends of the first face-varying
//   boundary edges met turning from the face each way around the vertex, as seen from the
//   faces on this side;
// - mask 0: the scheme's smooth interior rule, creases or not.
// An edge's point is the midpoint (of each side's values) on a face-varying boundary edge,
// else the scheme's smooth edge rule. Far instead refines a value that is continuous with the
// vertex's own mask, fractional sharpness included, and a semi-sharp crease's value with the
// crease rule only while the sharpness lasts; hence the two differences the compatibility
// notes illustrate (a dart's values drawn toward the dart's edge, fractional sharpness not
// blended).
//
// Values are stored as Hbr stores them: one per face point, one per edge point (one per side on
// a face-varying boundary edge), one per vertex whose mask is 0 and one per face otherwise
// (equal neighbours merged).

#include "face_varying_legacy_rules.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "crossdiv/subdiv/catmull_clark_mask.h"
#include "crossdiv/subdiv/crease_level.h"
#include "crossdiv/subdiv/crease_mask.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "face_varying_children.h"

namespace crossdiv::face_varying_legacy_rules {
namespace {

/// Hbr's face-varying interpolate-boundary methods for the rules of Far they stand for
/// (the compatibility notes' table; `all` is linear under both and never reaches here).
struct Method {
    bool edge_and_corner = false;  ///< k_InterpolateBoundaryEdgeAndCorner (plus1, plus2)
    bool propagate_corners = false;  ///< SetFVarPropagateCorners (plus2)
    bool always_sharp = false;     ///< k_InterpolateBoundaryAlwaysSharp (boundaries)
};

Method method_for(FaceVaryingRule rule) {
    switch (rule) {
        case FaceVaryingRule::None: return {};  // k_InterpolateBoundaryEdgeOnly
        case FaceVaryingRule::CornersPlus1: return {true, false, false};
        case FaceVaryingRule::CornersPlus2: return {true, true, false};
        case FaceVaryingRule::Boundaries: return {false, false, true};
        case FaceVaryingRule::CornersOnly:
        case FaceVaryingRule::All: break;
    }
    throw std::logic_error("face_varying_legacy_rules: rule " + std::string(to_string(rule)) + " has no Hbr method here");
}

/// Hbr's mask of a corner (k_Corner): a vertex this sharp is kept under edge-and-corner.
constexpr int kCornerMask = 3;
/// HbrHalfedge::GetFVarInfiniteSharp: two values closer than this, component by component in
/// float, are one value.
constexpr float kSameValue = 0.001f;

/// What a vertex of the level before left a child vertex (FaceVaryingSemiSharp::vertex_origin).
enum Origin : unsigned char { kKept = 0, kNewPoint = 1, kBoundaryEdgePoint = 2 };

class Level {
public:
    Level(const PolyMesh& parent, const PolyConnectivity& conn, const FaceVaryingChannel& channel, FaceVaryingScheme scheme,
          const FaceVaryingOptions& options, const FaceVaryingSemiSharp* carried)
        : parent_(parent), conn_(conn), channel_(channel), scheme_(scheme), method_(method_for(options.rule)),
          crease_(parent, conn, options.creasing, options.geometry_corners_sharp, CreaseRules::Hbr), d_(channel.dimension) {
        const int nv = parent.num_vertices(), ne = conn.num_edges();
        const std::vector<unsigned char>* origin = carried && !carried->vertex_origin.empty() ? &carried->vertex_origin : nullptr;
        if (origin && origin->size() != static_cast<size_t>(nv))
            throw std::logic_error("face_varying_legacy_rules: vertex origins of another level");
        boundary_.assign(static_cast<size_t>(ne), 0);
        for (int e = 0; e < ne; ++e) {
            const int c = conn.edge_corner[e], tw = conn.twin[c];
            bool b = tw < 0 || is_sharp(crease_.edge_sharpness(e));
            if (!b) b = differ(conn.next[tw], c) || differ(tw, conn.next[c]);
            if (!b && origin) {
                const unsigned char o0 = (*origin)[static_cast<size_t>(conn.edge_vertices[e][0])];
                const unsigned char o1 = (*origin)[static_cast<size_t>(conn.edge_vertices[e][1])];
                b = (o0 == kKept && o1 == kBoundaryEdgePoint) || (o0 == kBoundaryEdgePoint && o1 == kKept);
            }
            boundary_[static_cast<size_t>(e)] = b;
        }
        sharpness_.assign(static_cast<size_t>(nv), 0.0f);
        mask_.assign(static_cast<size_t>(nv), 0);
        for (int v = 0; v < nv; ++v) {
            float s = crease_.vertex_tag(v);
            // The edge-and-corner rule makes a boundary vertex with one face infinitely sharp
            // (HbrMesh::Finish), and so a kept value under every face-varying method.
            if (options.geometry_corners_sharp && conn.is_boundary_vertex(v) && conn.fan(v).faces == 1) s = kSharpnessInfinite;
            sharpness_[static_cast<size_t>(v)] = s;
            int mask = s >= 1.0f ? kCornerMask : 0;
            for_each_edge_around(conn, v, [&](int e, int) {
                if (boundary_[static_cast<size_t>(e)] && mask < kCornerMask) ++mask;
            });
            mask_[static_cast<size_t>(v)] = static_cast<unsigned char>(mask);
        }
        find_boundary_ends();
    }

    bool boundary_edge(int e) const { return boundary_[static_cast<size_t>(e)]; }
    int mask(int v) const { return mask_[static_cast<size_t>(v)]; }
    const double* value(int corner) const { return channel_.value(channel_.corner_values[static_cast<size_t>(corner)]); }

    /// The value of corner c's vertex in corner c's child face, into `out`.
    void vertex_value(int c, double* out) const {
        const int v = conn_.corner_vertex[c];
        const int m = mask(v);
        bool corner = false;
        if (method_.edge_and_corner)
            corner = m >= kCornerMask || (method_.propagate_corners
                                              ? fvar_corner_[static_cast<size_t>(v)] != 0
                                              : boundary_edge(conn_.corner_edge[c]) && boundary_edge(conn_.corner_edge[conn_.prev[c]]));
        if ((method_.always_sharp && m >= 1) || is_sharp(sharpness_[static_cast<size_t>(v)]) || corner) {
            set(out, value(c), 1.0);
        } else if (m == 1) {
            dart(c, out);
        } else if (m != 0) {
            crease(c, out);
        } else if (scheme_ == FaceVaryingScheme::Loop) {
            const int n = conn_.fan(v).faces;
            const VertexMask w = interior_vertex_mask(LoopWeights::Loop, n);
            set(out, value(c), w.self);
            for_each_corner_around(v, [&](int k) { add(out, value(conn_.next[k]), w.neighbor); });
        } else {
            const int n = conn_.fan(v).faces;
            const CatmullClarkVertexMask w = catmull_clark_interior_vertex_mask(n);
            set(out, value(c), w.self);
            for_each_corner_around(v, [&](int k) {
                const int f = conn_.corner_face[k];
                const double per_corner = w.face / parent_.face_size(f);
                for (int j = parent_.face_start[f]; j < parent_.face_start[f + 1]; ++j) add(out, value(j), per_corner);
                add(out, value(conn_.next[k]), w.ring);
            });
        }
    }

    /// The point of corner c's edge seen from c's face, into `out`.
    void edge_value(int c, double* out) const {
        const int e = conn_.corner_edge[c];
        if (boundary_edge(e)) {
            set(out, value(c), 0.5);
            add(out, value(conn_.next[c]), 0.5);
            return;
        }
        const int tw = conn_.twin[c];
        if (scheme_ == FaceVaryingScheme::Loop) {
            const EdgeMask w = interior_edge_mask();
            set(out, value(c), w.end);
            add(out, value(conn_.next[c]), w.end);
            add(out, value(conn_.prev[c]), w.opposite);
            add(out, value(conn_.prev[tw]), w.opposite);
            return;
        }
        set(out, value(c), kCatmullClarkEdgeEnd);
        add(out, value(conn_.next[c]), kCatmullClarkEdgeEnd);
        add_face_average(out, conn_.corner_face[c], kCatmullClarkEdgeFace);
        add_face_average(out, conn_.corner_face[tw], kCatmullClarkEdgeFace);
    }

    void face_value(int f, double* out) const {
        for (int k = 0; k < d_; ++k) out[k] = 0.0;
        add_face_average(out, f, 1.0);
    }

private:
    bool differ(int a, int b) const {
        const double *x = value(a), *y = value(b);
        for (int k = 0; k < d_; ++k)
            if (std::fabs(static_cast<float>(x[k]) - static_cast<float>(y[k])) > kSameValue) return true;
        return false;
    }

    template <class F>
    void for_each_corner_around(int v, F f) const {
        const int start = conn_.vertex_corner[v];
        for (int c = start; c >= 0;) {
            f(c);
            c = conn_.next_around_vertex(c);
            if (c == start) break;
        }
    }

    /// For every vertex with face-varying boundary edges, in one walk around it (so that no
    /// vertex costs more than its valence): whether it is a face-varying corner
    /// (HbrVertex::IsFVarCorner: a dart, or two boundary edges side by side -- edges of one
    /// face at it, so on a boundary the two boundary edges are not, unless it has one face); a
    /// dart's boundary edge; and for each corner the far ends of the first boundary edges met
    /// turning from its face each way (HbrVertex::GetNextEdge and GetPreviousEdge), as the
    /// corners whose values they are.
    void find_boundary_ends() {
        const int nv = parent_.num_vertices();
        fvar_corner_.assign(static_cast<size_t>(nv), 0);
        dart_.assign(static_cast<size_t>(nv), -1);
        end_before_.assign(static_cast<size_t>(conn_.num_corners()), -1);
        end_after_.assign(static_cast<size_t>(conn_.num_corners()), -1);
        std::vector<int> walk, before, after;
        std::vector<char> in, out;
        for (int v = 0; v < nv; ++v) {
            if (mask(v) == 0) continue;
            walk.clear();
            for_each_corner_around(v, [&](int c) { walk.push_back(c); });
            const int n = static_cast<int>(walk.size());
            const bool on_boundary = conn_.is_boundary_vertex(v);
            in.resize(static_cast<size_t>(n));
            out.resize(static_cast<size_t>(n));
            for (int i = 0; i < n; ++i) {
                const int c = walk[static_cast<size_t>(i)];
                in[static_cast<size_t>(i)] = boundary_edge(conn_.corner_edge[conn_.prev[c]]);
                out[static_cast<size_t>(i)] = boundary_edge(conn_.corner_edge[c]);
                if (out[static_cast<size_t>(i)] && dart_[static_cast<size_t>(v)] < 0) dart_[static_cast<size_t>(v)] = c;
            }
            // Side by side: the edges in turn are in[0], out[0], out[1], ... (out[i] is in[i + 1]
            // inside the walk); around an inner vertex the last is beside the first.
            bool side_by_side = mask(v) == 1;
            for (int i = 0; i < n && !side_by_side; ++i)
                side_by_side = out[static_cast<size_t>(i)] && (i > 0 ? out[static_cast<size_t>(i - 1)] != 0
                                                                     : on_boundary ? in[0] != 0 : out[static_cast<size_t>(n - 1)] != 0);
            fvar_corner_[static_cast<size_t>(v)] = side_by_side;
            // Backward: the last boundary edge coming in at or before each corner; forward: the
            // first going out at or after it. Twice around an inner vertex (its walk is a cycle);
            // on a boundary the walk's first edge in and last edge out are the mesh's boundary.
            before.assign(static_cast<size_t>(n), -1);
            after.assign(static_cast<size_t>(n), -1);
            for (int t = 0, last = -1; t < 2 * n; ++t) {
                const int i = t % n;
                if (in[static_cast<size_t>(i)]) last = i;
                if (t >= n || on_boundary) before[static_cast<size_t>(i)] = before[static_cast<size_t>(i)] < 0 ? last : before[static_cast<size_t>(i)];
            }
            for (int t = 2 * n - 1, next = -1; t >= 0; --t) {
                const int i = t % n;
                if (out[static_cast<size_t>(i)]) next = i;
                if (t < n || on_boundary) after[static_cast<size_t>(i)] = after[static_cast<size_t>(i)] < 0 ? next : after[static_cast<size_t>(i)];
            }
            for (int i = 0; i < n; ++i) {
                const int c = walk[static_cast<size_t>(i)];
                const int b = before[static_cast<size_t>(i)], a = after[static_cast<size_t>(i)];
                end_before_[static_cast<size_t>(c)] = b >= 0 ? conn_.prev[walk[static_cast<size_t>(b)]] : c;
                end_after_[static_cast<size_t>(c)] = a >= 0 ? conn_.next[walk[static_cast<size_t>(a)]] : conn_.next[c];
            }
        }
    }

    /// The dart rule: the two values of the far end of v's one face-varying boundary edge.
    void dart(int c, double* out) const {
        const int found = dart_[static_cast<size_t>(conn_.corner_vertex[c])];
        if (found < 0 || conn_.twin[found] < 0) throw std::logic_error("face_varying_legacy_rules: a dart without its edge");
        set(out, value(c), kCreaseVertexWeight);
        add(out, value(conn_.next[found]), kCreaseEdgeWeight);
        add(out, value(conn_.twin[found]), kCreaseEdgeWeight);
    }

    /// The boundary rule: 3/4 itself, 1/8 each of the far ends of the first face-varying
    /// boundary edges met turning from c's face each way, in the last face before them.
    void crease(int c, double* out) const {
        set(out, value(c), kCreaseVertexWeight);
        add(out, value(end_before_[static_cast<size_t>(c)]), kCreaseEdgeWeight);
        add(out, value(end_after_[static_cast<size_t>(c)]), kCreaseEdgeWeight);
    }

    void add_face_average(double* out, int f, double weight) const {
        const double w = weight / parent_.face_size(f);
        for (int j = parent_.face_start[f]; j < parent_.face_start[f + 1]; ++j) add(out, value(j), w);
    }
    void set(double* out, const double* x, double w) const {
        for (int k = 0; k < d_; ++k) out[k] = w * x[k];
    }
    void add(double* out, const double* x, double w) const {
        for (int k = 0; k < d_; ++k) out[k] += w * x[k];
    }

    const PolyMesh& parent_;
    const PolyConnectivity& conn_;
    const FaceVaryingChannel& channel_;
    FaceVaryingScheme scheme_;
    Method method_;
    CreaseLevel crease_;
    int d_;
    std::vector<char> boundary_;        ///< per edge: a face-varying boundary edge
    std::vector<float> sharpness_;      ///< per vertex
    std::vector<unsigned char> mask_;   ///< per vertex: the face-varying mask
    std::vector<char> fvar_corner_;     ///< per vertex: HbrVertex::IsFVarCorner
    std::vector<int> dart_;             ///< per vertex: the corner whose edge is a dart's boundary edge
    std::vector<int> end_before_, end_after_;  ///< per corner: the boundary rule's two other values
};

}  // namespace

FaceVaryingChannel refine(const PolyMesh& parent, const PolyConnectivity& conn, const RefinementStep& step,
                          const FaceVaryingChannel& channel, FaceVaryingScheme scheme, const FaceVaryingOptions& options,
                          const FaceVaryingSemiSharp* carried, FaceVaryingSemiSharp* next) {
    if (scheme == FaceVaryingScheme::Bilinear) throw std::logic_error("face_varying_legacy_rules: bilinear is linear");
    Level level(parent, conn, channel, scheme, options, carried);
    const face_varying_children::ChildOrigins origin = face_varying_children::child_origins(parent, conn, step, scheme);
    const int nv = parent.num_vertices(), ne = conn.num_edges(), d = channel.dimension;
    const int child_nv = step.stencils.num_rows();

    FaceVaryingChannel out;
    out.name = channel.name;
    out.dimension = d;
    auto append = [&]() {
        out.values.resize(out.values.size() + static_cast<size_t>(d));
        return out.num_values() - 1;
    };

    std::vector<int> face_point(static_cast<size_t>(parent.num_faces()), -1);
    if (scheme == FaceVaryingScheme::CatmullClark)
        for (int f = 0; f < parent.num_faces(); ++f) {
            face_point[static_cast<size_t>(f)] = append();
            level.face_value(f, out.value(face_point[static_cast<size_t>(f)]));
        }
    // An edge point: one value, or one per side of a face-varying boundary edge (side 0 the
    // face of conn.edge_corner, as face_varying_refinement numbers them).
    std::vector<int> edge_point(static_cast<size_t>(ne), -1);
    for (int e = 0; e < ne; ++e) {
        const int c = conn.edge_corner[e], tw = conn.twin[c];
        edge_point[static_cast<size_t>(e)] = append();
        level.edge_value(c, out.value(edge_point[static_cast<size_t>(e)]));
        if (level.boundary_edge(e) && tw >= 0) level.edge_value(tw, out.value(append()));
    }
    // A vertex's value per corner: one if its mask is 0, else each face's, a face whose value
    // equals the one before it around the vertex sharing that one's.
    std::vector<int> corner_value(static_cast<size_t>(conn.num_corners()), -1);
    std::vector<double> scratch(static_cast<size_t>(d));
    for (int v = 0; v < nv; ++v) {
        const int start = conn.vertex_corner[v];
        if (start < 0) continue;
        const bool one = level.mask(v) == 0;
        int first = -1, previous = -1, run_start = -1;
        int count = 0;
        for (int c = start; c >= 0;) {
            if (one && first >= 0) {
                corner_value[static_cast<size_t>(c)] = first;
            } else {
                level.vertex_value(c, scratch.data());
                if (previous >= 0 && std::memcmp(out.value(previous), scratch.data(), sizeof(double) * static_cast<size_t>(d)) == 0) {
                    corner_value[static_cast<size_t>(c)] = previous;
                } else {
                    previous = append();
                    std::memcpy(out.value(previous), scratch.data(), sizeof(double) * static_cast<size_t>(d));
                    corner_value[static_cast<size_t>(c)] = previous;
                    run_start = count;
                    if (first < 0) first = previous;
                }
            }
            ++count;
            c = conn.next_around_vertex(c);
            if (c == start) break;
        }
        // Around an interior vertex the last run may continue the first: one value.
        if (!one && previous != first && !conn.is_boundary_vertex(v) &&
            std::memcmp(out.value(previous), out.value(first), sizeof(double) * static_cast<size_t>(d)) == 0) {
            int k = 0;
            for (int c = start; c >= 0; ++k) {
                if (k >= run_start) corner_value[static_cast<size_t>(c)] = first;
                c = conn.next_around_vertex(c);
                if (c == start) break;
            }
            if (previous == out.num_values() - 1) out.values.resize(out.values.size() - static_cast<size_t>(d));
        }
    }

    out.corner_values.resize(step.face_vertices.size());
    for (size_t cf = 0; cf + 1 < step.face_start.size(); ++cf) {
        const int f = origin.parent_face[cf];
        for (int k = step.face_start[cf]; k < step.face_start[cf + 1]; ++k) {
            const int x = step.face_vertices[static_cast<size_t>(k)];
            int value = -1;
            if (x < nv) {
                const int pc = origin.parent_corner[cf];
                if (pc < 0 || parent.face_vertices[pc] != x)
                    throw std::logic_error("face_varying_legacy_rules: a child face keeps an unexpected vertex");
                value = corner_value[static_cast<size_t>(pc)];
            } else if (const int e = origin.edge_of_child[x]; e >= 0) {
                const int c = conn.edge_corner[e];
                const bool two = level.boundary_edge(e) && conn.twin[c] >= 0;
                value = edge_point[static_cast<size_t>(e)] + (two && conn.corner_face[c] != f ? 1 : 0);
            } else {
                value = face_point[static_cast<size_t>(origin.face_of_child[x])];
            }
            out.corner_values[static_cast<size_t>(k)] = value;
        }
    }
    if (next) {
        next->tag.clear();
        next->vertex_origin.assign(static_cast<size_t>(child_nv), kNewPoint);
        for (int x = 0; x < nv; ++x) next->vertex_origin[static_cast<size_t>(x)] = kKept;
        for (int x = nv; x < child_nv; ++x)
            if (const int e = origin.edge_of_child[x]; e >= 0 && level.boundary_edge(e))
                next->vertex_origin[static_cast<size_t>(x)] = kBoundaryEdgePoint;
    }
    return out;
}

}  // namespace crossdiv::face_varying_legacy_rules
