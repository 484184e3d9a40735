#include "crossdiv/subdiv/catmull_clark_streaming.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "huge_pages.h"
#include "parallel_blocks.h"
#include "stream_twins.h"

namespace crossdiv {
namespace {

/// An allocator whose resize leaves ints unwritten: every array below is written whole before
/// it is read, and zero-filling each first would be one more pass over the level.
template <class T>
struct Unfilled : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = Unfilled<U>;
    };
    Unfilled() = default;
    template <class U>
    Unfilled(const Unfilled<U>&) {}
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        if constexpr (sizeof...(Args) == 0) ::new (static_cast<void*>(p)) U;
        else ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};
using Ints = std::vector<int, Unfilled<int>>;

/// A level's connectivity as the passes read it, in PolyConnectivity's conventions. The input
/// level (any polygons) keeps its faces' next, prev and face arrays; a refined level has quads
/// only, whose next, prev and face are closed forms (Quads).
struct Level {
    int nv = 0, nf = 0;
    std::vector<int> corner_vertex;  ///< the faces' corners, face after face (the output's at the last level)
    Ints twin;                       ///< -1 on a boundary
    Ints corner_edge, edge_corner;
    Ints start;                      ///< where each vertex's one-ring walk starts (-1: isolated)
    Ints faces;                      ///< faces around each vertex
    // The input level only:
    Ints next, prev, corner_face, face_start;

    int num_edges() const { return static_cast<int>(edge_corner.size()); }
    int num_corners() const { return static_cast<int>(corner_vertex.size()); }
};

/// The input level's faces.
struct Polygons {
    const Level& l;
    int next(int c) const { return l.next[c]; }
    int prev(int c) const { return l.prev[c]; }
    int face(int c) const { return l.corner_face[c]; }
    int begin(int f) const { return l.face_start[f]; }
    int end(int f) const { return l.face_start[f + 1]; }
};

/// A refined level's faces: quad q has corners 4q .. 4q + 3.
struct Quads {
    static int next(int c) { return (c & ~3) | ((c + 1) & 3); }
    static int prev(int c) { return (c & ~3) | ((c + 3) & 3); }
    static int face(int c) { return c >> 2; }
    static int begin(int f) { return 4 * f; }
    static int end(int f) { return 4 * f + 4; }
};

