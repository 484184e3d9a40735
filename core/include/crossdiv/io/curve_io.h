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
/// `crc2|crc3` closed Catmull-Rom (N >= 3, wraps around), `tcb2|tcb3` and `tcc2|tcc3` open and
/// closed Kochanek-Bartels splines whose keys are `[x y]` or `[x y TENSION CONTINUITY BIAS]`
/// (each in [-1, 1], 0 when left out), `ovh2|ovh3` and `ovc2|ovc3` open and closed
/// Bessel-Overhauser splines (chord-length knots; consecutive points distinct), the open ones
/// with Catmull-Rom's counts and ends, `cam3 NAME STEPS N [x y z w qx qy qz] ...` a camera path
/// (positions a bez3 chain, N = 3n + 1, and a quaternion per point, normalized on reading, whose
/// quaternion Bezier chain gives the orientation), `helx NAME STEPS RADIUS PITCH TURNS` a helix about +z,
/// `trfl NAME STEPS SCALE` a trefoil knot, and `#` comments to end of line.
///
/// BZC (meshedit): N, then N `x y` pairs: one Bezier curve of degree N - 1.

#include <istream>
#include <optional>
#include <string>
#include <string_view>

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

/// What an SWP spline keyword (bez2, bsp3, crm2, ..., kpc2, cam3) makes: its type and dimension.
struct SplineKeyword {
    CurveType type;
    int dim;
};
/// The spline an SWP keyword names; nullopt for any other word (a primitive, a surface, a typo).
std::optional<SplineKeyword> spline_keyword(std::string_view keyword);

/// Reads by extension: .swp or .bzc. @throws InputError for another extension.
CurveFile read_curve_file(const std::string& path);

/// Writes the control-point records of `curves` as SWP that read_swp reads back to the same
/// records: every spline keyword but cam3 (tcb and tcc with each key's tension, continuity and
/// bias when any is not 0), under the record's own keyword; an anonymous record is named '.'.
/// Coordinates are written with 17 significant digits, so every double reads back bit for bit.
/// @throws InputError naming the record for one SWP cannot hold this way (a primitive, a
/// camera path, a BZC curve, a keyword that does not name the record's type and dimension), a
/// sweep, or a non-finite coordinate.
void write_swp(std::ostream& out, const CurveFile& curves);
void write_swp(const std::string& path, const CurveFile& curves);

}  // namespace crossdiv
