#include "crossdiv/verification/harness/nearest_points.h"

#include "harness/point_cloud.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <utility>

namespace crossdiv::verification {

/// Cells of 2^-16 of the box's longest side: two refinements of one surface part by roundings
/// (1e-16 to 1e-7 of the diagonal, doubles to floats), so a query lies near a wall only rarely,
/// and the 65,536 cells a side leave a real model's vertices a few to a cell.
constexpr double kCellsOnLongestSide = 65536;

struct NearestPoints::Grid {
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
    static constexpr int kAxisBits = 21;  // 65,538 cells a side at most

    Vec3 lo = Vec3::Zero();
    double cell = 1, inv_cell = 1;
    /// How far a computed wall distance may lie from the true one: the rounding of a
    /// coordinate's cell (its difference from `lo`, scaled), with room to spare.
    double margin = 0;
    std::int64_t cells[3] = {1, 1, 1};
    std::vector<Vec3> points;       ///< the points in cell order
    std::vector<unsigned> index;    ///< each one's index in the set
    std::vector<std::uint64_t> slot_key;
    std::vector<std::uint32_t> slot_begin, slot_end;  ///< the cell's run in `points`
    int shift = 64;

    /// The cell of `p`, and for each axis its place in cell units; false outside the grid.
    bool locate(const Vec3& p, std::int64_t (&c)[3], double (&t)[3]) const {
        for (int a = 0; a < 3; ++a) {
            t[a] = (p[a] - lo[a]) * inv_cell;
            if (!(t[a] >= 0 && t[a] < static_cast<double>(cells[a]))) return false;
            c[a] = static_cast<std::int64_t>(t[a]);
        }
        return true;
    }

    static std::uint64_t key(const std::int64_t (&c)[3]) {
        return (static_cast<std::uint64_t>(c[0]) << (2 * kAxisBits)) | (static_cast<std::uint64_t>(c[1]) << kAxisBits) |
               static_cast<std::uint64_t>(c[2]);
    }

    size_t slot_of(std::uint64_t k) const {
        const size_t mask = slot_key.size() - 1;
        size_t s = static_cast<size_t>((k * 0x9E3779B97F4A7C15ull) >> shift);
        while (slot_key[s] != k && slot_key[s] != kEmpty) s = (s + 1) & mask;
        return s;
    }

    explicit Grid(const std::vector<Vec3>& set) {
        Vec3 hi = set[0];
        lo = set[0];
        for (const Vec3& p : set) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        const double longest = (hi - lo).maxCoeff();
        cell = longest > 0 ? longest / kCellsOnLongestSide : 1.0;
        inv_cell = 1.0 / cell;
        // Half a cell of room around the box: the extreme points, queried at their own places,
        // lie inside a cell rather than on the grid's outer walls.
        lo -= Vec3::Constant(cell / 2);
        for (int a = 0; a < 3; ++a) cells[a] = static_cast<std::int64_t>((hi[a] - lo[a]) * inv_cell) + 2;
        const double largest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
        margin = 16 * largest * std::numeric_limits<double>::epsilon() + cell * 0x1p-30;

        std::vector<std::pair<std::uint64_t, unsigned>> keyed(set.size());
        for (size_t i = 0; i < set.size(); ++i) {
            std::int64_t c[3] = {0, 0, 0};
            double t[3];
            locate(set[i], c, t);  // inside: the box is the points'
            keyed[i] = {key(c), static_cast<unsigned>(i)};
        }
        std::sort(keyed.begin(), keyed.end());
        points.resize(set.size());
        index.resize(set.size());
        size_t distinct = 0;
        for (size_t i = 0; i < keyed.size(); ++i) {
            points[i] = set[keyed[i].second];
            index[i] = keyed[i].second;
            distinct += i == 0 || keyed[i].first != keyed[i - 1].first;
        }
        const size_t slots = std::bit_ceil(2 * distinct + 2);
        shift = 64 - std::countr_zero(slots);
        slot_key.assign(slots, kEmpty);
        slot_begin.resize(slots);
        slot_end.resize(slots);
        for (size_t i = 0; i < keyed.size();) {
            size_t j = i + 1;
            while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
            const size_t s = slot_of(keyed[i].first);
            slot_key[s] = keyed[i].first;
            slot_begin[s] = static_cast<std::uint32_t>(i);
            slot_end[s] = static_cast<std::uint32_t>(j);
            i = j;
        }
    }