/// The input level's connectivity built directly, in time linear in the corners whatever the
/// valences, with build_poly_connectivity's numbering (edges at their first corner in scan
/// order, a walk from the corner whose incoming half-edge is on the boundary, else from the
/// vertex's first corner): the half-edges bucketed by their lesser end (a counting sort),
/// twins matched in each bucket by the greater end (an array stamped with the bucket, never
/// cleared), each vertex's corners walked once to see that they form one fan. The faces'
/// next, prev and face arrays are made for a mesh that is not all quads. nullopt when the mesh
/// is not a manifold, consistently oriented polygon mesh with valid indices: the builder then
/// names the element.
template <class Faces>
std::optional<Level> stream_input(const PolyMesh& mesh, bool quads) {
    const int nv = mesh.num_vertices(), nf = mesh.num_faces(), nc = static_cast<int>(mesh.face_vertices.size());
    Level l;
    l.nv = nv;
    l.nf = nf;
    l.corner_vertex = mesh.face_vertices;
    const int* cv = l.corner_vertex.data();
    if (!quads) {
        l.face_start.assign(mesh.face_start.begin(), mesh.face_start.end());
        l.next.resize(static_cast<size_t>(nc));
        l.prev.resize(static_cast<size_t>(nc));
        l.corner_face.resize(static_cast<size_t>(nc));
    }
    // Faces: at least 3 corners, indices in range, no vertex twice (a stamp per vertex).
    std::vector<int> stamp(static_cast<size_t>(nv), -1);
    for (int f = 0; f < nf; ++f) {
        const int b = mesh.face_start[f], e = mesh.face_start[f + 1];
        if (e - b < 3) return std::nullopt;
        for (int c = b; c < e; ++c) {
            const int v = cv[c];
            if (v < 0 || v >= nv || stamp[v] == f) return std::nullopt;
            stamp[v] = f;
            if (!quads) {
                l.next[c] = c + 1 < e ? c + 1 : b;
                l.prev[c] = c > b ? c - 1 : e - 1;
                l.corner_face[c] = f;
            }
        }
    }
    const Faces F = [&] {
        if constexpr (std::is_same_v<Faces, Quads>) return Quads{};
        else return Faces{l};
    }();
    // Half-edge c runs from cv[c] to cv[next c]. Its ends once: lesser[c], and key[c] =
    // 2 * greater end + (1 when it runs from the lesser end).
    std::vector<int> lesser(static_cast<size_t>(nc)), key(static_cast<size_t>(nc));
    for (int c = 0; c < nc; ++c) {
        const int a = cv[c], b = cv[F.next(c)];
        lesser[c] = std::min(a, b);
        key[c] = 2 * std::max(a, b) + (a < b);
    }
    l.twin.assign(static_cast<size_t>(nc), -1);
    if (!detail::stream_twins(nv, lesser, key, l.twin)) return std::nullopt;
    // Every vertex's corners in one fan: walk forward (across each outgoing edge) from the
    // first unvisited corner and, on a boundary, backward too; a second walk at a vertex is a
    // second fan (a bowtie).
    std::vector<std::uint8_t> visited(static_cast<size_t>(nc), 0), walked(static_cast<size_t>(nv), 0);
    for (int c0 = 0; c0 < nc; ++c0) {
        if (visited[c0]) continue;
        if (walked[cv[c0]]++) return std::nullopt;
        int c = c0;
        do {
            visited[c] = 1;
            c = l.twin[c] < 0 ? -1 : F.next(l.twin[c]);
        } while (c >= 0 && c != c0);
        if (c < 0)
            for (c = l.twin[F.prev(c0)]; c >= 0; c = l.twin[F.prev(c)]) visited[c] = 1;
    }
    // Edges at their first corner; walks from the boundary's incoming corner, else the first.
    l.corner_edge.resize(static_cast<size_t>(nc));
    l.edge_corner.reserve(static_cast<size_t>(nc) / 2 + 16);
    l.start.assign(static_cast<size_t>(nv), -1);
    l.faces.assign(static_cast<size_t>(nv), 0);
    for (int c = 0; c < nc; ++c) {
        const int t = l.twin[c];
        if (t < 0 || t > c) {
            l.corner_edge[c] = static_cast<int>(l.edge_corner.size());
            l.edge_corner.push_back(c);
        } else {
            l.corner_edge[c] = l.corner_edge[t];
        }
        const int v = cv[c];
        if (l.start[v] < 0 || l.twin[F.prev(c)] < 0) l.start[v] = c;
        ++l.faces[v];  // one fan, no vertex twice in a face: a face per corner
    }
    return l;
}

/// The input level. A mesh stream_input refuses is one build_poly_connectivity refuses too,
/// naming the element; were it to accept one, the two would disagree on what a manifold is,
/// which is a bug.
Level input_level(const PolyMesh& mesh, bool quads) {
    std::optional<Level> l = quads ? stream_input<Quads>(mesh, true) : stream_input<Polygons>(mesh, false);
    if (l) return std::move(*l);
    (void)build_poly_connectivity(mesh);  // throws, naming the element
    throw std::logic_error("the streaming Catmull-Clark driver refused a mesh build_poly_connectivity accepts");
}

/// The interior vertex masks by face count, once per count that occurs.
std::vector<CatmullClarkVertexMask> interior_masks(const Level& l) {
    const int most = l.faces.empty() ? 0 : *std::max_element(l.faces.begin(), l.faces.end());
    std::vector<CatmullClarkVertexMask> m(static_cast<size_t>(most) + 1);
    for (int n = 1; n <= most; ++n) m[n] = catmull_clark_interior_vertex_mask(n);
    return m;
}

/// s += w p, component by component: the operations Eigen's `s += w * p` performs, spelled
/// out so that the compiler keeps them in the loop (as a call per term they cost a third of a
/// level, measured).
inline void add(Vec3& s, double w, const Vec3& p) {
    s[0] += w * p[0];
    s[1] += w * p[1];
    s[2] += w * p[2];
}

