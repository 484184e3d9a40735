#pragma once
/// @file
/// Several meshes as one, each a component of its own: the inverse of splitting a mesh into
/// its connected components (the invariance check's `components` refines the parts apart and
/// compares their union with the whole), and how the edge-case catalog builds its
/// several-component inputs.

#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// The parts one after another: positions, faces (renumbered past the earlier parts' vertices),
/// colours where every part has them, and face-varying channels where every part has the same
/// ones (count and dimension), their values renumbered alike. Crease tags, holes and the
/// source's lines are not carried.
PolyMesh disjoint_union(const std::vector<PolyMesh>& parts);

}  // namespace crossdiv
