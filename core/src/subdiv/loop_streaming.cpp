#include "crossdiv/subdiv/loop_streaming.h"

#include <algorithm>
#include <climits>
#include <exception>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "finite_level.h"
#include "huge_pages.h"
#include "parallel_blocks.h"
#include "stream_twins.h"

namespace crossdiv {
namespace {

/// An array that is not initialized when made: each stream writes every element before any
/// is read, and a value-initialized std::vector would first fill the whole array with zeros
/// (measured: a tenth of a level's time). A large one is on huge pages (huge_pages.h).
template <class T>
struct Buffer {
    static_assert(std::is_trivially_destructible_v<T>);
    T* data = nullptr;
    size_t size = 0;

    /// This array as `n` elements at `at`, in an ArrayBlock's memory.
    void place(char* at, size_t n) {
        data = std::uninitialized_default_construct_n(reinterpret_cast<T*>(at), n) - n;  // no code: nothing to initialize
        size = n;
    }
    T& operator[](size_t i) { return data[i]; }
    const T& operator[](size_t i) const { return data[i]; }
};

/// One allocation for several arrays, each Buffer placed on cache lines of its own: a level's
/// arrays (the input's topology, a refined level's points and topology) are made at once at
/// their final sizes, and together they fill 2 MB pages
/// where each alone would be faulted in by 4 KB ones. Measured with the 2 MB-aligned blocks
/// (huge_pages.h), each refinement in a child process, memory returned to the kernel after each:
/// Loop to 320k and 1.28M faces, cold, 4,000 and 7,300 faults a run before, 1,600 and 1,600-2,100
/// after, 0.66-0.74x the time; warm unchanged or faster (0.93-0.95x).
class ArrayBlock {
    std::unique_ptr<char, detail::HugePagesDeleter> memory_;
    static size_t lines(size_t bytes) { return (bytes + 63) & ~size_t{63}; }

  public:
    template <class T>
    struct Part {
        Buffer<T>& array;
        size_t n;
    };
    /// `array` as `n` elements of the block.
    template <class T>
    static Part<T> part(Buffer<T>& array, size_t n) {
        return {array, n};
    }
    ArrayBlock() = default;
    template <class... T>
    explicit ArrayBlock(Part<T>... parts) {
        const size_t bytes = (lines(parts.n * sizeof(T)) + ...);
        memory_ = {static_cast<char*>(detail::allocate_on_huge_pages(bytes)), {bytes}};
        char* at = memory_.get();
        ((parts.array.place(at, parts.n), at += lines(parts.n * sizeof(T))), ...);
    }
};

/// A level's topology as the streams read it. An edge is "first" seen from the triangle that
/// numbers it (TriConnectivity::edge_corner); its ends and its first opposite vertex are read
/// from there, so that edge points sum exactly what loop_subdivide sums.
struct StreamTopology {
    /// The level's triangles: the input's, or a refined level's own (`own_triangles`).
    std::span<const Triangle> triangles;
    Buffer<Triangle> own_triangles;
    /// A refined level's points (and colours), made with its topology (the input's are the mesh's).
    Buffer<Vec3> points, point_colors;
    ArrayBlock memory;  ///< every Buffer of the level, in one allocation
    /// Per triangle corner j: (edge << 1) | side of edge j (corner j to j + 1); side 0 when this
    /// triangle is the edge's first.
    Buffer<std::array<int, 3>> tri_edges;
    Buffer<std::array<int, 2>> ends;      ///< per edge, from its first triangle's corner
    Buffer<std::array<int, 2>> opposite;  ///< per edge: in the first triangle, in the second (-1: boundary)
    Buffer<int> faces;                    ///< per vertex: triangles around it (0: isolated)
    Buffer<std::uint8_t> boundary;        ///< per vertex: on a boundary
    /// Per edge: its corner (3 triangle + corner, the edge running from that corner) in its
    /// first triangle and in its second (-1: boundary). The next level's edge-indexed arrays are
    /// written edge by edge from these, so that no two threads write one edge's entries.
    Buffer<std::array<int, 2>> edge_corners;
    /// Each vertex's edges in increasing edge order, as (edge << 1) | which end the vertex is:
    /// the vertex's entries start at incident_start[v] and number faces + boundary (a fan of
    /// f triangles has f edges inside, f + 1 on a boundary). A vertex point sums its neighbours
    /// in this order, which is the order in which a pass over the edges would meet them.
    Buffer<int> incident_start;
    Buffer<int> incident;
    int most_faces = 0;  ///< the largest face count of a vertex