/// One level's points into `out` (vertex points at 0..nv-1, face points at nv + f, edge points
/// at nv + nf + e), each summed from zero in catmull_clark_step's order of terms
/// (StencilTable::apply): face points in corner order; an edge point's ends, then the face
/// points of its first corner's face and its twin's; a vertex point's face points around its
/// one-ring walk, then its ring vertices, then itself. Each function writes block b of
/// `blocks` of its points; the edge and vertex points read the face points, all of them
/// written before (a region of their own).
template <class Faces>
void face_points(const Level& l, const Faces& F, const Vec3* p, Vec3* out, size_t b, size_t blocks) {
    const int* cv = l.corner_vertex.data();
    Vec3* fp = out + l.nv;
    const auto [begin, end] = detail::ParallelBlocks::block_range(static_cast<size_t>(l.nf), b, blocks);
    for (int f = static_cast<int>(begin); f < static_cast<int>(end); ++f) {
        const int c0 = F.begin(f), c1 = F.end(f);
        const double w = 1.0 / (c1 - c0);
        Vec3 s = Vec3::Zero();
        for (int c = c0; c < c1; ++c) add(s, w, p[cv[c]]);
        fp[f] = s;
    }
}

template <class Faces>
void edge_points(const Level& l, const Faces& F, const CatmullClarkOptions& o, const Vec3* p, Vec3* out, size_t b,
                 size_t blocks) {
    const int* cv = l.corner_vertex.data();
    const int* twin = l.twin.data();
    const Vec3* fp = out + l.nv;
    Vec3* ep = out + l.nv + l.nf;
    const auto [begin, end] = detail::ParallelBlocks::block_range(static_cast<size_t>(l.num_edges()), b, blocks);
    for (int e = static_cast<int>(begin); e < static_cast<int>(end); ++e) {
        const int c = l.edge_corner[e], t = twin[c];
        const Vec3 &a = p[cv[c]], &q = p[cv[F.next(c)]];
        Vec3 s = Vec3::Zero();
        if (t < 0) {  // the crease mask: the midpoint
            add(s, 0.5, a);
            add(s, 0.5, q);
        } else {
            const int fc = F.face(c), ft = F.face(t);
            const CatmullClarkEdgeWeights w = catmull_clark_edge_weights(
                o.smooth_triangles, F.end(fc) - F.begin(fc) == 3, F.end(ft) - F.begin(ft) == 3);
            add(s, w.end, a);
            add(s, w.end, q);
            add(s, w.face, fp[fc]);
            add(s, w.face, fp[ft]);
        }
        ep[e] = s;
    }
}

