#pragma once
/// @file
/// The curve editor page (reports/editor/): a static folder that opens from disk, offline, in
/// which a user adds, removes and drags the control points of Bezier chains, B-splines and
/// Catmull-Rom splines, sees the curve, its uniform tessellation and its de Casteljau
/// construction, and exports SWP. `crossdiv editor` writes it for a user's curves; the suite's
/// `pages` study writes it for the bundled curves with core's adaptive tessellations and frames,
/// the report's curves page.
///
/// The folder holds editor.html, editor.js, spline_math.js, Debian's three.min.js and
/// OrbitControls.js (libjs-three), and curves.js: `window.CROSSDIV_EDITOR_DATA = {title,
/// curves: [{name, keyword, steps, points: [[x, y, z]...], core?}], skipped: [label...], solo?}`
/// (solo: draw the selected curve alone, framed in its own dimension), every
/// coordinate as JSON's shortest exact decimal. `core` (the report's) is {tessellations: [{mode,
/// tol, edges, deviation, points, worst}], frames: {recursive|rmf: {points, T, N, B}}}.

#include <nlohmann/json.hpp>
#include <initializer_list>
#include <string>
#include <vector>

#include "crossdiv/curves/curve_record.h"

namespace crossdiv::verification {

/// Whether the editor edits a record of this type: Bezier chains, B-splines and open and
/// closed Catmull-Rom splines (the records whose Bezier segments its script builds).
bool editor_edits(const CurveRecord& record);

/// Core's view of one record for the report's page: the distance and angle modes at three
/// tolerances each (points, edge count, measured deviation and the curve point where it is
/// reached) and the recursive and rotation-minimizing frames on the uniform tessellation.
nlohmann::json core_curve_views(const CurveRecord& record);

/// The page's data: the editable records of `files` (each labelled by its file), the others
/// named in `skipped` ("file: label (keyword, line N)"). With `with_core`, each curve carries
/// core_curve_views.
nlohmann::json editor_data(const std::vector<CurveFile>& files, const std::string& title, bool with_core);

/// Writes the editor folder `dir` (created if missing) with `data` as curves.js.
/// @throws InputError naming the file that cannot be read (Debian's three.js missing: install
/// libjs-three) or written.
void write_editor_page(const std::string& dir, const nlohmann::json& data);

/// Makes a page's folder `dir` (created if missing): Debian's three.min.js and OrbitControls.js,
/// and `files` from the report's folder `page` (reports/editor, reports/levels). The editor and
/// the levels page share it. @throws InputError as above.
void prepare_page_folder(const std::string& dir, const std::string& page, std::initializer_list<const char*> files);

}  // namespace crossdiv::verification
