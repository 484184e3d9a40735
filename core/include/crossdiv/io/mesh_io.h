#pragma once
/// @file
/// OBJ and OFF reading and writing. Readers keep vertex order, face order and each face's
/// corner order exactly, keep polygons as polygons, and record each element's source line.
/// Writers print 17 significant digits, enough for a double to read back bit-identical.

#include <iosfwd>
#include <span>
#include <string>
#include <string_view>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

/// Reads a Wavefront OBJ: `v x y z [r g b]`, `vt u [v [w]]` and `f` lines (`i`, `i/t`, `i//n`,
/// `i/t/n`; negative indices count back from the last vertex or texture coordinate read).
/// Texture coordinates the faces index become face-varying channel "uv" (2 components, 3
/// when a `vt` has a w), exactly as written; normals, groups, objects, smoothing groups,
/// materials and lines are skipped; OpenSubdiv's shape-file tags are read (crease_tags.h). Lines with an
/// unknown statement are skipped too (real course files carry browser HTML around the OBJ)
/// and summarized in source.notes with the first such line; geometry lost that way shows up
/// as an out-of-range index, which is an error.
/// @param name the file name used in messages.
/// @throws ParseError with `name:line` on a malformed `v`, `vt` or `f` line, a missing or
///         non-numeric coordinate, NaN or infinity, an index that is 0 or out of range, or a
///         face corner without a texture index in a file whose first corner has one (or the
///         reverse).
PolyMesh read_obj(std::istream& in, const std::string& name);

/// Reads an OFF file (`OFF` or `COFF` header, counts, vertices, faces `n i0 .. in-1`).
/// Extra values after a face's indices (colors) are ignored; after a COFF vertex, the first
/// three are taken as its color.
/// @throws ParseError with `name:line`, as read_obj.
PolyMesh read_off(std::istream& in, const std::string& name);

/// Reads a PLY file (ASCII, binary little or big endian): the x, y, z of element `vertex` in
/// file order and the `vertex_indices` (or `vertex_index`) list of element `face`; other
/// properties and elements are read past. Binary float coordinates read back exactly.
/// @throws ParseError with `name:line` (in binary data, the line of the element's
///         declaration and the record's index), NonFiniteNumber for NaN or infinity.
PolyMesh read_ply(std::istream& in, const std::string& name);

/// The extensions read_mesh takes: ".obj", ".off", ".ply" (compared without case).
std::span<const std::string_view> mesh_extensions();

/// Reads a mesh file, choosing the format by extension (.obj, .off, .ply).
/// @throws InputError if the file cannot be opened or the extension is unknown, ParseError
///         on malformed content.
PolyMesh read_mesh(const std::string& path);

/// Writes OBJ (`v x y z [r g b]`, 1-based `f` lines) with 17 significant digits. The first
/// face-varying channel, if any, is written as `vt` lines and faces `f v/t ...`. With
/// `normals` (one per vertex), also `vn` lines and faces as `f a//a b//b c//c` (`a/t/a` with
/// texture coordinates). Tags are written in the shape-file format.
/// @throws std::logic_error if normals is neither empty nor one per vertex, or the channel
///         does not fit the mesh.
void write_obj(std::ostream& out, const PolyMesh& mesh, std::span<const Vec3> normals = {});
/// Writes OFF with 17 significant digits.
void write_off(std::ostream& out, const PolyMesh& mesh);
/// Writes ASCII PLY with double coordinates and 17 significant digits.
void write_ply(std::ostream& out, const PolyMesh& mesh);
/// Writes by extension (.obj, .off, .ply). @throws InputError if the file cannot be written.
void write_mesh(const std::string& path, const PolyMesh& mesh);

}  // namespace crossdiv
