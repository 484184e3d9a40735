#pragma once
/// @file
/// Surface inputs that ship with the project (so a machine without ../shared still builds
/// and checks every surface construction), and where the course's surface files are.

#include <string>
#include <vector>

#include "crossdiv/datasets/bundled_curves.h"

namespace crossdiv::datasets {

/// vase (srev, profile ends on the axis: closed), bottle-cs (srev of a closed profile),
/// knot-tube (gcyl: circle along a trefoil, closed), bean-ring (gcyl: a non-circular closed
/// B-spline along a circle), horn (gcyl with a scale curve, open), square-frame and
/// cornered-tube (gcyl along sweeps with corners, mitred: closed and open), and two BEZ models:
/// saddle-pair (two bicubic patches sharing an edge) and pillow (six patches, closed).
const std::vector<BundledCurve>& bundled_surfaces();

/// The text of one, by name. @throws InputError naming the unknown name and the known ones.
const BundledCurve& bundled_surface(const std::string& name);

/// The course's surface files when ../shared/data exists: c3100/swp/srev/*.swp,
/// c3100/swp/gcyl/*.swp, meshedit/bez/*.bez (each folder sorted), else empty.
std::vector<std::string> course_surface_files();

}  // namespace crossdiv::datasets
