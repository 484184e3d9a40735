#pragma once
/// @file
/// The pages study (suite operation "pages", over the catalog): writes the report's interactive
/// curve and surface pages into the suite's output folder and checks what they show.
/// - curves/editor.html: the bundled curves in the curve editor (editor_page.h), each with
///   core's distance- and angle-mode tessellations at three tolerances and its recursive and
///   rotation-minimizing frames; checked: every distance-mode run's measured deviation within
///   its tolerance.
/// - levels/levels.html: levels 0..3 of bundled meshes under every scheme (levels_page.h);
///   checked: every level keeps its input's Euler characteristic and boundary loops.

#include <string>

#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

CheckReport pages_study(const std::string& out_dir);

}  // namespace crossdiv::verification
