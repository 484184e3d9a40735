#pragma once
/// @file
/// The isosurface study (suite operation "isosurface", over the catalog): marching cubes with
/// the asymptotic decider (volume/marching_cubes.h) against exact implicit surfaces, against
/// its own 1987-style face rule on ambiguous faces, and against scikit-image's marching cubes.

#include "crossdiv/verification/comparisons/isosurface_comparison.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// The sphere, torus, genus-2 surface and gyroid at 4 resolutions each: distance of every vertex
/// to the exact surface and its fitted order, Euler characteristic, watertightness and
/// manifoldness by our checks and CGAL's, enclosed volume against the exact one; the ambiguous
/// field under both face rules and scikit-image's two tables; scikit-image's MC33 on every
/// surface, vertices matched and the difference classified.
CheckReport isosurface_study();

/// The outcome of a comparison with scikit-image as the suite counts it: identical agrees, the
/// same vertices in other triangles diverge by triangulation or topology, other vertices are
/// unexplained; a failed run is the reference's failure.
Outcome skimage_outcome(const IsosurfaceRun& run, const IsosurfaceComparison* comparison);

}  // namespace crossdiv::verification
