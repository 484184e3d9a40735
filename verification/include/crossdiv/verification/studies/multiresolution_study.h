#pragma once
/// @file
/// The multiresolution study (suite operation "multiresolution", over the catalog): Loop
/// multiresolution editing (subdiv/multiresolution.h) on every bundled triangle mesh, 3 levels,
/// with a detail added along the normals: the round trip, a rigid motion, and the vertices an
/// edit of a base vertex moves against the predicted reach and the subdivision support.

#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

CheckReport multiresolution_study();

}  // namespace crossdiv::verification
