#pragma once
/// @file
/// VTK 9 adapter: the triangle subdivision filters of VTK's FiltersModeling module on a
/// vtkPolyData of double-precision points, one translation unit (vtk_subdivision.cpp).
///
/// Each filter runs once per level on the level before (NumberOfSubdivisions = 1), so every
/// level can be read; a filter keeps no state between calls. VTK keeps the input's points first,
/// in order, and appends one point per edge.

#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv::adapters::vtk {

/// The three subdivision filters.
enum class Filter {
    Loop,       ///< vtkLoopSubdivisionFilter (approximating)
    Butterfly,  ///< vtkButterflySubdivisionFilter (interpolating)
    Linear,     ///< vtkLinearSubdivisionFilter (each triangle into four at its edge midpoints)
};

/// "vtkLoopSubdivisionFilter", ...
const char* filter_name(Filter filter);

/// `levels` levels of `filter` on `mesh`.
/// @throws Rejected with VTK's own words when the filter reports an error (VTK's filters
///         refuse a non-manifold edge, for one) or returns no triangles.
LevelTrace subdivide(const TriMesh& mesh, Filter filter, int levels);

/// The same refinement in one filter call of `levels` subdivisions, kept in VTK's structures:
/// what `crossdiv bench` times. Returns the number of output faces. @throws as subdivide().
size_t subdivide_native(const TriMesh& mesh, Filter filter, int levels);

/// "VTK 9.1.0".
std::string version();

}  // namespace crossdiv::adapters::vtk
