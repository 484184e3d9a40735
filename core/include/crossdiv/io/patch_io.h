#pragma once
/// @file
/// The BEZ reader (CS184 meshedit): a patch count N, then N bicubic patches of 16 control
/// points `x y z`, each patch as 4 rows of 4 points. Layout is free (the course's teapot
/// has a row per line, wavy_cube one number per line); only the order of numbers matters.

#include <istream>
#include <string>
#include <vector>

#include "crossdiv/surfaces/bezier_patch.h"

namespace crossdiv {

/// Reads a BEZ file. Each patch records the line its first number is on.
/// @throws ParseError (file:line) on a bad count, a missing, extra or non-finite number;
///         InputError if the file cannot be opened.
std::vector<BezierPatch> read_bez(const std::string& path);
std::vector<BezierPatch> read_bez(std::istream& in, const std::string& name);

}  // namespace crossdiv
