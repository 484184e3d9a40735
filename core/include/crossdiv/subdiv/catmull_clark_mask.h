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
#include "crossdiv/subdiv/nonmanifold_rule.h"

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

/// The weights of a smooth interior vertex point, with F the average of the new face points
/// around the vertex V, R the average of the midpoints of its edges, n its valence.
enum class CatmullClarkVertexRule {
    /// (F + 2R + (n - 3) V) / n: Catmull and Clark's rule, OpenSubdiv's and every library's.
    Standard,
    /// F/4 + R/2 + V/4 at every valence: the paper's weights at valence 4 (the bicubic
    /// B-spline's) kept at extraordinary vertices, where the surface is then not the paper's.
    RegularWeights,
    /// (F + 2E + (n - 3) V) / n with E the average of the new edge *points* rather than of
    /// the edge midpoints: a reading of the rule found in course notes and, for a time, in
    /// Wikipedia's statement of it. It differs at every valence, 4 included.
    EdgePointAverage,
};

struct CatmullClarkOptions {
    CatmullClarkBoundary boundary;
    /// How semi-sharp crease tags decay (crease_mask.h); without tags it changes nothing.
    CreaseMethod creasing = CreaseMethod::Uniform;
    /// OpenSubdiv's TRI_SUB_SMOOTH (`t smoothtriangles 0/0/1 smooth`): a smooth edge point
    /// next to triangles weighs their face points more (catmull_clark_edge_weights). Only
    /// the first level has triangles, so only it changes.
    bool smooth_triangles = false;
    /// A mesh that is not a manifold: OpenSubdiv's rules (nonmanifold.h) or refused.
    NonManifoldRule nonmanifold = NonManifoldRule::OpenSubdiv;
    /// The smooth interior vertex rule (the literature's variants, for naming what an
    /// implementation under test does; Standard is everyone's).
    CatmullClarkVertexRule vertex = CatmullClarkVertexRule::Standard;
    /// Whose semi-sharp crease rules (crease_tags.h): Far's, or Hbr's where they differ.
    CreaseRules crease_rules = CreaseRules::OpenSubdiv;
    friend bool operator==(const CatmullClarkOptions&, const CatmullClarkOptions&) = default;
};

/// Weights of the interior vertex-point mask at valence n.
struct CatmullClarkVertexMask {
    double self;   ///< (n - 2) / n
    double ring;   ///< 1 / n^2 on each vertex across an incident edge
    double face;   ///< 1 / n^2 on each new face point around the vertex
};

/// The mask of `rule` at valence n, in (self, ring, face) form: R = (V + ring average) / 2
/// expands each rule. RegularWeights: 1/2, 1/(4n), 1/(4n). EdgePointAverage: an interior
/// edge point is (V + W + two face points) / 4, so E = (V + ring average + 2 F) / 4 and the
/// mask is (2n - 5)/(2n), 1/(2n^2), 2/n^2.
inline CatmullClarkVertexMask catmull_clark_interior_vertex_mask(int valence,
                                                                 CatmullClarkVertexRule rule = CatmullClarkVertexRule::Standard) {
    const double n = valence;
    switch (rule) {
        case CatmullClarkVertexRule::RegularWeights: return {0.5, 0.25 / n, 0.25 / n};
        case CatmullClarkVertexRule::EdgePointAverage: return {(2.0 * n - 5.0) / (2.0 * n), 0.5 / (n * n), 2.0 / (n * n)};
        case CatmullClarkVertexRule::Standard: break;
    }
    return {(n - 2.0) / n, 1.0 / (n * n), 1.0 / (n * n)};
}

/// "standard", "regular-weights", "edge-point-average".
constexpr std::string_view to_string(CatmullClarkVertexRule r) {
    switch (r) {
        case CatmullClarkVertexRule::Standard: return "standard";
        case CatmullClarkVertexRule::RegularWeights: return "regular-weights";
        case CatmullClarkVertexRule::EdgePointAverage: return "edge-point-average";
    }
    return "?";
}

/// Interior edge point: 1/4 on each endpoint and 1/4 on each of the two new face points.
inline constexpr double kCatmullClarkEdgeEnd = 0.25, kCatmullClarkEdgeFace = 0.25;

/// The weight OpenSubdiv's TRI_SUB_SMOOTH gives a triangle's face point in an edge point
/// (Sdc::Scheme<SCHEME_CATMARK>::assignSmoothMaskForEdge, CATMARK_SMOOTH_TRI_EDGE_WEIGHT,
/// after Hbr).
inline constexpr double kSmoothTriangleEdgeFace = 0.470;

/// Weights of a smooth interior edge point, {on each endpoint, on each face point}: 1/4 and
/// 1/4, or under TRI_SUB_SMOOTH with a triangle on either side, the two faces' weights
/// (0.47 for a triangle, 1/4 otherwise) averaged for each face point and the endpoints taking
/// the rest: {1/2 (1 - 2 f), f}, i.e. {0.03, 0.47} between two triangles, {0.14, 0.36}
/// between a triangle and a quad. Computed in the library's order of operations.
struct CatmullClarkEdgeWeights {
    double end, face;
};
inline CatmullClarkEdgeWeights catmull_clark_edge_weights(bool smooth_triangles, bool face0_is_triangle,
                                                          bool face1_is_triangle) {
    if (!smooth_triangles || !(face0_is_triangle || face1_is_triangle)) return {kCatmullClarkEdgeEnd, kCatmullClarkEdgeFace};
    const double f0 = face0_is_triangle ? kSmoothTriangleEdgeFace : 0.25;
    const double f1 = face1_is_triangle ? kSmoothTriangleEdgeFace : 0.25;
    const double f = 0.5 * (f0 + f1);
    return {0.5 * (1.0 - 2.0 * f), f};
}

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

inline constexpr std::array kAllCatmullClarkBoundaries{CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner,
                                                       CatmullClarkBoundary::MidpointAverage};

/// The boundary rule named `name`. @throws InputError listing the names.
inline CatmullClarkBoundary catmull_clark_boundary_from_string(std::string_view name) {
    return variant_from_string<CatmullClarkBoundary>(name, kAllCatmullClarkBoundaries, "Catmull-Clark boundary rule");
}

}  // namespace crossdiv