/// `ring`: scratch for the ring vertices of the vertex at hand, one per block.
template <class Faces>
void vertex_points(const Level& l, const Faces& F, const CatmullClarkOptions& o,
                   const std::vector<CatmullClarkVertexMask>& masks, const Vec3* p, Vec3* out, std::vector<int>& ring,
                   size_t b, size_t blocks) {
    const int* cv = l.corner_vertex.data();
    const int* twin = l.twin.data();
    const Vec3* fp = out + l.nv;
    const auto [begin, end] = detail::ParallelBlocks::block_range(static_cast<size_t>(l.nv), b, blocks);
    for (int v = static_cast<int>(begin); v < static_cast<int>(end); ++v) {
        const int start = l.start[v];
        Vec3 s = Vec3::Zero();
        if (start < 0) {  // isolated: nothing to average with, it stays
            add(s, 1.0, p[v]);
            out[v] = s;
            continue;
        }
        if (twin[F.prev(start)] < 0) {  // the walk starts where the boundary comes in
            const CatmullClarkBoundaryMask m = catmull_clark_boundary_vertex_mask(o.boundary, l.faces[v]);
            if (m.neighbor != 0.0) {
                int last = start;
                while (twin[last] >= 0) last = F.next(twin[last]);
                add(s, m.neighbor, p[cv[F.prev(start)]]);
                add(s, m.neighbor, p[cv[F.next(last)]]);
            }
            add(s, m.self, p[v]);
        } else {
            // One walk round the vertex: the face points summed, the ring vertices kept for
            // after them (the order of terms is the stencil's).
            const int n = l.faces[v];
            const CatmullClarkVertexMask& m = masks[n];
            if (n == 4) {  // the regular vertex, most of every refined level: the walk unrolled
                const int c1 = F.next(twin[start]), c2 = F.next(twin[c1]), c3 = F.next(twin[c2]);
                add(s, m.face, fp[F.face(start)]);
                add(s, m.face, fp[F.face(c1)]);
                add(s, m.face, fp[F.face(c2)]);
                add(s, m.face, fp[F.face(c3)]);
                add(s, m.ring, p[cv[F.next(start)]]);
                add(s, m.ring, p[cv[F.next(c1)]]);
                add(s, m.ring, p[cv[F.next(c2)]]);
                add(s, m.ring, p[cv[F.next(c3)]]);
                add(s, m.self, p[v]);
                out[v] = s;
                continue;
            }
            if (ring.size() < static_cast<size_t>(n)) ring.resize(static_cast<size_t>(n));
            int c = start, k = 0;
            do {
                add(s, m.face, fp[F.face(c)]);
                ring[k++] = cv[F.next(c)];
                c = F.next(twin[c]);
            } while (c != start);
            for (int j = 0; j < k; ++j) add(s, m.ring, p[ring[j]]);
            add(s, m.self, p[v]);
        }
        out[v] = s;
    }
}

/// Corner c's child quad (catmull_clark.h's numbering: quad c = (v_c, E(c), F(f), E(prev c))).
template <class Faces>
std::array<int, 4> child_quad(const Level& l, const Faces& F, int c) {
    const int face_point = l.nv, edge_point = l.nv + l.nf;
    return {l.corner_vertex[c], edge_point + l.corner_edge[c], face_point + F.face(c), edge_point + l.corner_edge[F.prev(c)]};
}

/// The next level but the last, built from the parent's connectivity alone, in the blocks of one
/// level: its quads and twins (quads_block); its edges, numbered at their first corner in scan
/// order, block by block from the counts of the blocks before (count_edges, then number_edges,
/// which also writes the walks' starts and face counts, then second_corners).
template <class Faces>
void quads_block(const Level& l, const Faces& F, Level& child, size_t b, size_t blocks) {
    const auto [begin, end] = detail::ParallelBlocks::block_range(static_cast<size_t>(l.num_corners()), b, blocks);
    for (int c = static_cast<int>(begin); c < static_cast<int>(end); ++c) {
        const std::array<int, 4> quad = child_quad(l, F, c);
        std::copy(quad.begin(), quad.end(), &child.corner_vertex[4 * static_cast<size_t>(c)]);
        // Twins. Corner c's quad has the half-edges v_c -> E(c) (its twin E(c) -> v_c is the
        // last of the quad of next(twin c), across edge c), E(c) -> F (twin: in the quad of
        // next c), F -> E(prev c) (twin: in the quad of prev c) and E(prev c) -> v_c (twin: the
        // first of the quad of twin(prev c), across edge prev c).
        const int t = l.twin[c], tp = l.twin[F.prev(c)];
        int* tw = &child.twin[4 * static_cast<size_t>(c)];
        tw[0] = t < 0 ? -1 : 4 * F.next(t) + 3;
        tw[1] = 4 * F.next(c) + 2;
        tw[2] = 4 * F.prev(c) + 1;
        tw[3] = tp < 0 ? -1 : 4 * tp;
    }
}

/// Whether child corner c is its edge's first (the edge is numbered there).
inline bool first_corner(const Level& child, int c) { return child.twin[c] < 0 || child.twin[c] > c; }

/// The first corners in block b of the child's corners, into edges[b + 1].
inline void count_edges(const Level& child, std::vector<int>& edges, size_t b, size_t blocks) {
    const auto [begin, end] = detail::ParallelBlocks::block_range(child.twin.size(), b, blocks);
    int n = 0;
    for (int c = static_cast<int>(begin); c < static_cast<int>(end); ++c) n += first_corner(child, c);
    edges[b + 1] = n;
}

