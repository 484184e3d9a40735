#pragma once
/// @file
/// Volume files: a scalar grid as a text header and raw samples, in the two header formats
/// volume tools read and write.
///
/// - MetaImage (ITK, VTK, 3D Slicer): `key = value` lines; `.mhd` names its data file in
///   ElementDataFile, `.mha` has `ElementDataFile = LOCAL` and the samples after that line.
///   Read: ObjectType Image, NDims 3, DimSize, ElementType (MET_CHAR, MET_UCHAR, MET_SHORT,
///   MET_USHORT, MET_INT, MET_UINT, MET_FLOAT, MET_DOUBLE), ElementSpacing (or ElementSize),
///   Offset (or Position, Origin), ElementByteOrderMSB (or BinaryDataByteOrderMSB), HeaderSize
///   (bytes to skip; -1: the samples are the file's last bytes), ElementNumberOfChannels 1.
/// - NRRD (Teem): a `NRRD000n` magic line, `field: value` lines, a blank line, then the
///   samples (or `data file:` names them). Read: type, dimension 3, sizes, spacings or
///   axis-aligned space directions, space origin, encoding raw, endian, byte skip (>= 0).
///
/// Anything else that would change the samples' meaning (compression, a rotation, several
/// channels, a text encoding) is refused by name rather than misread. Samples are x fastest.
/// Hand-written rather than from a library: Debian's Teem reads NRRD but not MetaImage, ITK
/// reads both but is a large toolkit, and the raw subset of either is a page.

#include <string>

#include "crossdiv/volume/scalar_grid.h"

namespace crossdiv {

/// Reads a MetaImage (.mhd, .mha) or NRRD (.nrrd, .nhdr) volume, by extension.
/// @throws ParseError (file:line) for a malformed or unsupported header line, InputError for a
///         data file that is missing or shorter than the header says, a value that is not
///         finite (naming the sample), a grid check_grid refuses.
ScalarGrid read_volume(const std::string& path);
ScalarGrid read_metaimage(const std::string& path);
ScalarGrid read_nrrd(const std::string& path);

/// Writes `grid` as MetaImage: the header at `path` (.mhd) and the samples, little-endian
/// doubles, beside it in the same name with extension .raw.
/// @throws InputError when a file cannot be written.
void write_metaimage(const std::string& path, const ScalarGrid& grid);
/// Writes `grid` as one NRRD file, raw little-endian doubles after the header.
void write_nrrd(const std::string& path, const ScalarGrid& grid);

}  // namespace crossdiv