    /// The k nearest of `q` among the points of its cell (fewer when the cell has fewer),
    /// nearest first, equally near by index; and the distance from `q` to the cell's nearest
    /// wall, less the margin: no point outside the cell is nearer. Returns how many, 0 when
    /// `q` has no cell here or its cell is crowded.
    size_t scan_cell(const Vec3& q, size_t k, unsigned* indices, double* d2, double& wall) const {
        std::int64_t c[3];
        double t[3];
        if (!locate(q, c, t)) return 0;
        const size_t s = slot_of(key(c));
        if (slot_key[s] == kEmpty || slot_end[s] - slot_begin[s] > kCrowdedCell) return 0;
        // The k best: an insertion into k <= 8 places.
        size_t found = 0;
        for (size_t i = slot_begin[s]; i < slot_end[s]; ++i) {
            // The k-d tree's metric, term by term in the same order: the same squared distance.
            const double dx = q[0] - points[i][0], dy = q[1] - points[i][1], dz = q[2] - points[i][2];
            const double d = dx * dx + dy * dy + dz * dz;
            const unsigned id = index[i];
            if (found == k && !(d < d2[k - 1] || (d == d2[k - 1] && id < indices[k - 1]))) continue;
            size_t at = found < k ? found++ : k - 1;
            while (at > 0 && (d < d2[at - 1] || (d == d2[at - 1] && id < indices[at - 1]))) {
                d2[at] = d2[at - 1];
                indices[at] = indices[at - 1];
                --at;
            }
            d2[at] = d;
            indices[at] = id;
        }
        wall = INFINITY;
        for (int a = 0; a < 3; ++a) {
            const double f = t[a] - static_cast<double>(c[a]);
            wall = std::min(wall, std::min(f, 1.0 - f) * cell);
        }
        wall -= margin;
        return found;
    }
};

struct NearestPoints::Tree {
    PointCloud cloud;
    std::once_flag built;
    std::unique_ptr<PointTree> tree;
    std::atomic<size_t> queries{0};

    /// The tree, built at its first use (nanoflann's constructor builds it); counts the query.
    const PointTree& get() {
        queries.fetch_add(1, std::memory_order_relaxed);
        std::call_once(built, [&] { tree = std::make_unique<PointTree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)); });
        return *tree;
    }
};

NearestPoints::NearestPoints(const std::vector<Vec3>& points)
    : points_(points), tree_(new Tree{PointCloud{points}, {}, nullptr, {}}) {
    const bool finite = std::all_of(points.begin(), points.end(), [](const Vec3& p) { return p.allFinite(); });
    if (finite && !points.empty()) grid_ = std::make_unique<Grid>(points);
}

NearestPoints::~NearestPoints() = default;

size_t NearestPoints::nearest(const Vec3& query, size_t k, unsigned* indices, double* d2) const {
    k = std::min({k, kMaxNeighbours, points_.size()});
    if (k == 0) return 0;
    double wall = 0;
    // Exact when the cell holds k points and the k-th is nearer than any point outside it.
    if (grid_ && grid_->scan_cell(query, k, indices, d2, wall) == k && std::sqrt(d2[k - 1]) < wall) return k;
    return tree_->get().knnSearch(query.data(), k, indices, d2);
}

size_t NearestPoints::nearest_within(const Vec3& query, size_t k, double slack, unsigned* indices, double* d2) const {
    k = std::min({k, kMaxNeighbours, points_.size()});
    if (k == 0) return 0;
    double wall = 0;
    size_t found = grid_ ? grid_->scan_cell(query, k, indices, d2, wall) : 0;
    // Exact when every point as near as the nearest, up to the slack, is inside the cell.
    if (found == 0 || !(std::sqrt(d2[0]) + slack < wall)) found = tree_->get().knnSearch(query.data(), k, indices, d2);
    size_t same = 1;
    while (same < found && as_near_as(d2[same], d2[0], slack)) ++same;
    return same;
}

size_t NearestPoints::tree_queries() const { return tree_->queries.load(std::memory_order_relaxed); }

}  // namespace crossdiv::verification