/// Block b's edges numbered from edges[b] (the first corners before it), into edges[b + 1]
/// when there is one block (which then numbers the second corners too: their twins are before
/// them); the walks' starts and face counts of block b of the old vertices, face points and
/// edge points.
template <class Faces>
void number_edges(const Level& l, const Faces& F, Level& child, std::vector<int>& edges, size_t b, size_t blocks) {
    using detail::ParallelBlocks;
    {
        const auto [begin, end] = ParallelBlocks::block_range(child.twin.size(), b, blocks);
        int e = edges[b];
        for (int c = static_cast<int>(begin); c < static_cast<int>(end); ++c)
            if (first_corner(child, c)) {
                child.corner_edge[c] = e;
                child.edge_corner[e++] = c;
            } else if (blocks == 1) {
                child.corner_edge[c] = child.corner_edge[child.twin[c]];
            }
        if (blocks == 1) edges[1] = e;
    }
    // The walks' starts in closed form. An old vertex's corners are 4c for its corners c, and
    // the incoming half-edge of 4c is on the boundary exactly when that of c is: 4 start(v).
    // A face point's corners are 4c + 2 inside: the first, 4 begin(f) + 2. An edge point's are
    // 4c + 1 and 4 next(c) + 3 for each corner c of the edge: on a boundary the walk starts at
    // 4c + 1 (its incoming half-edge is half of the edge), inside at the least of the four.
    // Old vertices keep their face count; a face point has its face's size; an edge point
    // 4 faces inside, 2 on a boundary.
    const int nv = l.nv, nf = l.nf, face_point = nv, edge_point = nv + nf;
    {
        const auto [begin, end] = ParallelBlocks::block_range(static_cast<size_t>(nv), b, blocks);
        for (int v = static_cast<int>(begin); v < static_cast<int>(end); ++v) {
            child.start[v] = l.start[v] < 0 ? -1 : 4 * l.start[v];
            child.faces[v] = l.faces[v];
        }
    }
    {
        const auto [begin, end] = ParallelBlocks::block_range(static_cast<size_t>(nf), b, blocks);
        for (int f = static_cast<int>(begin); f < static_cast<int>(end); ++f) {
            child.start[face_point + f] = 4 * F.begin(f) + 2;
            child.faces[face_point + f] = F.end(f) - F.begin(f);
        }
    }
    const auto [begin, end] = ParallelBlocks::block_range(static_cast<size_t>(l.num_edges()), b, blocks);
    for (int e = static_cast<int>(begin); e < static_cast<int>(end); ++e) {
        const int c = l.edge_corner[e], t = l.twin[c];
        int s = 4 * c + 1;
        if (t >= 0) s = std::min({s, 4 * F.next(c) + 3, 4 * t + 1, 4 * F.next(t) + 3});
        child.start[edge_point + e] = s;
        child.faces[edge_point + e] = t < 0 ? 2 : 4;
    }
}

/// A second corner takes its twin's edge number (the twin is below it, so it is the first).
inline void second_corners(Level& child, size_t b, size_t blocks) {
    const auto [begin, end] = detail::ParallelBlocks::block_range(child.twin.size(), b, blocks);
    for (int c = static_cast<int>(begin); c < static_cast<int>(end); ++c)
        if (!first_corner(child, c)) child.corner_edge[c] = child.corner_edge[child.twin[c]];
}

/// catmull_clark_step's refusal of a level past 32-bit indices.
void require_addressable(const Level& l) {
    const long long nc = l.num_corners();
    if (static_cast<long long>(l.nv) + l.nf + l.num_edges() > INT_MAX || 4 * nc > INT_MAX)
        throw InputError("the next Catmull-Clark level would have " + std::to_string(nc) +
                         " faces, more than 32-bit indices address; use fewer levels");
}

