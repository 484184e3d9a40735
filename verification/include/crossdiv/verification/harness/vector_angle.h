#pragma once
/// @file
/// The angle between two vectors, as every normal comparison measures it.

#include <cmath>

#include <Eigen/Geometry>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// The angle between `a` and `b` in radians, from atan2(|a x b|, a . b): accurate near 0 and
/// pi, where acos of the normalized dot product loses half the digits.
inline double vector_angle(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

}  // namespace crossdiv::verification
