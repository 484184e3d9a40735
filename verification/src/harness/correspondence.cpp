#include "crossdiv/verification/harness/correspondence.h"

#include <algorithm>
#include <cmath>
#include <bit>
#include <cstdint>
#include <limits>
#include <numeric>
#include <span>
#include <string>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/harness/nearest_points.h"

namespace crossdiv::verification {
namespace {

/// Where a refined vertex of a primal scheme comes from, named in our coarse numbering: an
/// old vertex {-1, v}; a face point {face, -1}; an edge point {face, k}, k the edge's place
/// in the face (counted from its canonical first corner, least_rotation), `face` the
/// lowest-numbered of our coarse faces around the edge. The face tells apart two edges with
/// the same ends (a pillow's refined levels have them, and a face that names a pair twice)
/// and the face points of two faces with the same corners in opposite orders (polygons back
/// to back).
struct Provenance {
    int face, local;
    bool operator==(const Provenance&) const = default;
};

/// Our coarse faces by their canonical oriented corner cycle (listed from its least
/// rotation), in a flat open-addressing table: a refinement names one parent per child face,
/// millions of them, looked up with no list made per face. Of a cycle listed twice (a
/// duplicate face) the first: the copies' edges are the same edges, and their children are
/// told apart only by symmetry (match_next_level pairs them in order).
class FaceIndex {
public:
    explicit FaceIndex(const PolyMesh& coarse) : coarse_(coarse), first_(static_cast<size_t>(coarse.num_faces())) {
        slots_.assign(std::bit_ceil(2 * first_.size() + 2), -1);
        for (int f = 0; f < coarse.num_faces(); ++f) {
            const std::span<const int> cycle = face(f);
            first_[static_cast<size_t>(f)] = least_rotation(cycle);
            size_t at = slot(cycle, first_[static_cast<size_t>(f)]);
            if (slots_[at] < 0) slots_[at] = f;
        }
    }

    /// Our first face whose cycle, listed from its least rotation, is `cycle` listed from
    /// `first`; -1 when we have none.
    int find(std::span<const int> cycle, size_t first) const { return slots_[slot(cycle, first)]; }

private:
    std::span<const int> face(int f) const { return {coarse_.face(f), static_cast<size_t>(coarse_.face_size(f))}; }

    /// The slot of `cycle` from `first`: the one holding its face, or the empty one where it would go.
    size_t slot(std::span<const int> cycle, size_t first) const {
        const size_t n = cycle.size(), mask = slots_.size() - 1;
        uint64_t h = n;
        for (size_t k = 0; k < n; ++k) h = (h ^ static_cast<uint32_t>(cycle[(first + k) % n])) * 0x100000001B3ull;
        for (size_t at = static_cast<size_t>(h ^ (h >> 31)) & mask;; at = (at + 1) & mask) {
            const int f = slots_[at];
            if (f < 0 || same_cycle(f, cycle, first)) return at;
        }
    }

    bool same_cycle(int f, std::span<const int> cycle, size_t first) const {
        const std::span<const int> ours = face(f);
        const size_t n = cycle.size(), from = first_[static_cast<size_t>(f)];
        if (ours.size() != n) return false;
        for (size_t k = 0; k < n; ++k)
            if (ours[(from + k) % n] != cycle[(first + k) % n]) return false;
        return true;
    }

