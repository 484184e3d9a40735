#pragma once
/// @file
/// Meshes as the report's pages read them: little-endian binary arrays in base64 (RFC 4648),
/// which a page decodes into JavaScript typed arrays. A level of 10k vertices costs 320 KB as
/// JSON text and 80 KB so.

#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

// Typed arrays take the machine's byte order: little-endian on every machine a browser runs
// on, and on this one.
static_assert(std::endian::native == std::endian::little, "page arrays are written as little-endian");

/// RFC 4648 base64 of `n` bytes.
std::string base64(const unsigned char* bytes, size_t n);

/// base64 of the bytes of `values`.
template <class T>
std::string base64(const std::vector<T>& values) {
    return base64(reinterpret_cast<const unsigned char*>(values.data()), values.size() * sizeof(T));
}

/// float64 xyz per vertex.
std::string positions64(const PolyMesh& mesh);
/// int32 corners of triangles; a polygon is fanned from its first corner.
std::string triangles32(const PolyMesh& mesh);
/// Every face's number of corners as int32 (with triangles32, the faces drawn as polygons: a
/// face of n corners is n - 2 of the triangles, fanned from its first corner).
std::string face_sizes32(const PolyMesh& mesh);
/// int32 vertex pairs, one per edge (MeshTopology::edge_list).
std::string edges32(const std::vector<std::array<int, 2>>& edges);

}  // namespace crossdiv::verification
