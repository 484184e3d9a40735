#include "crossdiv/mesh/closest_point.h"

#include <algorithm>
#include <limits>

#include "crossdiv/error.h"

namespace crossdiv {
namespace {

constexpr int kLeafSize = 4;

TrianglePoint at(const Vec3& a, const Vec3& b, const Vec3& c, double u, double v, double w) {
    return {u * a + v * b + w * c, {u, v, w}};
}

/// Squared distance from `p` to the box [low, high] (0 inside).
double box_distance2(const Vec3& p, const Vec3& low, const Vec3& high) {
    const Vec3 d = (low - p).cwiseMax(p - high).cwiseMax(0.0);
    return d.squaredNorm();
}

}  // namespace

TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Ericson's region tests: each early return is one Voronoi region of the triangle's
    // features, decided by signs of dot products (no division until the region is known,
    // so a degenerate triangle falls into a vertex or edge region instead of dividing by 0).
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return at(a, b, c, 1, 0, 0);
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return at(a, b, c, 0, 1, 0);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return at(a, b, c, 1 - v, v, 0);
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return at(a, b, c, 0, 0, 1);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return at(a, b, c, 1 - w, 0, w);
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return at(a, b, c, 0, 1 - w, w);
    }
    const double denom = 1 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    return at(a, b, c, 1 - v - w, v, w);
}

TriangleTree::TriangleTree(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles) {
    corners_.reserve(triangles.size());
    std::vector<Vec3> centroids;
    centroids.reserve(triangles.size());
    for (const Triangle& t : triangles) {
        corners_.push_back({positions[t[0]], positions[t[1]], positions[t[2]]});
        centroids.push_back((positions[t[0]] + positions[t[1]] + positions[t[2]]) / 3);
    }
    order_.resize(triangles.size());
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<int>(i);
    if (!order_.empty()) {
        nodes_.reserve(2 * order_.size() / kLeafSize + 2);
        build(0, static_cast<int>(order_.size()), centroids);
    }
}

int TriangleTree::build(int begin, int end, std::vector<Vec3>& centroids) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
    Vec3 c_low = low, c_high = high;
    for (int i = begin; i < end; ++i) {
        for (const Vec3& q : corners_[order_[i]]) low = low.cwiseMin(q), high = high.cwiseMax(q);
        c_low = c_low.cwiseMin(centroids[order_[i]]), c_high = c_high.cwiseMax(centroids[order_[i]]);
    }
    nodes_[index].low = low, nodes_[index].high = high;
    if (end - begin <= kLeafSize) {
        nodes_[index].first = begin, nodes_[index].count = end - begin;
        return index;
    }
    int axis = 0;
    (c_high - c_low).maxCoeff(&axis);
    const int mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int x, int y) { return centroids[x][axis] < centroids[y][axis]; });
    // The left child follows its parent; the right one comes after the left's whole subtree.
    const int left = build(begin, mid, centroids);
    const int right = build(mid, end, centroids);
    nodes_[index].first = left;
    nodes_[index].count = -right;  // negative: an inner node, minus its right child
    return index;
}

TriangleTree::Hit TriangleTree::closest(const Vec3& p) const {
    if (nodes_.empty()) throw InputError("closest point on a mesh without triangles");
    if (!p.allFinite()) throw InputError("closest point to a point that is not finite");
    Hit best;
    best.squared_distance = std::numeric_limits<double>::infinity();
    // An explicit stack of (node, squared distance to its box); depth is O(log n).
    std::array<std::pair<int, double>, 128> stack;
    int top = 0;
    stack[top++] = {0, box_distance2(p, nodes_[0].low, nodes_[0].high)};
    while (top > 0) {
        const auto [n, d2] = stack[--top];
        if (d2 >= best.squared_distance) continue;
        const Node& node = nodes_[n];
        if (node.count > 0) {
            for (int i = node.first; i < node.first + node.count; ++i) {
                const auto& t = corners_[order_[i]];
                const TrianglePoint q = closest_point_on_triangle(p, t[0], t[1], t[2]);
                const double e2 = (q.point - p).squaredNorm();
                if (e2 < best.squared_distance) best = {order_[i], q, e2};
            }
            continue;
        }
        const int a = node.first, b = -node.count;
        const double da = box_distance2(p, nodes_[a].low, nodes_[a].high);
        const double db = box_distance2(p, nodes_[b].low, nodes_[b].high);
        // Push the farther first so that the nearer is searched first.
        if (da <= db) {
            stack[top++] = {b, db}, stack[top++] = {a, da};
        } else {
            stack[top++] = {a, da}, stack[top++] = {b, db};
        }
    }
    return best;
}

}  // namespace crossdiv