    const PolyMesh& coarse_;
    std::vector<size_t> first_;  ///< per face: where its least rotation starts
    std::vector<int> slots_;     ///< a face, or -1; a power of two, at most half full
};

std::string cycle_text(const std::vector<int>& cycle) {
    std::string s = "(";
    for (size_t i = 0; i < cycle.size(); ++i) s.append(i ? " " : "").append(std::to_string(cycle[i]));
    return s.append(")");
}

/// The provenance of every vertex of `fine`, a primal refinement (each triangle split into
/// four, or each n-gon into n quads around a face point) whose first to_ours.size() vertices
/// are the coarse ones, named through `to_ours`. Each child face holding one coarse vertex
/// names its parent: a corner triangle (a, e_ab, e_ca) the face (a, b, c); the quads around
/// a face point the face of their coarse corners, in order. An edge point has two coarse
/// neighbours, or one when its edge is degenerate (a face naming a vertex twice in a row).
/// Empty, with `why`, when `fine` is not such a refinement of faces we have.
std::vector<Provenance> read_provenance(const PolyMesh& fine, const std::vector<int>& to_ours,
                                        const FaceIndex& our_faces, std::string& why) {
    const int n_old = static_cast<int>(to_ours.size()), n = fine.num_vertices();
    if (n < n_old) {
        why = std::to_string(n) + " vertices, fewer than the " + std::to_string(n_old) + " of the level before";
        return {};
    }
    // The coarse neighbours of each new vertex: two (or one) for an edge point, none for a face point.
    std::vector<std::array<int, 2>> old_neighbors(static_cast<size_t>(n), {-1, -1});
    std::vector<int> old_count(static_cast<size_t>(n), 0);
    for (auto [a, b] : mesh_topology(fine).edge_list) {
        if (a < n_old && b < n_old) {
            why = "old vertices " + std::to_string(a) + " and " + std::to_string(b) + " are adjacent";
            return {};
        }
        for (auto [v, w] : {std::pair{a, b}, std::pair{b, a}})
            if (v >= n_old && w < n_old && old_count[v]++ < 2) old_neighbors[v][old_count[v] - 1] = w;
    }
    const auto other_end = [&](int edge_point, int end) {
        const auto& ab = old_neighbors[static_cast<size_t>(edge_point)];
        switch (old_count[static_cast<size_t>(edge_point)]) {
            case 1: return ab[0] == end ? end : -1;  // a degenerate edge (end, end)
            case 2: return ab[0] == end ? ab[1] : ab[1] == end ? ab[0] : -1;
            default: return -1;
        }
    };

    constexpr int kNone = std::numeric_limits<int>::max();
    std::vector<Provenance> edge_of(static_cast<size_t>(n), {kNone, -1});
    std::vector<int> face_of(static_cast<size_t>(n), kNone);
    // Names parent `fine_listing` (coarse corners in fine numbering) and puts each edge point
    // given as (vertex, place in the listing) on its edge.
    std::vector<int> listing;  // the parent in our numbering; reused, one parent per child face
    const auto name_parent = [&](std::span<const int> fine_listing, int child, std::span<const std::pair<int, int>> points,
                                 int face_point) {
        listing.clear();
        for (int v : fine_listing) listing.push_back(to_ours[static_cast<size_t>(v)]);
        const size_t start = least_rotation(listing);
        const int p = our_faces.find(listing, start);
        if (p < 0) {
            why = "face " + std::to_string(child) + " is a child of " + cycle_text(listing) + ", not a face of ours";
            return false;
        }
        const int m = static_cast<int>(listing.size());
        for (auto [v, place] : points) {
            const Provenance here{p, (place - static_cast<int>(start) + m) % m};
            Provenance& e = edge_of[static_cast<size_t>(v)];
            if (p < e.face) e = here;
        }
        if (face_point >= 0) face_of[static_cast<size_t>(face_point)] = p;
        return true;
    };

    struct Corner { int face_point, a, next, prev, child; };  // quad (a, next, face_point, prev)
    std::vector<Corner> quads;
    for (int f = 0; f < fine.num_faces(); ++f) {
        const int* c = fine.face(f);
        const int m = fine.face_size(f);
        int corner = -1, corners = 0;
        for (int k = 0; k < m; ++k)
            if (c[k] < n_old) corner = k, ++corners;
        if (corners == 0) continue;  // a Loop centre triangle: its vertices are in corner ones too
        if (corners > 1 || (m != 3 && m != 4)) {
            why = "face " + std::to_string(f) + " has " + std::to_string(m) + " corners, " + std::to_string(corners) +
                  " of them old: not a child of a triangle or quad split";
            return {};
        }
        const int a = c[corner], x = c[(corner + 1) % m], y = c[(corner + m - 1) % m];
        if (m == 4) {
            quads.push_back({c[(corner + 2) % m], a, x, y, f});
            continue;
        }
        const int b = other_end(x, a), cc = other_end(y, a);
        if (b < 0 || cc < 0) {
            why = "triangle " + std::to_string(f) + " at old vertex " + std::to_string(a) + " is not a corner child";
            return {};
        }
        const int parent[3] = {a, b, cc};
        const std::pair<int, int> edge_points[2] = {{x, 0}, {y, 2}};
        if (!name_parent(parent, f, edge_points, -1)) return {};
    }
    // Quads by face point, each group chained around it: quad i's next edge point is quad
    // i+1's previous one.
    std::sort(quads.begin(), quads.end(), [](const Corner& l, const Corner& r) {
        return l.face_point != r.face_point ? l.face_point < r.face_point : l.prev < r.prev;
    });
    std::vector<int> corners;  // of one face point's parent, in fine numbering
    std::vector<std::pair<int, int>> edge_points;  // its edge points with their places in `corners`
    for (size_t s = 0, e = 0; s < quads.size(); s = e) {
        while (e < quads.size() && quads[e].face_point == quads[s].face_point) ++e;
        const auto group = std::span(quads).subspan(s, e - s);
        corners.clear();
        edge_points.clear();
        for (size_t at = 0, steps = 0; steps < group.size(); ++steps) {
            // quad `at`'s next edge point is on the listing's edge `steps`
            edge_points.emplace_back(group[at].next, static_cast<int>(steps));
            corners.push_back(group[at].a);
            const int next_edge_point = group[at].next;
            const auto it = std::lower_bound(group.begin(), group.end(), next_edge_point,
                                             [](const Corner& q, int v) { return q.prev < v; });
            at = static_cast<size_t>(it - group.begin());
            // One ring: back at the first quad after exactly group.size() steps, not before.
            if (it == group.end() || it->prev != next_edge_point || (at == 0) != (steps + 1 == group.size())) {
                why = "the quads around face point " + std::to_string(group[0].face_point) + " do not make one ring";
                return {};
            }
        }
        if (!name_parent(corners, group[0].child, edge_points, group[0].face_point)) return {};
    }

    std::vector<Provenance> out(static_cast<size_t>(n));
    for (int v = 0; v < n; ++v) {
        if (v < n_old) {
            out[v] = {-1, to_ours[v]};
        } else if (old_count[v] == 0 && face_of[v] != kNone) {
            out[v] = {face_of[v], -1};
        } else if ((old_count[v] == 1 || old_count[v] == 2) && edge_of[v].face != kNone) {
            out[v] = edge_of[v];
        } else {
            why = "new vertex " + std::to_string(v) + " has " + std::to_string(old_count[v]) +
                  " old neighbours and is in no corner face that names it";
            return {};
        }
    }
    return out;
}

/// The copies that vertices sharing their provenance with others belong to: such vertices
/// are joined when they share a face. Per vertex, its copy as a list of its members sorted by
/// (provenance, index); -1 for a vertex whose provenance is its own.
struct Copies {
    std::vector<int> of;                   ///< per vertex: its copy, or -1
    std::vector<std::vector<int>> members;  ///< per copy, ordered by its smallest vertex
};

Copies group_copies(const PolyMesh& fine, const std::vector<Provenance>& provenance, const std::vector<char>& shared) {
    const size_t n = provenance.size();
    std::vector<int> root(n);
    std::iota(root.begin(), root.end(), 0);
    const auto find = [&](int x) {
        while (root[static_cast<size_t>(x)] != x) x = root[static_cast<size_t>(x)] = root[static_cast<size_t>(root[static_cast<size_t>(x)])];
        return x;
    };
    for (int f = 0; f < fine.num_faces(); ++f) {
        int last = -1;
        for (int k = 0; k < fine.face_size(f); ++k) {
            const int v = fine.face(f)[k];
            if (!shared[static_cast<size_t>(v)]) continue;
            if (last >= 0) root[static_cast<size_t>(find(v))] = find(last);
            last = v;
        }
    }
    Copies c;
    c.of.assign(n, -1);
    std::vector<int> copy_of_root(n, -1);
    for (size_t v = 0; v < n; ++v) {
        if (!shared[v]) continue;
        int& id = copy_of_root[static_cast<size_t>(find(static_cast<int>(v)))];
        if (id < 0) {
            id = static_cast<int>(c.members.size());
            c.members.emplace_back();
        }
        c.of[v] = id;
        c.members[static_cast<size_t>(id)].push_back(static_cast<int>(v));
    }
    for (std::vector<int>& m : c.members)
        std::stable_sort(m.begin(), m.end(), [&](int x, int y) {
            return std::pair{provenance[x].face, provenance[x].local} < std::pair{provenance[y].face, provenance[y].local};
        });
    return c;
}

/// Recovers level k+1 of the reference from level k's map by provenance; returns a reason on
/// failure. Vertices that share their provenance (the children of a duplicate face's copies,
/// which only the symmetry swapping the copies tells apart) are matched copy by copy: a
/// reference copy takes the first of ours with the same provenances, so that the map stays
/// one symmetry; `symmetric` counts them.
std::string match_next_level(const std::vector<int>& prev, const PolyMesh& our_coarse, const PolyMesh& our_fine,
                             const PolyMesh& ref_fine, std::vector<int>& next, int& symmetric) {
    if (ref_fine.num_vertices() != our_fine.num_vertices())
        return "reference has " + std::to_string(ref_fine.num_vertices()) + " vertices, ours " +
               std::to_string(our_fine.num_vertices());
    const FaceIndex faces(our_coarse);
    std::vector<int> identity(static_cast<size_t>(our_coarse.num_vertices()));
    std::iota(identity.begin(), identity.end(), 0);
    std::string why;
    const std::vector<Provenance> ours = read_provenance(our_fine, identity, faces, why);
    if (ours.empty()) return "our level: " + why;
    const std::vector<Provenance> theirs = read_provenance(ref_fine, prev, faces, why);
    if (theirs.empty()) return why;

    // Our vertex of each provenance, in one array with a place for every old vertex, face and
    // corner of our coarse level (an edge point is named by a face and an edge of it, and a
    // face's edges are its corners): kAbsent, kShared (several of ours), or the vertex.
    constexpr int kAbsent = -2, kShared = -1;
    const size_t n_vertices = static_cast<size_t>(our_coarse.num_vertices()), n_faces = static_cast<size_t>(our_coarse.num_faces());
    const auto place = [&](const Provenance& p) {
        if (p.face < 0) return static_cast<size_t>(p.local);
        if (p.local < 0) return n_vertices + static_cast<size_t>(p.face);
        return n_vertices + n_faces + static_cast<size_t>(our_coarse.face_start[static_cast<size_t>(p.face)] + p.local);
    };
    std::vector<int> our_vertex(n_vertices + n_faces + our_coarse.face_vertices.size(), kAbsent);
    for (size_t i = 0; i < ours.size(); ++i) {
        int& at = our_vertex[place(ours[i])];
        at = at == kAbsent ? static_cast<int>(i) : kShared;
    }
    std::vector<char> our_shared(ours.size()), their_shared(theirs.size());
    for (size_t i = 0; i < ours.size(); ++i) our_shared[i] = our_vertex[place(ours[i])] == kShared;
    next.assign(theirs.size(), -1);
    for (size_t v = 0; v < theirs.size(); ++v) {
        const int ours_at = our_vertex[place(theirs[v])];
        if (ours_at == kAbsent) return "new vertex " + std::to_string(v) + " sits on an edge or face we do not have";
        their_shared[v] = ours_at == kShared;
        if (!their_shared[v]) next[v] = ours_at;
    }
    if (std::find(our_shared.begin(), our_shared.end(), 1) != our_shared.end()) {
        const Copies our_copies = group_copies(our_fine, ours, our_shared);
        const Copies their_copies = group_copies(ref_fine, theirs, their_shared);
        const auto same = [&](const std::vector<int>& mine, const std::vector<int>& other) {
            if (mine.size() != other.size()) return false;
            for (size_t k = 0; k < mine.size(); ++k)
                if (!(ours[static_cast<size_t>(mine[k])] == theirs[static_cast<size_t>(other[k])])) return false;
            return true;
        };
        std::vector<char> taken(our_copies.members.size(), 0);
        for (const std::vector<int>& copy : their_copies.members) {
            size_t match = 0;
            while (match < taken.size() && (taken[match] || !same(our_copies.members[match], copy))) ++match;
            if (match == taken.size())
                return "reference vertex " + std::to_string(copy.front()) +
                       " shares its provenance with others, in a group none of ours matches";
            taken[match] = 1;
            for (size_t k = 0; k < copy.size(); ++k) next[static_cast<size_t>(copy[k])] = our_copies.members[match][k];
            symmetric += static_cast<int>(copy.size());
        }
    }
    std::vector<char> used(ours.size(), 0);
    for (size_t v = 0; v < next.size(); ++v) {
        if (next[v] < 0) return "reference vertex " + std::to_string(v) + " is left without a match";
        if (used[static_cast<size_t>(next[v])]++) return "two reference vertices map to our vertex " + std::to_string(next[v]);
    }
    return "";
}

/// Each vertex's corners in face order, in flat lists: the face of each and the corner after it
/// in its face (the end of the vertex's outgoing edge there). Built once per match.
struct CornersAround {
    std::vector<int> first, face, next;