/// Whether the driver takes `mesh`: untagged, its edges implied by its faces, every coordinate
/// finite and below a quarter of the largest double. Every mask is convex (non-negative weights
/// summing to 1), so no partial sum of any level exceeds the input's largest coordinate and
/// nothing can overflow; catmull_clark_subdivide checks every level of the others.
bool streamable(const PolyMesh& mesh, int levels) {
    if (levels <= 0 || !mesh.creases.empty() || !mesh.derived.empty()) return false;
    constexpr double kLimit = std::numeric_limits<double>::max() / 4;
    const auto small = [](const std::vector<Vec3>& values) {
        for (const Vec3& q : values)
            if (!q.allFinite() || !(q.cwiseAbs().maxCoeff() < kLimit)) return false;
        return true;
    };
    return small(mesh.positions) && small(mesh.colors);
}

/// The last level's quads and face starts (quad f starts at corner 4f), appended to the result's
/// vectors on one thread while the others make the points, as Loop's triangles are
/// (append_last_triangles): vectors sized first are zeroed first (25 MB at 1.25M quads). Here
/// it measured the same time as sizing them first and writing them in chunks, on one thread and
/// on two.
template <class Faces>
void append_last_quads(const Level& l, const Faces& F, std::vector<int>& quads, std::vector<int>& face_start) {
    const size_t nc = static_cast<size_t>(l.num_corners());
    quads.clear();
    quads.reserve(4 * nc);
    detail::prefer_huge_pages(quads.data(), quads.capacity() * sizeof(int));
    face_start.clear();
    face_start.reserve(nc + 1);
    detail::prefer_huge_pages(face_start.data(), face_start.capacity() * sizeof(int));
    for (int c = 0; c < static_cast<int>(nc); ++c) {
        const std::array<int, 4> quad = child_quad(l, F, c);
        quads.insert(quads.end(), quad.begin(), quad.end());
        face_start.push_back(4 * c);
    }
    face_start.push_back(static_cast<int>(4 * nc));
}

/// One level: the points of positions and colors and the child's connectivity, in four
/// parallel regions, each pass split into one block per thread: face points and quads; edge
/// and vertex points (which read the face points) and the count of edges per block (which reads
/// the twins); the edges numbered, starts and face counts; the second corners' edges. The last
/// level: the face points, then the edge and vertex points in chunks beside the result's quads
/// and face starts (into `face_start`).
template <class Faces>
void refine_level(const Level& l, const Faces& F, const CatmullClarkOptions& o, bool last, std::vector<Vec3>& positions,
                  std::vector<Vec3>& colors, Level& child, std::vector<int>& face_start, detail::ParallelBlocks& parallel) {
    require_addressable(l);
    const std::vector<CatmullClarkVertexMask> masks = interior_masks(l);
    const int nc = l.num_corners();
    const size_t n = static_cast<size_t>(l.nv) + l.nf + l.num_edges();
    std::vector<Vec3> next, next_colors;
    detail::resize_on_huge_pages(next, n);
    if (!colors.empty()) detail::resize_on_huge_pages(next_colors, n);
    child.nv = l.nv + l.nf + l.num_edges();
    child.nf = nc;
    using detail::resize_on_huge_pages;
    const size_t blocks = parallel.blocks(static_cast<size_t>(nc));
    std::vector<std::vector<int>> rings(blocks, std::vector<int>(8));
    const auto edge_and_vertex_points = [&](size_t b, size_t of, std::vector<int>& ring) {
        edge_points(l, F, o, positions.data(), next.data(), b, of);
        vertex_points(l, F, o, masks, positions.data(), next.data(), ring, b, of);
        if (!colors.empty()) {
            edge_points(l, F, o, colors.data(), next_colors.data(), b, of);
            vertex_points(l, F, o, masks, colors.data(), next_colors.data(), ring, b, of);
        }
    };
    if (last) {
        parallel.run(blocks, [&](size_t b) {
            face_points(l, F, positions.data(), next.data(), b, blocks);
            if (!colors.empty()) face_points(l, F, colors.data(), next_colors.data(), b, blocks);
        });
        // One thread appends the result's quads and face starts (append_last_quads) while the
        // others start on the edge and vertex points; it then takes the points left.
        if (blocks > 1) {
            parallel.run_chunks_beside(
                blocks, [&] { append_last_quads(l, F, child.corner_vertex, face_start); },
                [&](size_t b, size_t c, size_t chunks) { edge_and_vertex_points(c, chunks, rings[b]); });
        } else {
            edge_and_vertex_points(0, 1, rings[0]);
            append_last_quads(l, F, child.corner_vertex, face_start);
        }
        positions = std::move(next);
        colors = std::move(next_colors);
        return;
    }
    resize_on_huge_pages(child.corner_vertex, 4 * static_cast<size_t>(nc));
    resize_on_huge_pages(child.twin, 4 * static_cast<size_t>(nc));
    resize_on_huge_pages(child.corner_edge, 4 * static_cast<size_t>(nc));
    // Two halves of every edge and one edge per corner inside each face.
    resize_on_huge_pages(child.edge_corner, 2 * static_cast<size_t>(l.num_edges()) + static_cast<size_t>(nc));
    resize_on_huge_pages(child.start, static_cast<size_t>(child.nv));
    resize_on_huge_pages(child.faces, static_cast<size_t>(child.nv));
    std::vector<int> edges(blocks + 1, 0);  // first corners before each block
    parallel.run(blocks, [&](size_t b) {
        face_points(l, F, positions.data(), next.data(), b, blocks);
        if (!colors.empty()) face_points(l, F, colors.data(), next_colors.data(), b, blocks);
        quads_block(l, F, child, b, blocks);
    });
    parallel.run(blocks, [&](size_t b) {
        edge_and_vertex_points(b, blocks, rings[b]);
        if (blocks > 1) count_edges(child, edges, b, blocks);
    });
    positions = std::move(next);
    colors = std::move(next_colors);
    // One block numbers every corner in one pass; several count their first corners first.
    for (size_t b = 1; b <= blocks && blocks > 1; ++b) edges[b] += edges[b - 1];
    parallel.run(blocks, [&](size_t b) { number_edges(l, F, child, edges, b, blocks); });
    if (edges.back() != static_cast<int>(child.edge_corner.size()))
        throw std::logic_error("a refined Catmull-Clark level has " + std::to_string(edges.back()) + " edges, not " +
                               std::to_string(child.edge_corner.size()));
    if (blocks > 1) parallel.run(blocks, [&](size_t b) { second_corners(child, b, blocks); });
}

}  // namespace

