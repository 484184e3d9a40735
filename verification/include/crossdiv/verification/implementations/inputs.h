#pragma once
/// @file
/// Input names the CLI accepts: a mesh file (.obj, .off, .ply; .dae, .stl through Assimp), `bundled:NAME`, `edgecase:NAME`,
/// `uv:LAYOUT:INPUT` (an input with texture coordinates in a named layout: welded, per-face,
/// half-seam, three-regions; datasets/uv_layouts.h), or a collection: `bundled:all`, `creases:all` (the crease catalog),
/// `edgecases:all`, `uv-edgecases:all` (the face-varying cases; `uv-edgecases-tri:all` their triangulations), `uv:LAYOUT:COLLECTION` (each of its
/// inputs with texture coordinates), `course:all` (../shared/data/c3100/objs),
/// `meshedit:all` (../shared/data/meshedit/dae), `cgal:all` (datasets/cgal), and a user's own
/// folder: `dir:PATH` (every mesh file in it) or `dir:PATH/PATTERN` (its files matching a
/// shell pattern, `dir:meshes/*.obj`), not recursive, relative to the working directory.

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

/// Expands collections into single inputs, in a stable order. A collection whose folder is
/// absent expands to nothing (optional data); a `dir:` folder that is absent or holds no
/// mesh is an error. @throws InputError for an unknown collection or such a folder.
std::vector<std::string> expand_inputs(const std::vector<std::string>& specs);

/// What loading does with a shape-file tag the reader does not know (MeshSource::unknown_tags).
enum class UnknownTags {
    Refuse,  ///< InputError naming the tag and its line: refining without it would follow other rules
    Ignore,  ///< keep the mesh, each tag turned into a note (--ignore-unknown-tags)
};

/// Loads one input. @throws InputError / ParseError naming the file and line, also for an
/// unknown tag unless `unknown_tags` is Ignore.
PolyMesh load_input(const std::string& spec, UnknownTags unknown_tags = UnknownTags::Refuse);

}  // namespace crossdiv::verification
