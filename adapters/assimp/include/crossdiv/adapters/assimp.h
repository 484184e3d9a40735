#pragma once
/// @file
/// Assimp adapter: mesh input in the formats our own readers do not parse (COLLADA .dae, the
/// meshedit course files; STL, AC3D, LightWave, FBX, glTF, 3DS, Blender, X, ASE, AMF and the
/// rest of Assimp's list). Not a subdivision reference: it only reads.

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::adapters::assimp {

/// The extensions read through Assimp, lower case with their dot, sorted: every one Assimp's
/// Importer lists ("*.3ds;*.ac;..."), but those core reads itself (mesh_extensions(): OBJ,
/// OFF, PLY).
const std::vector<std::string>& extensions();

/// Reads every mesh of the scene into one polygon mesh, in world coordinates (node transforms
/// applied: aiProcess_PreTransformVertices), polygons kept as polygons (no triangulation).
/// Assimp stores one vertex per face corner for COLLADA (each corner has its own normal and
/// texture coordinate), so the shared vertices are recovered here by welding corners with
/// bit-identical positions (Assimp's JoinIdenticalVertices would also compare normals and
/// uses a tolerance). Vertices are numbered in order of first use by the faces, which is the
/// vertex order `crossdiv edit` indices refer to for these formats. Point and line
/// primitives are skipped and counted in source.notes. Texture coordinates (the first set)
/// become face-varying channel "uv" when every mesh of the scene has them (else a note says
/// which has none): the corners of one vertex with bit-identical coordinates share a value,
/// and different ones are a seam (Assimp keeps a value per corner, not the file's indices).
/// @throws InputError naming the file with Assimp's message when it cannot read it, when the
///         scene has no polygon, or naming the vertex when a coordinate is NaN or infinite.
PolyMesh read_mesh(const std::string& path);

/// "Assimp 5.2.5".
std::string version();

}  // namespace crossdiv::adapters::assimp