    explicit CornersAround(const PolyMesh& m)
        : first(static_cast<size_t>(m.num_vertices()) + 1, 0), face(m.face_vertices.size()), next(m.face_vertices.size()) {
        for (int v : m.face_vertices) ++first[static_cast<size_t>(v) + 1];
        std::partial_sum(first.begin(), first.end(), first.begin());
        std::vector<int> fill(first.begin(), first.end() - 1);
        for (int f = 0; f < m.num_faces(); ++f)
            for (int k = 0, size = m.face_size(f); k < size; ++k) {
                const size_t at = static_cast<size_t>(fill[static_cast<size_t>(m.face(f)[k])]++);
                face[at] = f;
                next[at] = m.face(f)[(k + 1) % size];
            }
    }

    /// The face of directed edge a->b (of two, the last), -1 when none.
    int face_of_edge(int a, int b) const {
        for (int i = first[static_cast<size_t>(a) + 1]; i-- > first[static_cast<size_t>(a)];)
            if (next[static_cast<size_t>(i)] == b) return face[static_cast<size_t>(i)];
        return -1;
    }
};

/// Our vertices at one place with the nearest to `at`: as near as it up to `tie`, at most 8.
std::span<const unsigned> copies_at(const NearestPoints& index, const Vec3& at, double tie, unsigned (&found)[8]) {
    double found_d2[8];
    return {found, index.nearest_within(at, 8, tie, found, found_d2)};
}

/// For match_nearest_and_faces: a reference face none of whose edges is matched yet (the two
/// copies of a double-sided face, a duplicated component: every corner has copies of ours at
/// its place) is placed on one of our faces whose corners, in the same cyclic order, are each
/// among the copies nearest its corner, free or already its own. The cyclic order tells a face
/// from its reversed copy. Returns whether it placed a vertex.
bool place_faces_of_copies(const PolyMesh& ours, const CornersAround& around, const PolyMesh& ref, const NearestPoints& index,
                           const std::vector<double>& d2, double tie, std::vector<int>& map, std::vector<int>& taken_by) {
    if (std::find(map.begin(), map.end(), -1) == map.end()) return false;
    const auto fits = [&](int r, int u) {
        return map[static_cast<size_t>(r)] >= 0 ? map[static_cast<size_t>(r)] == u
                                                : taken_by[static_cast<size_t>(u)] < 0 &&
                                                      as_near_as((ours.positions[static_cast<size_t>(u)] - ref.positions[static_cast<size_t>(r)]).squaredNorm(),
                                                                 d2[static_cast<size_t>(r)], tie);
    };
    bool placed = false;
    for (int f = 0; f < ref.num_faces(); ++f) {
        const int m = ref.face_size(f);
        const int* rf = ref.face(f);
        if (std::all_of(rf, rf + m, [&](int r) { return map[static_cast<size_t>(r)] >= 0; })) continue;
        unsigned found[8];
        const int r0 = rf[0];
        const std::span<const unsigned> starts =
            map[static_cast<size_t>(r0)] >= 0
                ? std::span<const unsigned>(found, (found[0] = static_cast<unsigned>(map[static_cast<size_t>(r0)]), 1))
                : copies_at(index, ref.positions[static_cast<size_t>(r0)], tie, found);
        bool done = false;
        for (const unsigned v : starts) {
            for (int i = around.first[v]; i < around.first[v + 1] && !done; ++i) {
                const int g = around.face[static_cast<size_t>(i)];
                if (ours.face_size(g) != m) continue;
                const int* og = ours.face(g);
                const int at = static_cast<int>(std::find(og, og + m, static_cast<int>(v)) - og);
                bool ok = true;
                for (int k = 0; k < m && ok; ++k) ok = fits(rf[k], og[(at + k) % m]);
                if (!ok) continue;
                for (int k = 0; k < m; ++k) {
                    const int u = og[(at + k) % m];
                    if (map[static_cast<size_t>(rf[k])] >= 0) continue;
                    map[static_cast<size_t>(rf[k])] = u;
                    taken_by[static_cast<size_t>(u)] = rf[k];
                }
                placed = done = true;
            }
            if (done) break;
        }
    }
    return placed;
}

}  // namespace

const char* to_string(MatchMethod method) {
    switch (method) {
        case MatchMethod::Order: return "order";
        case MatchMethod::Topology: return "topology";
        case MatchMethod::Nearest: return "nearest";
        case MatchMethod::NearestAndFaces: return "nearest+faces";
        case MatchMethod::None: return "none";
    }
    return "unknown";
}

namespace {

/// The one-to-one match by nearest positions, from each reference vertex's nearest of ours;
/// method None, with the note, when two share one.
Correspondence nearest_bijection(const std::vector<unsigned>& nearest, size_t ours) {
    Correspondence c;
    c.method = MatchMethod::None;
    c.ref_to_ours.resize(nearest.size());
    std::vector<char> used(ours, 0);
    for (size_t i = 0; i < nearest.size(); ++i) {
        const unsigned idx = nearest[i];
        if (used[idx]) {
            c.note = "nearest-neighbour matching is not one-to-one (our vertex " + std::to_string(idx) + " is nearest to two)";
            c.ref_to_ours.clear();
            return c;
        }
        used[idx] = 1;
        c.ref_to_ours[i] = static_cast<int>(idx);
    }
    c.method = MatchMethod::Nearest;
    return c;
}

std::string counts_differ(size_t ref, size_t ours) {
    return "vertex counts differ (" + std::to_string(ref) + " vs " + std::to_string(ours) + ")";
}

}  // namespace

Correspondence match_nearest(const std::vector<Vec3>& ours, const std::vector<Vec3>& ref) {
    if (ours.size() != ref.size()) {
        Correspondence c;
        c.note = counts_differ(ref.size(), ours.size());
        return c;
    }
    const NearestPoints index(ours);
    std::vector<unsigned> nearest(ref.size());
    for (size_t i = 0; i < ref.size(); ++i) {
        double d2 = 0;
        index.nearest(ref[i], 1, &nearest[i], &d2);
    }
    return nearest_bijection(nearest, ours.size());
}

Correspondence match_nearest_and_faces(const PolyMesh& ours, const PolyMesh& ref, double copy_distance) {
    if (ours.num_vertices() != ref.num_vertices()) {
        Correspondence c;
        c.note = counts_differ(ref.positions.size(), ours.positions.size());
        return c;
    }
    const size_t n = ref.positions.size();

    // Closest pairs first.
    const NearestPoints index(ours.positions);
    std::vector<unsigned> nearest(n);
    std::vector<double> d2(n);
    // A reference vertex with two of ours as near (copies of a vertex at one place: a seam cut
    // open, a duplicate face's corners; as near up to `tie`) is placed by the faces alone: by
    // position it would take either copy, and the wrong one blocks the faces around both.
    const double tie = copy_distance * bounding_box_diagonal(ours.positions);
    std::vector<char> tied(n, 0);
    for (size_t i = 0; i < n; ++i) {
        unsigned two[2] = {0, 0};
        double two_d2[2] = {0, 0};
        tied[i] = index.nearest_within(ref.positions[i], 2, tie, two, two_d2) == 2;
        nearest[i] = two[0];
        d2[i] = two_d2[0];
    }
    Correspondence c = nearest_bijection(nearest, n);
    const std::string nearest_failed = c.note;
    // One to one by position, with no copies to confuse it: done. With copies, a one-to-one
    // match by position may still have taken the wrong copy of each (their distances differ
    // by rounding only): the faces decide.
    if (c.method != MatchMethod::None && std::find(tied.begin(), tied.end(), 1) == tied.end()) return c;
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return d2[a] < d2[b]; });
    // Only mutual nearest neighbours: a reference vertex that moved far may sit nearest to
    // one of ours whose own twin moved too, and must not take it.
    const NearestPoints ref_index(ref.positions);
    const auto mutual = [&](int i) {
        unsigned back = 0;
        double back_d2 = 0;
        ref_index.nearest(ours.positions[nearest[i]], 1, &back, &back_d2);
        return back_d2 >= d2[i];  // i is (one of) the nearest to its nearest
    };
    std::vector<int> map(n, -1), taken_by(n, -1);
    for (int i : order)
        if (!tied[i] && taken_by[nearest[i]] < 0 && mutual(i)) {
            map[i] = static_cast<int>(nearest[i]);
            taken_by[nearest[i]] = i;
        }

    // Our faces by their directed edges, to find the face a reference face maps to; the
    // reference's faces around each vertex: a face is tried again when a vertex of it is placed.
    const CornersAround our_corners(ours), ref_corners(ref);
    // A face whose matched edge names one of ours places its unmatched corners there, if free.
    // Its answer changes only when one of its corners is placed (our faces and a taken vertex
    // stay as they are), so the faces are tried from a queue: every face once, in order, then
    // the faces around each vertex placed; no pass over every face again.
    std::vector<int> queue(static_cast<size_t>(ref.num_faces()));
    std::vector<char> queued(queue.size(), 1);
    std::iota(queue.begin(), queue.end(), 0);
    const auto place = [&](int r, int u) {
        map[static_cast<size_t>(r)] = u;
        taken_by[static_cast<size_t>(u)] = r;
        for (int i = ref_corners.first[static_cast<size_t>(r)]; i < ref_corners.first[static_cast<size_t>(r) + 1]; ++i) {
            const int g = ref_corners.face[static_cast<size_t>(i)];
            if (!queued[static_cast<size_t>(g)]) {
                queued[static_cast<size_t>(g)] = 1;
                queue.push_back(g);
            }
        }
    };
    for (size_t head = 0;;) {
        for (; head < queue.size(); ++head) {
            const int f = queue[head];
            queued[static_cast<size_t>(f)] = 0;
            const int m = ref.face_size(f);
            const int* rf = ref.face(f);
            int unmatched = 0, edge = -1;  // edge: a corner k with k and k+1 matched
            for (int k = 0; k < m; ++k) {
                if (map[rf[k]] < 0) ++unmatched;
                else if (edge < 0 && map[rf[(k + 1) % m]] >= 0) edge = k;
            }
            if (unmatched == 0 || edge < 0) continue;
            // The matched edge names our face; its corners at the unmatched places must be free.
            const int a = map[rf[edge]], b = map[rf[(edge + 1) % m]];
            const int g = our_corners.face_of_edge(a, b);
            if (g < 0 || ours.face_size(g) != m) continue;
            const int* of = ours.face(g);
            int at = 0;
            while (of[at] != a) ++at;
            for (int k = 0; k < m; ++k) {
                if (map[rf[k]] >= 0) continue;
                const int candidate = of[(at + k - edge + m) % m];
                if (taken_by[candidate] < 0) place(rf[k], candidate);
            }
        }
        // No face places more: faces of copies by their corners' copies, and from them again.
        std::vector<int> before = map;
        if (!place_faces_of_copies(ours, our_corners, ref, index, d2, tie, map, taken_by)) break;
        for (size_t r = 0; r < n; ++r)
            if (before[r] < 0 && map[r] >= 0) {
                const int u = map[r];
                map[r] = -1;
                place(static_cast<int>(r), u);
            }
    }
    // Tied vertices no face placed (copies no face uses): any free copy of ours at that place.
    for (size_t i = 0; i < n; ++i) {
        if (!tied[i] || map[i] >= 0) continue;
        unsigned near[8];
        for (const unsigned u : copies_at(index, ref.positions[i], tie, near))
            if (taken_by[u] < 0) {
                map[i] = static_cast<int>(u);
                taken_by[u] = static_cast<int>(i);
                break;
            }
    }
    std::vector<int> left_ref, left_ours;
    for (size_t i = 0; i < n; ++i) {
        if (map[i] < 0) left_ref.push_back(static_cast<int>(i));
        if (taken_by[i] < 0) left_ours.push_back(static_cast<int>(i));
    }
    if (left_ref.size() == 1 && left_ours.size() == 1) map[left_ref[0]] = left_ours[0];
    else if (!left_ref.empty()) {
        // The faces could not place every copy: a one-to-one match by position stands, with
        // the note; none is none.
        c.note = (c.method != MatchMethod::None ? "copies at one place matched by position" : nearest_failed) + "; " +
                 std::to_string(left_ref.size()) + " vertices left unplaced by the faces";
        return c;
    }
    c.method = MatchMethod::NearestAndFaces;
    c.ref_to_ours = std::move(map);
    c.note = nearest_failed;
    return c;
}

