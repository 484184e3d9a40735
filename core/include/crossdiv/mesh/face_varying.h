#pragma once
/// @file
/// Face-varying data: values attached to face corners rather than to vertices, so that a
/// vertex on a seam carries one value per side (texture coordinates are the common case).
/// Stored as OpenSubdiv stores a face-varying channel (Far::TopologyDescriptor::FVarChannel):
/// a table of values and, for every face corner, the index of its value. Two corners of a
/// vertex share a value exactly when they name the same index; two indices whose numbers
/// happen to be equal are still two values (the sides of a seam may coincide), as in
/// OpenSubdiv, so topology is read from the indices and never from the numbers.

#include <string>
#include <vector>

namespace crossdiv {

struct PolyMesh;

/// One face-varying channel of a mesh.
struct FaceVaryingChannel {
    std::string name = "uv";  ///< what the values are ("uv" for OBJ texture coordinates)
    int dimension = 2;        ///< components per value, at least 1
    /// The values, `dimension` numbers each: value i is values[i * dimension .. (i + 1) * dimension).
    std::vector<double> values;
    /// The value of every face corner, in the order of PolyMesh::face_vertices.
    std::vector<int> corner_values;

    int num_values() const { return dimension > 0 ? static_cast<int>(values.size()) / dimension : 0; }
    const double* value(int i) const { return values.data() + static_cast<size_t>(i) * dimension; }
    double* value(int i) { return values.data() + static_cast<size_t>(i) * dimension; }
};

/// Checks that every channel of `mesh` fits it: a dimension of at least 1, a whole number of
/// values, one value index per face corner, every index in range and every value finite.
/// @throws InputError naming the channel and the first bad face corner (with the face's
///         source line when the mesh has one) or value.
void check_face_varying(const PolyMesh& mesh);

}  // namespace crossdiv
