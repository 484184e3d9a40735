#pragma once
/// @file
/// The report's subdivision-levels page (reports/levels/): each level of a mesh refined by core
/// under one scheme, side by side, with the control net over every level, the level's
/// wireframe and flat or smooth shading (the seed's GUI views), one camera for all.
///
/// The folder holds levels.html, levels.js, Debian's three.js and levels-data.js:
/// `window.CROSSDIV_LEVELS = {entries: [{mesh, scheme, rule, levels: [{positions, triangles,
/// edges, faces}]}]}`, the arrays as in page_arrays.h (float64 positions, int32 fanned
/// triangles, int32 edge pairs).

#include <nlohmann/json.hpp>
#include <string>

#include "crossdiv/adapters/reference.h"

namespace crossdiv::verification {

/// One mesh refined by one scheme, level by level.
struct LevelsEntry {
    std::string mesh;
    std::string scheme;
    std::string rule;
    adapters::LevelTrace levels;
};

/// The page's data script for `entries`.
std::string levels_data_script(const std::vector<LevelsEntry>& entries);

/// Writes the page into `dir` (created if missing). @throws InputError naming a file that
/// cannot be read or written.
void write_levels_page(const std::string& dir, const std::vector<LevelsEntry>& entries);

}  // namespace crossdiv::verification
