#pragma once
// Tiny polygon meshes the scheme tests compute by hand.

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::test {

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

}  // namespace crossdiv::test