PolyMesh catmull_clark_subdivide_streaming(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels,
                                           int threads, bool* streamed) {
    detail::ParallelBlocks parallel(threads);
    if (streamed) *streamed = false;
    // The literature's other vertex rules are for naming a subject's, not for speed: the
    // closed forms below are the standard rule's.
    if (!streamable(mesh, levels) || options.vertex != CatmullClarkVertexRule::Standard)
        return catmull_clark_subdivide(mesh, options, levels);
    // A quad mesh takes the quads' closed forms from the start.
    bool quads = true;
    for (int f = 0; f <= mesh.num_faces() && quads; ++f) quads = mesh.face_start[f] == 4 * f;
    Level level;
    try {
        level = input_level(mesh, quads);
    } catch (const NonManifoldInput&) {
        // OpenSubdiv's non-manifold rules, or the refusal under NonManifoldRule::Refuse.
        return catmull_clark_subdivide(mesh, options, levels);
    }
    if (streamed) *streamed = true;
    std::vector<Vec3> positions = mesh.positions, colors = mesh.colors;
    Level child;
    PolyMesh out;
    if (quads) refine_level(level, Quads{}, options, levels == 1, positions, colors, child, out.face_start, parallel);
    else refine_level(level, Polygons{level}, options, levels == 1, positions, colors, child, out.face_start, parallel);
    for (int l = 1; l < levels; ++l) {
        std::swap(level, child);
        if (l == 1) child = Level{};  // the input level's arrays, no longer read
        refine_level(level, Quads{}, options, l + 1 == levels, positions, colors, child, out.face_start, parallel);
    }
    out.positions = std::move(positions);
    out.colors = std::move(colors);
    out.face_vertices = std::move(child.corner_vertex);
    return out;
}

}  // namespace crossdiv
