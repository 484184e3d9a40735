#pragma once
/// @file
/// The surface checks: every srev/gcyl surface of an SWP file and every BEZ patch model
/// built, then checked as a closed surface by our mesh checks and by CGAL (watertight,
/// manifold, outward, volume); Bezier patches against the Bernstein tensor sum and across
/// shared boundaries; and the studies against exact surfaces (sphere of revolution, torus as
/// a generalized cylinder) and against OpenSubdiv's Bfr limit surface. The suite runs these
/// as its `surfaces` operation; records have the curve checks' shape (scheme "surfaces").

#include <span>
#include <functional>
#include <string>
#include <vector>

#include "crossdiv/curves/curve_record.h"
#include "crossdiv/surfaces/bezier_patch.h"
#include "crossdiv/surfaces/sweep_surface.h"
#include "crossdiv/verification/properties/curve_checks.h"

namespace crossdiv::verification {

/// What check_surface_mesh should know about the mesh's construction.
struct MeshCheckContext {
    /// Patch models: separate parts that touch at a point (the teapot's handle ends on a
    /// body vertex) weld into a bowtie vertex; such non-manifold vertices are counted apart
    /// (table "point_contacts") instead of as mesh errors.
    bool point_contacts_expected = false;
    /// Tubes: per vertex, whether the tube folds over there (its offset from the sweep
    /// exceeds the sweep's radius of curvature toward it); empty when unknown.
    std::vector<char> folded_vertex;
};

/// Checks of one built mesh, appended to `checks` under `name`: our mesh checks find no
/// error, the faces agree with the vertex normals (no face whose normal points away from
/// its corners' mean normal), and, when `closed`, no boundary edge, a positive signed
/// volume, and CGAL's is_valid_polygon_mesh / is_closed / is_outward_oriented / volume
/// agreeing. Returns a table row with the measured values.
nlohmann::json check_surface_mesh(const std::string& name, const SurfaceMesh& surface, bool closed,
                                  std::vector<Check>& checks, const MeshCheckContext& context = {});

/// How check_sweep_file builds a surface: build_sweep; tests substitute a deliberately broken one.
using SweepBuilder = std::function<SweepSurface(const CurveFile&, int, const SweepOptions&)>;

/// Every srev and gcyl record of the file (gcyl with the seed's recursive frames and with
/// RMF), with check_surface_mesh; srev surfaces also get their measured deviation from the
/// exact surface of revolution in the table. Whether a surface must be closed is read from
/// the records (the exact curve ends), never from the tessellation checked, and the
/// construction's own claim is checked against it ("closed-as-input").
CheckReport check_sweep_file(const CurveFile& file, const std::string& input, const SweepBuilder& build = build_sweep);

/// A BEZ model: de Casteljau against the Bernstein tensor sum on an 11 x 11 grid per patch,
/// the largest gap along shared patch boundaries, and check_surface_mesh of the welded
/// tessellation (closed when it has no boundary edge).
CheckReport check_patch_file(std::span<const BezierPatch> patches, const std::string& input);

/// The studies: the sphere of revolution (exact circle profile and cubic Bezier profile)
/// and the torus (circle along circle, recursive and RMF frames) at five doubling
/// resolutions against the analytic surfaces, and the Catmull-Clark limit of regular grids
/// against OpenSubdiv's Bfr (when built with OpenSubdiv).
CheckReport check_surface_studies();

/// Surface input names: a .bez file, a .swp file, `surface:NAME` (bundled), or the
/// collections `surfaces:bundled`, `surfaces:course` (../shared/data: c3100/swp/{srev,gcyl}
/// and meshedit/bez), `surfaces:synthetic`.
std::vector<std::string> expand_surface_inputs(const std::vector<std::string>& specs);

/// Runs the checks one input names, sweeps built by `build`.
/// @throws InputError / ParseError naming file and line.
CheckReport check_surface_input(const std::string& spec, const SweepBuilder& build = build_sweep);

}  // namespace crossdiv::verification
