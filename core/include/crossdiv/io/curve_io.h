#pragma once
/// @file
/// Curve file readers. Every error is a ParseError naming the file and line.
///
/// SWP (CS-C3100 course format), whitespace-separated, points in brackets, any layout:
///
///     bez2 NAME STEPS N [x y] ...      piecewise cubic Bezier, N = 3n + 1
///     bsp2 NAME STEPS N [x y] ...      uniform cubic B-spline, N >= 4
///     bez3 / bsp3 NAME STEPS N [x y z] ...
///     circ NAME STEPS RADIUS           circle in the xy-plane
///     srev NAME STEPS PROFILE          surface of revolution of curve PROFILE
///     gcyl NAME PROFILE SWEEP [SCALE]  generalized cylinder; SCALE (our extension) sizes the profile
///
/// NAME '.' is anonymous. Our extensions, which standard files never contain so standard
/// files read unchanged: `crm2|crm3 NAME STEPS N [..]...` open Catmull-Rom (N >= 4),
/// `crc2|crc3` closed Catmull-Rom (N >= 3, wraps around), `helx NAME STEPS RADIUS PITCH TURNS`
/// a helix about +z, `trfl NAME STEPS SCALE` a trefoil knot, and `#` comments to end of line.
///
/// BZC (meshedit): N, then N `x y` pairs: one Bezier curve of degree N - 1.

#include <istream>
#include <string>

#include "crossdiv/curves/curve_record.h"

namespace crossdiv {

/// Reads an SWP file. @throws ParseError (file:line) on an unknown record, an unbalanced
/// bracket, a wrong point count or coordinate count, a non-finite number, a repeated or
/// undefined curve name; InputError if the file cannot be opened.
CurveFile read_swp(const std::string& path);
CurveFile read_swp(std::istream& in, const std::string& name);

/// Reads a BZC file. @throws ParseError (file:line) on a bad count, a missing or extra
/// number, a non-finite number.
CurveFile read_bzc(const std::string& path);
CurveFile read_bzc(std::istream& in, const std::string& name);

/// Reads by extension: .swp or .bzc. @throws InputError for another extension.
CurveFile read_curve_file(const std::string& path);

}  // namespace crossdiv
