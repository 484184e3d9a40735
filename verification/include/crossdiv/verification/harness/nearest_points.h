#pragma once
/// @file
/// The nearest points of a fixed set to a query, exactly, made for matching two refinements of
/// one surface vertex for vertex: their points part by roundings, far less than the distance
/// between neighbours.

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// Whether a point at squared distance `d2` from a query is as near as the nearest one (at
/// `d2_nearest`) up to `slack`: a copy of it at one place, or the same vertex as two
/// implementations round it (summing its neighbours in another order puts it an ulp or two
/// apart), which positions must not tell apart.
inline bool as_near_as(double d2, double d2_nearest, double slack) { return std::sqrt(d2) <= std::sqrt(d2_nearest) + slack; }

/// The k nearest points of a fixed set to a query point: the same neighbours and squared
/// distances as a k-d tree's search (equally near points may come in another order).
///
/// A uniform grid over the points' box (cells 2^-16 of its longest side) answers a query whose
/// k nearest lie in its own cell, nearer than the cell's walls: no point outside the cell can be
/// nearer, so the answer is exact, after one hash probe and a scan of the few points in the cell.
/// Any other query (near a wall, in a cell with fewer than k points or more than
/// kCrowdedCell, outside the box) goes to a k-d tree (nanoflann), built at the first such query.
/// Matching a refinement of a million vertices with a k-d tree alone spent 60% of an invariance
/// check in building and searching the tree; two refinements of one surface send almost no
/// query to it.
///
/// The set is read in place: `points` must outlive the index and stay unchanged. Queries may come
/// from several threads.
class NearestPoints {
public:
    /// At most this many neighbours per query.
    static constexpr size_t kMaxNeighbours = 8;
    /// A cell with more points than this (copies of a vertex at one place, a dense detail of a
    /// large model) leaves its queries to the tree, so no query scans more than this many.
    static constexpr size_t kCrowdedCell = 32;

    explicit NearestPoints(const std::vector<Vec3>& points);
    ~NearestPoints();
    NearestPoints(const NearestPoints&) = delete;
    NearestPoints& operator=(const NearestPoints&) = delete;

    /// The min(k, size()) points nearest `query` (k <= kMaxNeighbours), nearest first: their
    /// indices in `indices` and squared distances in `d2`. Returns how many were written.
    size_t nearest(const Vec3& query, size_t k, unsigned* indices, double* d2) const;

    /// The point nearest `query` and the others as near up to `slack`: a point p with
    /// |p - query| <= |nearest - query| + slack (copies of one vertex, or its roundings), at
    /// most k (<= kMaxNeighbours) in all, nearest first. Returns how many were written: 1 and
    /// more, 0 for an empty set.
    size_t nearest_within(const Vec3& query, size_t k, double slack, unsigned* indices, double* d2) const;

    size_t size() const { return points_.size(); }

    /// How many queries so far went to the k-d tree (for tests and measurements).
    size_t tree_queries() const;

private:
    struct Grid;
    struct Tree;
    const std::vector<Vec3>& points_;
    std::unique_ptr<Grid> grid_;  ///< null when a point is not finite: every query to the tree
    std::unique_ptr<Tree> tree_;
};

}  // namespace crossdiv::verification
