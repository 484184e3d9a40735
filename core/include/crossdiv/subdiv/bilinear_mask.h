#pragma once
/// @file
/// The masks of bilinear subdivision (OpenSubdiv's Sdc::SCHEME_BILINEAR; "simple" or midpoint
/// subdivision in modelling tools): every new point is an average of the corners it lies
/// between, so the limit surface is the control mesh itself, each quad a bilinear patch.

namespace crossdiv {

/// A vertex point is the vertex itself.
inline constexpr double kBilinearVertexSelf = 1.0;
/// An edge point is the midpoint of its two ends.
inline constexpr double kBilinearEdgeEnd = 0.5;
/// A face point is the centroid of its `corners` corners.
inline constexpr double bilinear_face_corner(int corners) { return 1.0 / corners; }

}  // namespace crossdiv
