#include "crossdiv/datasets/valence_shapes.h"

#include <algorithm>
#include <cmath>

#include "shapes.h"

namespace crossdiv::datasets {

using namespace shapes;

PolyMesh valence_shape(ValenceShape shape, int k) {
    switch (shape) {
        case ValenceShape::Bicone: return pole(k, 1);
        case ValenceShape::DiscFan: return fan(k);
        case ValenceShape::Polygon: {
            std::vector<Vec3> p;
            std::vector<int> face;
            for (int i = 0; i < k; ++i) {
                const double a = 2 * M_PI * i / k;
                p.emplace_back(std::cos(a), std::sin(a), 0.1 * std::sin(3.0 * a + 0.5));
                face.push_back(i);
            }
            return make(std::move(p), {face});
        }
    }
    return {};
}

PolyMesh regular_counterpart(ValenceShape shape, int k) {
    // n x n cells of two triangles (or one quad) give 2 n^2 triangles (or n^2 quads).
    const auto side = [](double cells) { return std::max(3, static_cast<int>(std::lround(std::sqrt(cells)))); };
    switch (shape) {
        case ValenceShape::Bicone: return torus(side(k), side(k), 1.0, 0.4);
        case ValenceShape::DiscFan: {
            const int n = side(k / 2.0);
            return grid_patch(n, n, [](double x, double y) { return 0.1 * std::sin(3 * x) * y; }, false);
        }
        case ValenceShape::Polygon: return quad_grid(side(k / 4.0), 0.1);
    }
    return {};
}

}  // namespace crossdiv::datasets