    int num_vertices() const { return static_cast<int>(faces.size); }
    int num_edges() const { return static_cast<int>(ends.size); }
};

/// Whether every vertex's corners form one fan: walk forward (across each outgoing edge) from
/// the first unvisited corner and, on a boundary, backward too; a second walk at a vertex is a
/// second fan (a bowtie). Corner c's outgoing half-edge is c itself; its incoming one is the
/// half-edge before it in its triangle.
bool one_fan_per_vertex(const std::vector<Triangle>& T, int nv, const std::vector<int>& twin) {
    const int nh = static_cast<int>(twin.size());
    const auto after = [](int h) { return h % 3 == 2 ? h - 2 : h + 1; };
    const auto before = [](int h) { return h % 3 == 0 ? h + 2 : h - 1; };
    std::vector<std::uint8_t> visited(static_cast<size_t>(nh), 0), walked(static_cast<size_t>(nv), 0);
    for (int c0 = 0; c0 < nh; ++c0) {
        if (visited[c0]) continue;
        if (walked[T[c0 / 3][c0 % 3]]++) return false;
        int c = c0;
        do {
            visited[c] = 1;
            c = twin[c] < 0 ? -1 : after(twin[c]);
        } while (c >= 0 && c != c0);
        if (c < 0)
            for (c = twin[before(c0)]; c >= 0; c = twin[before(c)]) visited[c] = 1;
    }
    return true;
}

/// The input level's topology from its twins: edges numbered as build_tri_connectivity numbers
/// them (at their first corner in scan order), each vertex's face count, boundary flag and
/// incidence list. On a mesh whose vertices are not each one fan, it throws std::logic_error
/// (the ends miscounted) before it writes an incidence list, or gives a topology to discard.
StreamTopology stream_topology(const std::vector<Triangle>& T, int nv, const std::vector<int>& twin) {
    const int nf = static_cast<int>(T.size()), nh = 3 * nf;
    StreamTopology t;
    t.triangles = T;  // a view: the input outlives the refinement
    // An edge is numbered at its first half-edge: one with no twin, or the lower of the two.
    size_t ne = 0;
    for (int c = 0; c < nh; ++c) ne += twin[c] < 0 || twin[c] > c;
    const size_t vertices = static_cast<size_t>(nv);
    using Block = ArrayBlock;
    // Every array in one allocation, as a refined level's; each edge has two incidence entries.
    t.memory = ArrayBlock(Block::part(t.tri_edges, static_cast<size_t>(nf)), Block::part(t.ends, ne),
                          Block::part(t.opposite, ne), Block::part(t.edge_corners, ne), Block::part(t.faces, vertices),
                          Block::part(t.boundary, vertices), Block::part(t.incident_start, vertices),
                          Block::part(t.incident, 2 * ne));
    std::fill(t.faces.data, t.faces.data + nv, 0);
    std::fill(t.boundary.data, t.boundary.data + nv, std::uint8_t{0});
    int e = 0;
    for (int i = 0; i < nf; ++i)
        for (int j = 0; j < 3; ++j) {
            const int c = 3 * i + j, g = twin[c], a = T[i][j], b = T[i][j == 2 ? 0 : j + 1];
            ++t.faces[a];
            if (g >= 0 && g < c) {  // numbered at its twin, the first corner
                t.tri_edges[i][j] = t.tri_edges[g / 3][g % 3] | 1;
                continue;
            }
            if (g < 0) t.boundary[a] = t.boundary[b] = 1;
            t.tri_edges[i][j] = e << 1;
            t.ends[e] = {a, b};
            t.opposite[e] = {T[i][j == 0 ? 2 : j - 1], g < 0 ? -1 : T[g / 3][(g % 3 + 2) % 3]};
            t.edge_corners[e++] = {c, g};
        }
    // Each vertex's edges by a counting sort in edge order. A vertex of one fan has as many as
    // its faces, plus one on a boundary; one of two boundary fans is counted short, and the
    // total tells before any list is written.
    std::vector<int> next(static_cast<size_t>(nv));
    int total = 0;
    for (int v = 0; v < nv; ++v) {
        t.incident_start[v] = next[v] = total;
        total += t.faces[v] + t.boundary[v];
        t.most_faces = std::max(t.most_faces, t.faces[v]);
    }
    if (total != 2 * e) throw std::logic_error("streaming Loop: edge ends miscounted");
    for (int k = 0; k < e; ++k) {
        t.incident[next[t.ends[k][0]]++] = k << 1;
        t.incident[next[t.ends[k][1]]++] = (k << 1) | 1;
    }
    return t;
}

/// The input level's topology built directly, in time linear in the corners whatever the
/// valences: the half-edges bucketed by their lesser end (a counting sort), twins matched in
/// each bucket by the greater end (an array stamped with the bucket, never cleared), then the
/// topology (stream_topology) and, beside it on a second thread when there is one, the check
/// that each vertex's corners form one fan (a walk of dependent reads). nullopt when the mesh
/// is not a manifold, consistently oriented triangle mesh with valid indices:
/// build_tri_connectivity then names the element.
std::optional<StreamTopology> stream_input(const TriMesh& mesh, detail::ParallelBlocks& parallel) {
    const auto& T = mesh.triangles;
    const int nv = mesh.num_vertices(), nf = mesh.num_faces(), nh = 3 * nf;
    // Half-edge h = 3i + j runs from corner j of triangle i to corner j + 1. Its ends once:
    // lesser[h], and key[h] = 2 * greater end + (1 when it runs from the lesser end).
    std::vector<int> lesser(static_cast<size_t>(nh)), key(static_cast<size_t>(nh));
    for (int i = 0; i < nf; ++i) {
        const Triangle& t = T[i];
        if (t[0] < 0 || t[0] >= nv || t[1] < 0 || t[1] >= nv || t[2] < 0 || t[2] >= nv) return std::nullopt;
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return std::nullopt;
        for (int j = 0; j < 3; ++j) {
            const int a = t[j], b = t[j == 2 ? 0 : j + 1];
            lesser[3 * i + j] = std::min(a, b);
            key[3 * i + j] = 2 * std::max(a, b) + (a < b);
        }
    }
    std::vector<int> twin(static_cast<size_t>(nh), -1);
    if (!detail::stream_twins(nv, lesser, key, twin)) return std::nullopt;
    bool fans = true;
    StreamTopology t;
    std::exception_ptr miscounted;
    const auto task = [&](size_t b) {
        if (b == 1) {
            fans = one_fan_per_vertex(T, nv, twin);
            return;
        }
        try {
            t = stream_topology(T, nv, twin);
        } catch (const std::logic_error&) {
            miscounted = std::current_exception();  // a vertex of two fans, or a bug
        }
    };
    if (parallel.blocks(static_cast<size_t>(nh)) > 1) {
        parallel.run(2, task);
    } else {
        task(1);
        if (fans) task(0);
    }
    if (!fans) return std::nullopt;
    if (miscounted) std::rethrow_exception(miscounted);
    return t;
}

/// The input level's topology. A mesh stream_input refuses is one build_tri_connectivity
/// refuses too, naming the element; were it to accept one, the two would disagree on what a
/// manifold is, which is a bug (the fuzzers compare the two drivers' refusals).
StreamTopology input_topology(const TriMesh& mesh, detail::ParallelBlocks& parallel) {
    for (int v = 0; v < mesh.num_vertices(); ++v)
        if (!mesh.positions[v].allFinite())
            throw InputError(mesh.source.describe_vertex(v) + ": coordinate is NaN or infinite");
    if (std::optional<StreamTopology> t = stream_input(mesh, parallel)) return std::move(*t);
    (void)build_tri_connectivity(mesh);  // throws, naming the element
    throw std::logic_error("the streaming Loop driver refused a mesh build_tri_connectivity accepts");
}

/// The vertex masks by face count, for every count up to the level's largest.
struct VertexMasks {
    std::vector<VertexMask> interior, boundary;
    VertexMasks(const StreamTopology& t, const LoopOptions& o) {
        interior.resize(static_cast<size_t>(t.most_faces) + 1);
        boundary.resize(static_cast<size_t>(t.most_faces) + 1);
        for (int n = 1; n <= t.most_faces; ++n) {
            interior[n] = interior_vertex_mask(o.weights, n);
            boundary[n] = boundary_vertex_mask(o.boundary, n);
        }
    }
};

/// One level's points: the vertex points at 0..nv-1, the edge points at nv + e, in `out` (which
/// holds nv + ne points). The edge points read the edge's ends and opposite vertices; a vertex
/// point sums its neighbours (on a boundary, its two boundary neighbours) along its incidence
/// list, in edge order. This call writes block b of `blocks` of the edges and of the vertices;
/// every point is written by one block, so the blocks run on any number of threads with the
/// same result. `Tuned`: the tuned families' edge masks, which read the ends' valences.
template <bool Tuned>
void level_points(const StreamTopology& t, const LoopOptions& o, const VertexMasks& masks, const Vec3* p, Vec3* out,
                  size_t b, size_t blocks) {
    const int nv = t.num_vertices();
    const std::uint8_t* bnd = t.boundary.data;
    const std::array<int, 2>* ends = t.ends.data;
    const std::array<int, 2>* opposite = t.opposite.data;
    const int* faces = t.faces.data;
    const TunedEdgeMask plain = tuned_edge_mask(o.weights, 0, 0);
    const double half = boundary_edge_mask().end;
    Vec3* edge_points = out + nv;
    {
        const auto [begin, end] = detail::ParallelBlocks::block_range(t.ends.size, b, blocks);
        for (size_t e = begin; e < end; ++e) {
            const int a = ends[e][0], b = ends[e][1], c = opposite[e][0], d = opposite[e][1];
            const Vec3 &pa = p[a], &pb = p[b];
            if (d < 0) {
                edge_points[e] = half * (pa + pb);
                continue;
            }
            // (a + b) and (c + d) summed first, then scaled (loop.cpp's stencil_sum).
            if constexpr (Tuned) {
                const TunedEdgeMask m = tuned_edge_mask(o.weights, tuned_edge_valence(faces[a], bnd[a]),
                                                        tuned_edge_valence(faces[b], bnd[b]));
                if (m.end_a == m.end_b) edge_points[e] = m.end_a * (pa + pb) + m.opposite * (p[c] + p[d]);
                else edge_points[e] = m.end_a * pa + m.opposite * (p[c] + p[d]) + m.end_b * pb;
            } else {
                edge_points[e] = plain.end_a * (pa + pb) + plain.opposite * (p[c] + p[d]);
            }
        }
    }
    const int* start = t.incident_start.data;
    const int* incident = t.incident.data;
    {
        const auto [begin, end] = detail::ParallelBlocks::block_range(static_cast<size_t>(nv), b, blocks);
        for (size_t v = begin; v < end; ++v) {
            const int f = faces[v];
            if (f == 0) {  // isolated: nothing to average with, it stays
                out[v] = p[v];
                continue;
            }
            // An interior vertex sums every neighbour, a boundary vertex its two boundary
            // neighbours (the ends of its boundary edges).
            const int* it = incident + start[v];
            Vec3 sum = Vec3::Zero();
            if (!bnd[v]) {
                for (int k = 0; k < f; ++k) sum += p[ends[it[k] >> 1][1 - (it[k] & 1)]];
            } else {
                for (int k = 0; k <= f; ++k)
                    if (opposite[it[k] >> 1][1] < 0) sum += p[ends[it[k] >> 1][1 - (it[k] & 1)]];
            }
            const VertexMask m = bnd[v] ? masks.boundary[f] : masks.interior[f];
            out[v] = m.neighbor != 0.0 ? Vec3(m.self * p[v] + m.neighbor * sum) : Vec3(m.self * p[v]);
        }
    }
}

/// The largest coordinate magnitude of `p`. The masks are convex (every weight in [0, 1], summing
/// to 1), so no refined point is larger than the input's largest M, at any level.
double largest_coordinate(std::span<const Vec3> p) {
    double largest = 0;
    for (const Vec3& q : p) largest = std::max(largest, q.cwiseAbs().maxCoeff());
    return largest;
}

/// Whether a level's points may overflow, from the input's largest coordinate M: a partial sum
/// is at most (largest valence + 2) M. Below this bound none can be infinite and the check after
/// the level is skipped.
bool may_overflow(double largest, const VertexMasks& masks) {
    const double terms = static_cast<double>(masks.interior.size() + 2);
    return !(largest * terms < std::numeric_limits<double>::max() / 4);  // NaN: a NaN input (refused before)
}

/// The arrays of the next level but the last: its points (and colours when `colored`), triangles
/// and the rest of its topology, in one ArrayBlock. The last level's are the result's vectors.
void allocate_child(const StreamTopology& t, bool colored, StreamTopology& child) {
    const size_t nv = static_cast<size_t>(t.num_vertices()), ne = static_cast<size_t>(t.num_edges()), nf = t.triangles.size();
    const size_t edges = 2 * ne + 3 * nf, vertices = nv + ne;
    using Block = ArrayBlock;
    // An edge vertex has 6 incidence slots (4 used on a boundary), after the old vertices' entries.
    child.memory = ArrayBlock(Block::part(child.points, vertices), Block::part(child.point_colors, colored ? vertices : 0),
                              Block::part(child.own_triangles, 4 * nf), Block::part(child.tri_edges, 4 * nf),
                              Block::part(child.ends, edges), Block::part(child.opposite, edges),
                              Block::part(child.edge_corners, edges), Block::part(child.faces, vertices),
                              Block::part(child.boundary, vertices), Block::part(child.incident_start, vertices),
                              Block::part(child.incident, t.incident.size + 6 * ne));
    child.triangles = std::span<const Triangle>(child.own_triangles.data, 4 * nf);
    child.most_faces = std::max(t.most_faces, 6);
}

/// Triangle i's four children (loop.h's numbering) into `out`.
inline void child_triangles(const StreamTopology& t, size_t i, Triangle* out) {
    const int nv = t.num_vertices();
    const Triangle& v = t.triangles[i];
    const std::array<int, 3>& te = t.tri_edges[i];
    const int m0 = nv + (te[0] >> 1), m1 = nv + (te[1] >> 1), m2 = nv + (te[2] >> 1);
    out[0] = {v[0], m0, m2};
    out[1] = {v[1], m1, m0};
    out[2] = {v[2], m2, m1};
    out[3] = {m0, m1, m2};
}

/// The last level's triangles, appended to the result's vector on one thread: a vector sized
/// first is zeroed first, a second pass over the level's largest array (measured 5.5 ms against
/// 3.5 ms for 1.28M triangles), and on several threads it costs more to size it on one and write
/// its parts on all than to append it on one while the others make the points (0.91-0.94x).
void append_last_triangles(const StreamTopology& t, std::vector<Triangle>& out) {
    out.clear();
    out.reserve(4 * t.triangles.size());
    detail::prefer_huge_pages(out.data(), out.capacity() * sizeof(Triangle));
    Triangle four[4];
    for (size_t i = 0; i < t.triangles.size(); ++i) {
        child_triangles(t, i, four);
        out.insert(out.end(), four, four + 4);
    }
}

/// Block b of `blocks` of the next level but the last (allocate_child): its triangles and the
/// rest of its topology. Each element is written by one block: a triangle writes its children
/// and its interior edges, an edge its halves and its new vertex (reading its one or two
/// triangles), an old vertex its own entries.
void refine_topology(const StreamTopology& t, StreamTopology& child, size_t b, size_t blocks) {
    using detail::ParallelBlocks;
    const int nv = t.num_vertices(), ne = t.num_edges();
    const auto [f0, f1] = ParallelBlocks::block_range(t.triangles.size(), b, blocks);
    for (size_t i = f0; i < f1; ++i) child_triangles(t, i, &child.own_triangles[4 * i]);
    const size_t old_entries = t.incident.size;
    // What each triangle's children own: their edges, and the three interior edges.
    for (size_t i = f0; i < f1; ++i) {
        const Triangle& v = t.triangles[i];
        const std::array<int, 3>& te = t.tri_edges[i];
        const int E[3] = {te[0] >> 1, te[1] >> 1, te[2] >> 1}, s[3] = {te[0] & 1, te[1] & 1, te[2] & 1};
        const int m[3] = {nv + E[0], nv + E[1], nv + E[2]};
        std::array<int, 3>* cte = &child.tri_edges[4 * i];
        const int interior = 2 * ne + 3 * static_cast<int>(i), first_child = 4 * static_cast<int>(i);
        for (int k = 0; k < 3; ++k) {
            const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            // Edge k runs v_k -> v_k1 here; its half at v_k is 2E + s (the halves keep the
            // first triangle's direction), at v_k1 2E + 1 - s. Corner child k = (v_k, m_k,
            // m_k2): the half of edge k at v_k, the interior edge k2 backwards, the half of
            // edge k2 at v_k. The centre child's edge k is interior edge k, which it sees
            // first.
            cte[k] = {((2 * E[k] + s[k]) << 1) | s[k], ((interior + k2) << 1) | 1,
                      ((2 * E[k2] + 1 - s[k2]) << 1) | s[k2]};
            cte[3][k] = (interior + k) << 1;
            // Interior edge k = (m_k, m_k1): first in the centre child (opposite m_k2, its
            // corner k), second in corner child k1 (opposite v_k1, its corner 1).
            child.ends[interior + k] = {m[k], m[k1]};
            child.opposite[interior + k] = {m[k2], v[k1]};
            child.edge_corners[interior + k] = {3 * (first_child + 3) + k, 3 * (first_child + k1) + 1};
        }
    }
    // What each edge owns: its two halves and its new vertex, read from its one or two
    // triangles. Old vertices keep their face count, boundary flag and incidence list, whose
    // edges are now the halves at them (edge E at its end s: half 2E + s, at the same end).
    {
        const auto [begin, end] = ParallelBlocks::block_range(static_cast<size_t>(nv), b, blocks);
        std::copy(t.faces.data + begin, t.faces.data + end, child.faces.data + begin);
        std::copy(t.boundary.data + begin, t.boundary.data + end, child.boundary.data + begin);
        std::copy(t.incident_start.data + begin, t.incident_start.data + end,
                  child.incident_start.data + begin);
    }
    {
        const auto [begin, end] = ParallelBlocks::block_range(old_entries, b, blocks);
        for (size_t j = begin; j < end; ++j) {
            const int e = t.incident[j], side = e & 1;
            child.incident[j] = ((2 * (e >> 1) + side) << 1) | side;
        }
    }
    const auto [begin, end] = ParallelBlocks::block_range(static_cast<size_t>(ne), b, blocks);
    for (size_t e = begin; e < end; ++e) {
        const int E = static_cast<int>(e), m = nv + E;
        const std::array<int, 2> corners = t.edge_corners[e];
        const bool on_boundary = corners[1] < 0;
        child.ends[2 * e] = {t.ends[e][0], m};
        child.ends[2 * e + 1] = {m, t.ends[e][1]};
        // A new edge vertex has 6 triangles round it inside, 3 on a boundary edge. Its
        // incidence list in edge order: the halves (it ends the first, starts the second),
        // then the two interior edges of each triangle, the lower-numbered triangle's first.
        child.faces[m] = on_boundary ? 3 : 6;
        child.boundary[m] = on_boundary;
        const size_t first = old_entries + 6 * e;
        child.incident_start[m] = static_cast<int>(first);
        child.incident[first] = ((2 * E) << 1) | 1;
        child.incident[first + 1] = (2 * E + 1) << 1;
        if (on_boundary) {
            child.opposite[2 * e][1] = child.opposite[2 * e + 1][1] = -1;
            child.edge_corners[2 * e][1] = child.edge_corners[2 * e + 1][1] = -1;
            child.incident[first + 4] = child.incident[first + 5] = 0;  // unused, defined
        }
        for (int s = 0; s < (on_boundary ? 1 : 2); ++s) {
            const int i = corners[s] / 3, k = corners[s] % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            const std::array<int, 3>& te = t.tri_edges[i];
            // In triangle i the edge is its edge k, the half 2E + s at v_k (in corner child
            // k, its corner 0) and 2E + 1 - s at v_k1 (in corner child k1, its corner 2),
            // opposite the midpoints of the triangle's other two edges.
            child.opposite[2 * e + s][s] = nv + (te[k2] >> 1);
            child.opposite[2 * e + 1 - s][s] = nv + (te[k1] >> 1);
            child.edge_corners[2 * e + s][s] = 3 * (4 * i + k);
            child.edge_corners[2 * e + 1 - s][s] = 3 * (4 * i + k1) + 2;
            // m_k's interior edges in triangle i: k (its first end), k2 (its second).
            const int interior = 2 * ne + 3 * i;
            const bool lower = on_boundary || i < corners[1 - s] / 3;
            int* slot = &child.incident[first + (lower ? 2 : 4)];
            const int ek = (interior + k) << 1, ek2 = ((interior + k2) << 1) | 1;
            slot[0] = k < k2 ? ek : ek2;
            slot[1] = k < k2 ? ek2 : ek;
        }
    }
}

void require_addressable(const StreamTopology& t) {
    const long long nf = static_cast<long long>(t.triangles.size()), nv = t.num_vertices(), ne = t.num_edges();
    // Indices are int, as loop_refine_once refuses; an edge id also takes a side bit.
    // The next level's incidence lists: this level's entries and 6 per edge.
    const long long entries = static_cast<long long>(t.incident.size) + 6 * ne;
    if (4 * nf > INT_MAX || 3 * (4 * nf) > INT_MAX || nv + ne > INT_MAX || 2 * (2 * ne + 3 * nf) > INT_MAX ||
        entries > INT_MAX)
        throw InputError("the next Loop level would have " + std::to_string(4 * nf) +
                         " faces, more than 32-bit indices address; use fewer levels");
}

}  // namespace

TriMesh loop_subdivide_streaming(const TriMesh& mesh, const LoopOptions& options, int levels, int threads) {
    if (levels < 0) throw InputError("number of levels must be >= 0, got " + std::to_string(levels));
    detail::ParallelBlocks parallel(threads);
    TriMesh out;
    if (levels == 0) {
        out.positions = mesh.positions;
        out.colors = mesh.colors;
        out.triangles = mesh.triangles;
        return out;
    }
    StreamTopology topology = input_topology(mesh, parallel);
    const bool colored = !mesh.colors.empty();
    const double largest = largest_coordinate(mesh.positions), largest_color = largest_coordinate(mesh.colors);
    // Each level's points: the input's, then a refined level's (made with its topology), and
    // the result's vectors for the last.
    std::span<const Vec3> positions = mesh.positions, colors = mesh.colors;
    const auto points = has_tuned_edges(options.weights) ? level_points<true> : level_points<false>;
    for (int l = 0; l < levels; ++l) {
        require_addressable(topology);
        const bool last = l + 1 == levels;  // the last level: its triangles only
        const VertexMasks masks(topology, options);
        const size_t n = static_cast<size_t>(topology.num_vertices()) + topology.num_edges();
        StreamTopology child;
        const size_t blocks = parallel.blocks(static_cast<size_t>(topology.num_edges()));
        if (!last) allocate_child(topology, colored, child);
        if (last) {
            detail::resize_on_huge_pages(out.positions, n);
            if (colored) detail::resize_on_huge_pages(out.colors, n);
        }
        Vec3* next = last ? out.positions.data() : child.points.data;
        Vec3* next_color = last ? out.colors.data() : child.point_colors.data;
        const auto points_of = [&](size_t b, size_t of) {
            points(topology, options, masks, positions.data(), next, b, of);
            if (colored) points(topology, options, masks, colors.data(), next_color, b, of);
        };
        if (last) {
            // One thread appends the result's triangles (append_last_triangles) while the
            // others start on the points; it then takes the points left.
            if (blocks > 1) {
                parallel.run_chunks_beside(blocks, [&] { append_last_triangles(topology, out.triangles); },
                                             [&](size_t, size_t c, size_t chunks) { points_of(c, chunks); });
            } else {
                points_of(0, 1);
                append_last_triangles(topology, out.triangles);
            }
        } else {
            // Every pass of the level in one parallel region, each block taking its share of
            // each (the passes read this level only and write disjoint parts of the next).
            parallel.run(blocks, [&](size_t b) {
                points_of(b, blocks);
                refine_topology(topology, child, b, blocks);
            });
        }
        if (may_overflow(largest, masks)) detail::require_finite_level({next, n}, positions, l + 1);
        if (colored && may_overflow(largest_color, masks)) detail::require_finite_level({next_color, n}, colors, l + 1);
        if (last) break;
        topology = std::move(child);
        positions = {topology.points.data, n};
        colors = {topology.point_colors.data, topology.point_colors.size};
    }
    return out;
}

}  // namespace crossdiv
