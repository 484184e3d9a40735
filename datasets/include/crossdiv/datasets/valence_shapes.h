#pragma once
/// @file valence_shapes.h
/// Meshes that time what a vertex of large valence, or a polygon of many sides, costs: each
/// beside a regular mesh of about the same size, so that a traversal linear in the mesh shows
/// the same time on both.

#include <string_view>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::datasets {

enum class ValenceShape {
    Bicone,   ///< two poles of valence k, closed: 2k triangles
    DiscFan,  ///< one interior vertex of valence k inside a boundary rim: k triangles
    Polygon,  ///< one polygon of k sides
};

inline constexpr ValenceShape kValenceShapes[] = {ValenceShape::Bicone, ValenceShape::DiscFan, ValenceShape::Polygon};

/// "bicone", "disc-fan", "polygon".
constexpr std::string_view to_string(ValenceShape s) {
    return s == ValenceShape::Bicone ? "bicone" : s == ValenceShape::DiscFan ? "disc-fan" : "polygon";
}

/// The shape with valence (or sides) k >= 3.
PolyMesh valence_shape(ValenceShape shape, int k);

/// Its regular counterpart: a regular triangulated torus of about 2k triangles (closed, like
/// the bicone), a triangulated square grid of about k triangles (open, like the disc fan), a
/// quad grid of about k / 4 quads (the polygon's k corners).
PolyMesh regular_counterpart(ValenceShape shape, int k);

}  // namespace crossdiv::datasets