Correspondence match_by_provenance(const std::vector<const PolyMesh*>& ours, const adapters::LevelTrace& ref) {
    Correspondence c;
    std::string why;
    if (ours.empty() || ref.size() != ours.size()) {
        why = "reference returned " + std::to_string(ref.size()) + " levels, we made " + std::to_string(ours.size());
    } else if (ref[0].positions != ours[0]->positions) {
        why = "reference's level 0 is not our input in our order";
    } else {
        std::vector<int> map(ours[0]->positions.size());
        std::iota(map.begin(), map.end(), 0);
        c.level_maps.push_back(map);
        int symmetric = 0;
        for (size_t k = 0; k + 1 < ref.size() && why.empty(); ++k) {
            std::vector<int> next;
            why = match_next_level(map, *ours[k], *ours[k + 1], ref[k + 1], next, symmetric);
            if (!why.empty()) why = "level " + std::to_string(k + 1) + ": " + why;
            map = std::move(next);
            c.level_maps.push_back(map);
        }
        if (why.empty()) {
            bool identity = true;
            for (size_t i = 0; i < map.size() && identity; ++i) identity = map[i] == static_cast<int>(i);
            c.method = identity ? MatchMethod::Order : MatchMethod::Topology;
            c.ref_to_ours = std::move(map);
            if (symmetric > 0)
                c.note = std::to_string(symmetric) + " vertices with the same provenance (children of a duplicate "
                         "face's copies) paired in order";
            return c;
        }
    }
    c.level_maps.clear();
    c.note = "matching by provenance failed (" + why + ")";
    return c;
}

