#pragma once
/// @file
/// Small curve files written into the code (SWP and BZC text, read by the real readers), each
/// a named case for the curve checks and `crossdiv tessellate curve:NAME`; and where the
/// course's curve files live.

#include <string>
#include <vector>

#include "crossdiv/curves/curve_record.h"

namespace crossdiv::datasets {

struct BundledCurve {
    std::string name;
    std::string description;  ///< one line: what it exercises
    std::string format;       ///< "swp" or "bzc"
    std::string text;         ///< the file's content
};

/// Every bundled curve file: s-curve, cusp, flower (closed B-spline), catmull-rom-open,
/// catmull-rom-star (closed), space-bspline, helix, trefoil, circles, degree-9.
const std::vector<BundledCurve>& bundled_curves();

/// A bundled curve file read by its reader (path "curve:NAME"). @throws InputError naming
/// the unknown name and listing the known ones.
CurveFile bundled_curve_file(const std::string& name);

/// The course's curve files when ../shared/data exists (c3100/swp/**.swp, then
/// meshedit/bzc/*.bzc, each sorted), else empty.
std::vector<std::string> course_curve_files();

}  // namespace crossdiv::datasets
