#pragma once
// nanoflann's dataset interface over a vector of points (internal to the harness).

#include <nanoflann.hpp>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

struct PointCloud {
    const std::vector<Vec3>& pts;
    size_t kdtree_get_point_count() const { return pts.size(); }
    double kdtree_get_pt(size_t i, size_t dim) const { return pts[i][static_cast<int>(dim)]; }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const { return false; }
};

/// A k-d tree over a PointCloud. Its constructor builds it (nanoflann 1.4): no buildIndex() after.
using PointTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 3>;

}  // namespace crossdiv::verification
