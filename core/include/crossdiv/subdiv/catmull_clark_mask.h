#pragma once
/// @file
/// Catmull-Clark masks: the weights only (as OpenSubdiv's sdc/catmarkScheme.h). The
/// traversal is catmull_clark.cpp; the driver is refinement.h.
///
/// E. Catmull, J. Clark, "Recursively generated B-spline surfaces on arbitrary topological
/// meshes", Computer-Aided Design 10(6), 1978; the weights written as OpenSubdiv writes them
/// (Sdc::Scheme<SCHEME_CATMARK>::assignSmoothMaskForVertex): (n-2)/n on the vertex, 1/n^2 on
/// each ring vertex and on each new face point -- the paper's (F + 2R + (n-3) V)/n expanded.

#include <array>
#include <string_view>

#include "crossdiv/named_variant.h"
#include "crossdiv/mesh/crease_tags.h"

namespace crossdiv {

/// How the boundary of an open mesh is refined. Every rule makes boundary edge points the
/// edge midpoints; they differ at boundary vertices.
enum class CatmullClarkBoundary {
    /// Boundary vertex 3/4, 1/8, 1/8 on its two boundary neighbours: the boundary is a cubic
    /// B-spline curve. OpenSubdiv's VTX_BOUNDARY_EDGE_ONLY; CGAL's border rule.
    EdgeOnly,
    /// As EdgeOnly, and a boundary vertex with one incident face is a corner that stays
    /// fixed. OpenSubdiv's VTX_BOUNDARY_EDGE_AND_CORNER.
    EdgeAndCorner,
    /// Boundary vertex = average of itself and its two boundary edge midpoints, i.e. 2/3,
    /// 1/6, 1/6: the B-spline curve's *limit* mask applied at every level, so the boundary
    /// does not converge to the cubic B-spline. OpenMesh's CatmullClarkT::update_vertex.
    MidpointAverage,
};

struct CatmullClarkOptions {
    CatmullClarkBoundary boundary;
    /// How semi-sharp crease tags decay (crease_mask.h); without tags it changes nothing.
    CreaseMethod creasing = CreaseMethod::Uniform;
    friend bool operator==(const CatmullClarkOptions&, const CatmullClarkOptions&) = default;
};

/// Weights of the interior vertex-point mask at valence n.
struct CatmullClarkVertexMask {
    double self;   ///< (n - 2) / n
    double ring;   ///< 1 / n^2 on each vertex across an incident edge
    double face;   ///< 1 / n^2 on each new face point around the vertex
};

inline CatmullClarkVertexMask catmull_clark_interior_vertex_mask(int valence) {
    const double n = valence;
    return {(n - 2.0) / n, 1.0 / (n * n), 1.0 / (n * n)};
}

/// Interior edge point: 1/4 on each endpoint and 1/4 on each of the two new face points.
inline constexpr double kCatmullClarkEdgeEnd = 0.25, kCatmullClarkEdgeFace = 0.25;

/// Weights of a boundary vertex-point mask: `self` on the vertex, `neighbor` on each of its
/// two boundary neighbours (none at a corner).
struct CatmullClarkBoundaryMask {
    double self, neighbor;
};

/// The boundary vertex mask of a vertex with `incident_faces` faces around it.
inline CatmullClarkBoundaryMask catmull_clark_boundary_vertex_mask(CatmullClarkBoundary rule, int incident_faces) {
    switch (rule) {
        case CatmullClarkBoundary::EdgeAndCorner:
            if (incident_faces == 1) return {1.0, 0.0};
            return {0.75, 0.125};
        case CatmullClarkBoundary::MidpointAverage: return {2.0 / 3.0, 1.0 / 6.0};
        case CatmullClarkBoundary::EdgeOnly: break;
    }
    return {0.75, 0.125};
}

/// "edge-only", "edge-and-corner", "midpoint-average".
constexpr std::string_view to_string(CatmullClarkBoundary b) {
    switch (b) {
        case CatmullClarkBoundary::EdgeOnly: return "edge-only";
        case CatmullClarkBoundary::EdgeAndCorner: return "edge-and-corner";
        case CatmullClarkBoundary::MidpointAverage: return "midpoint-average";
    }
    return "?";
}

/// The boundary rule named `name`. @throws InputError listing the names.
inline CatmullClarkBoundary catmull_clark_boundary_from_string(std::string_view name) {
    return variant_from_string<CatmullClarkBoundary>(
        name, std::array{CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner, CatmullClarkBoundary::MidpointAverage},
        "Catmull-Clark boundary rule");
}

}  // namespace crossdiv
