#pragma once
// Tiny polygon meshes the scheme tests compute by hand.

#include <array>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/subdiv/catmull_clark_mask.h"

namespace crossdiv::test {

/// Catmull-Clark's boundary rules, as the tests name them.
inline constexpr CatmullClarkOptions kEdgeOnly{CatmullClarkBoundary::EdgeOnly};
inline constexpr CatmullClarkOptions kEdgeAndCorner{CatmullClarkBoundary::EdgeAndCorner};
inline constexpr CatmullClarkOptions kMidpointAverage{CatmullClarkBoundary::MidpointAverage};

/// The cube [-1, 1]^3 as six outward quads; vertex i = (+-1, +-1, +-1) by the bits of i,
/// every vertex of valence 3.
inline PolyMesh cube() {
    PolyMesh m;
    for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    m.add_face({0, 2, 3, 1});  // z = -1
    m.add_face({4, 5, 7, 6});  // z = +1
    m.add_face({0, 1, 5, 4});  // y = -1
    m.add_face({2, 6, 7, 3});  // y = +1
    m.add_face({0, 4, 6, 2});  // x = -1
    m.add_face({1, 3, 7, 5});  // x = +1
    return m;
}

/// The unit square in z = 0, one quad: four boundary corners.
inline PolyMesh square() {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    m.add_face({0, 1, 2, 3});
    return m;
}

/// The octahedron with vertices 0..5 = +x, -x, +y, -y, +z, -z; outward triangles, every
/// vertex of valence 4. Its equator (z = 0) is the loop 0-2-1-3-0.
inline PolyMesh octahedron() {
    PolyMesh m;
    m.positions = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
    for (auto f : {std::array{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}})
        m.add_face(f);
    return m;
}

}  // namespace crossdiv::test
