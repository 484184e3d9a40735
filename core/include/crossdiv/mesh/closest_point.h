#pragma once
/// @file
/// Closest points on a triangle mesh: a bounding-volume hierarchy of axis-aligned boxes over
/// the triangles (median split along the longest side, leaves of a few triangles, nodes in
/// one flat array), and the exact closest point of a triangle (Ericson, "Real-Time Collision
/// Detection", 2005, sec. 5.1.5: the Voronoi regions of the vertices, edges and face). A query
/// descends nearer child first and prunes every box farther than the best point found, so it
/// is exact, not approximate; it costs O(log n) on meshes whose triangles are not all huge.

#include <array>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

/// The closest point of a triangle to a point, with its barycentric coordinates.
struct TrianglePoint {
    Vec3 point = Vec3::Zero();
    std::array<double, 3> barycentric{1, 0, 0};  ///< of corners 0, 1, 2; sum 1, each in [0, 1]
};
TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleTree {
public:
    /// The hit of a query: the triangle, its closest point and the squared distance.
    struct Hit {
        int triangle = -1;
        TrianglePoint where;
        double squared_distance = 0;
    };

    /// Copies the corner positions of `triangles` (indices into `positions`, checked by the
    /// caller). An empty triangle list makes a tree every query of which throws.
    TriangleTree(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles);

    int num_triangles() const { return static_cast<int>(corners_.size()); }
    /// The closest point of the mesh to `p` (the lowest triangle index among equal distances
    /// is not promised; the distance is exact). @throws InputError for an empty tree or a
    /// point that is not finite.
    Hit closest(const Vec3& p) const;

private:
    struct Node {
        Vec3 low, high;
        int first = 0;  ///< leaf: first entry of order_; inner: index of the left child
        int count = 0;  ///< leaf: number of triangles (> 0); inner: minus the right child's index
    };
    int build(int begin, int end, std::vector<Vec3>& centroids);

    std::vector<std::array<Vec3, 3>> corners_;
    std::vector<int> order_;  ///< triangle indices, each leaf's a contiguous run
    std::vector<Node> nodes_;
};

}  // namespace crossdiv
