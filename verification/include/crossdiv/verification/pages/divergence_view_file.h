#pragma once
/// @file
/// The side file of the report's 3D divergence viewer: one case's DivergenceView as a
/// script, `views/jobN.js`, that a page opened from disk can load (a file:// page may run a
/// script beside it but not fetch a data file). The large arrays are little-endian binary in
/// base64, not JSON numbers: a level of 10k vertices costs 320 KB as text, 80 KB so.
///
/// The script calls `crossdivView({...})` with (schema in reports/results-schema.md):
/// - `job`, `subject` (the implementation under test);
/// - `levels[l]`: `positions` (float64 xyz per vertex), `triangles` (int32 corners; a polygon is
///   fanned from its first corner), `sizes` when some face is not a triangle (int32 corners per
///   face: the viewer draws the polygons' edges, not the fans'), and for l >= 1 where the
///   provenance is known (the primal schemes) `origins` (int32 pairs: the vertex point of old
///   vertex a as (a, -1), the edge point of old edge (a, b) as (a, b), the face point of old
///   face f as (f, -2));
/// - `levels[l].uv`, when the case compares texture coordinates: `name`, `dimension`,
///   `values` (float64, `dimension` per value) and `corners` (int32, the value of every face
///   corner in face order: a seam is two corners of one vertex with different values);
/// - `reference_uvs[name]`, with those: float64 values of the reference at every corner of the
///   last level in our corner order (NaN: its face has no partner), or null when it gave none;
///   `uv_worst_corner`, the corner where the references' values part most (-1: none diverge);
/// - `references[name][l]`: float32 xyz per vertex, the reference's position minus ours (NaN:
///   unmatched), or null where the reference has no vertex map at level l. An offset in float32
///   keeps the reference's value to 1e-7 of its distance from ours, far finer than any
///   divergence the viewer colours;
/// - `minimal`, when the suite shrank the case: `reference`, `symptom`, `tests`, `faces`,
///   `positions` and `triangles` of the minimal input (as a level's), and `reproduce`, the
///   crossdiv compare line on its OBJ file.

#include <string>

#include "crossdiv/verification/comparisons/divergence_view.h"

namespace crossdiv::verification {

/// The script text of `view` for suite job `job`.
std::string divergence_view_script(const DivergenceView& view, int job, const std::string& subject);

/// Writes divergence_view_script to `path`. @throws InputError naming the path if it cannot be written.
void write_divergence_view(const DivergenceView& view, int job, const std::string& subject, const std::string& path);

}  // namespace crossdiv::verification
