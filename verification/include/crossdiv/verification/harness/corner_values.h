#pragma once
/// @file
/// Face-varying values (texture coordinates) of two refinements of one mesh, compared corner
/// by corner: faces are matched through the vertex correspondence (a face is its set of
/// vertices), and each corner's value within its face by its vertex. Value indices play no
/// part: two implementations number their values their own way, and a seam shows as two
/// corners of one vertex with different values, whatever their indices.

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// The first face-varying channel of `ours` against that of `ref`.
struct CornerValueComparison {
    /// Why nothing was compared ("" when compared): a side without a channel, channels of
    /// different dimension, a face of `ref` with no partner in `ours`.
    std::string not_compared;
    int corners = 0;        ///< corners compared
    double max_abs = 0;     ///< the largest component difference
    double uv_box = 0;      ///< the diagonal of the box of ours' values
    double max_rel = 0;     ///< max_abs / uv_box (max_abs when the box is a point)
    int worst_face = -1;    ///< ours, where max_abs is
    int worst_corner = -1;  ///< its corner (0 .. face size - 1)
    int worst_vertex = -1;  ///< ours, the vertex of that corner
    bool compared() const { return not_compared.empty(); }
};

/// Compares the channels; `ref_to_ours` maps each vertex of `ref` to one of `ours` (a
/// Correspondence's ref_to_ours, a bijection).
CornerValueComparison compare_corner_values(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours);

/// The values of `ref`'s first channel at every corner of `ours`, in ours' corner order
/// (face_vertices), `dimension` numbers per corner; NaN at a corner of a face that has no
/// partner in `ref`. Empty when compare_corner_values could not compare the channels. What
/// the report's viewer shows beside ours at a picked corner.
std::vector<double> corner_values_in_our_order(const PolyMesh& ours, const PolyMesh& ref, const std::vector<int>& ref_to_ours);

/// The diagonal of the box of a channel's first two components (of its only one, for a
/// one-component channel): the scale face-varying tolerances are relative to.
double uv_box_diagonal(const FaceVaryingChannel& channel);

/// What a face-varying value is at its vertex, for locating where two implementations part.
enum class UvVertexClass {
    Interior,  ///< one value, inside the mesh: the vertex's own rule
    Boundary,  ///< one value, on the mesh's boundary
    Seam,      ///< two values: a seam passes (or ends, at a boundary)
    Junction,  ///< three or more values: UV regions meet (whatever the value's own faces)
    Corner,    ///< fewer than three values, and this one has one face at its vertex (a UV corner)
};
/// "interior", "boundary", "seam", "junction", "corner".
const char* to_string(UvVertexClass c);

/// The class of the value at every corner of `mesh` (its first channel), in corner order
/// (face_vertices); O(corners log corners).
std::vector<UvVertexClass> uv_corner_classes(const PolyMesh& mesh);

/// The class of the value at corner `corner` of face `face` of `mesh` (uv_corner_classes).
UvVertexClass uv_vertex_class(const PolyMesh& mesh, int face, int corner);

}  // namespace crossdiv::verification