Correspondence match_refinement(const std::vector<const PolyMesh*>& ours, const adapters::LevelTrace& ref) {
    Correspondence by_provenance = match_by_provenance(ours, ref);
    if (by_provenance.method != MatchMethod::None || ours.empty() || ref.empty()) return by_provenance;
    Correspondence c = match_nearest_and_faces(*ours.back(), ref.back());
    c.note = by_provenance.note + (c.note.empty() ? "" : "; " + c.note);
    return c;
}

std::vector<VertexBirth> primal_births(const PolyMesh& coarse, const PolyMesh& fine) {
    const FaceIndex faces(coarse);
    std::vector<int> identity(static_cast<size_t>(coarse.num_vertices()));
    std::iota(identity.begin(), identity.end(), 0);
    std::string why;
    const std::vector<Provenance> provenance = read_provenance(fine, identity, faces, why);
    std::vector<VertexBirth> out;
    out.reserve(provenance.size());
    std::vector<int> cycle;
    for (const Provenance& p : provenance) {
        if (p.face < 0) {
            out.push_back({VertexBirth::Kind::Vertex, p.local, -1});
        } else if (p.local < 0) {
            out.push_back({VertexBirth::Kind::Face, p.face, -1});
        } else {
            // The edge's place counts from the face's canonical first corner (least_rotation).
            cycle.assign(coarse.face(p.face), coarse.face(p.face) + coarse.face_size(p.face));
            const size_t m = cycle.size(), at = least_rotation(cycle) + static_cast<size_t>(p.local);
            out.push_back({VertexBirth::Kind::Edge, cycle[at % m], cycle[(at + 1) % m]});
        }
    }
    return out;
}

std::vector<const PolyMesh*> level_view(const adapters::LevelTrace& levels) {
    std::vector<const PolyMesh*> view;
    for (const PolyMesh& m : levels) view.push_back(&m);
    return view;
}

PolyMesh renumber(const PolyMesh& mesh, const std::vector<int>& to_ours) {
    PolyMesh out = mesh;
    for (size_t i = 0; i < to_ours.size(); ++i) out.positions[static_cast<size_t>(to_ours[i])] = mesh.positions[i];
    if (mesh.colors.size() == to_ours.size())
        for (size_t i = 0; i < to_ours.size(); ++i) out.colors[static_cast<size_t>(to_ours[i])] = mesh.colors[i];
    for (int& v : out.face_vertices) v = to_ours[static_cast<size_t>(v)];
    out.source = {};
    return out;
}

}  // namespace crossdiv::verification
