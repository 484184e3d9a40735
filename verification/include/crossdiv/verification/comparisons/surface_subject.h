#pragma once
/// @file
/// A program's surface tessellation put in core's place (the course's Bezier-patch task and
/// its surfaces of revolution and generalized cylinders): it is given the input file ({in}:
/// BEZ or SWP; the resolution is a literal of its command) and writes an OBJ with a `vn` per
/// `v` ({out}), welded or not, in any order, with or without faces. Its vertices and core's
/// are matched by position both ways (nearest neighbours), so the two point sets must cover
/// each other; at matched points its normals are held to core's and to their reversal, and
/// the one that fits is named; where it writes faces, each face is checked to turn towards its
/// vertices' normals, and the surface, welded, to have no more boundary edges than core's (a
/// crack at a seam, a ring left unjoined). Core may offer several conventions (a generalized
/// cylinder's frames, closed or not): the first is core's own, the others name what a subject
/// that misses it follows instead.

#include <span>
#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/surfaces/bezier_patch.h"
#include "crossdiv/surfaces/sweep_surface.h"
#include "crossdiv/surfaces/surface_mesh.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {

struct SurfaceNormalFit {
    std::string name;  ///< "as core's" or "reversed"
    double max_deg = 0;
    int off = 0;       ///< vertices beyond the tolerance
    bool fits = false;
};

/// A subject's positions against one of core's conventions.
struct SurfacePositionFit {
    std::string convention;
    double subject_to_core = 0;  ///< largest distance from a subject vertex to core's nearest, over core's diagonal
    double core_to_subject = 0;  ///< ... and back: a part of the surface it left out
    bool fits = false;
};

struct SurfaceSubjectComparison {
    std::string input, subject;
    RunOutcome outcome;
    int core_vertices = 0, subject_vertices = 0;
    double subject_to_core = 0;  ///< against core's own convention (the first)
    double core_to_subject = 0;
    bool positions_fit = false;  ///< on core's own convention
    std::vector<SurfacePositionFit> conventions;  ///< every convention core offered, in its order
    std::string convention;      ///< the first whose positions fit ("" none); normals and faces are held to it
    std::string core_convention; ///< core's own (the first offered; "" when it offered one unnamed)
    std::vector<SurfaceNormalFit> normals;
    std::string normal_rule;     ///< the first that fits ("" none)
    int zero_normals = 0;        ///< its vertices with a zero normal (a degenerate point it left undecided): not held
    int faces = 0, faces_against_normals = 0;
    int core_folded_faces = 0;   ///< core's own faces against its normals (a tube folding over itself)
    int boundary_edges = -1;     ///< of its faces, welded at the position tolerance (-1: it wrote no faces)
    int core_boundary_edges = 0;
    /// Whether the convention it follows is core's own (the first offered).
    bool follows_core() const;
    bool passed() const;
    std::string summary() const;
};

/// Core's samples of the surface before welding: a point of a seam or a corner once per patch
/// (or sweep piece) that has it, each with that piece's normal.
struct SurfaceSamples {
    std::string convention;   ///< how core built them ("" when it offers only one way)
    std::vector<Vec3> positions, normals;
    int welded_vertices = 0;  ///< how many vertices core's welded tessellation has
    int boundary_edges = 0;   ///< ... and boundary edges (0: watertight)
    int folded_faces = 0;     ///< ... and faces that turn against its own normals (a surface folding over itself)
};

/// Appends one piece of core's surface: its samples before welding (`positions`, `normals`)
/// and the welded surface they make (its vertices, boundary edges and folded faces counted).
void add_surface_piece(SurfaceSamples& samples, std::span<const Vec3> positions, std::span<const Vec3> normals,
                       const SurfaceMesh& welded);

/// Core's samples of every srev and gcyl record of `file` under `options`, first: its own; when
/// the file has a generalized cylinder, then the other frame conventions (recursive or
/// rotation-minimizing frames, the seam closed or left open), each named.
/// @throws ParseError / InputError as build_sweep does.
std::vector<SurfaceSamples> sweep_conventions(const CurveFile& file, const SweepOptions& options);

/// Core's grid of every patch at `res` quads a side before welding (each point with its own
/// patch's normal) and the counts of `welded`, core's tessellation of them.
SurfaceSamples patch_samples(const std::vector<BezierPatch>& patches, int res, const SurfaceMesh& welded);

/// How many faces of `mesh` turn against the normals given at their vertices (Newell's area
/// vector against their sum); faces of no area (below `area_floor`) are not counted.
int faces_against_normals(const PolyMesh& mesh, std::span<const Vec3> normals, double area_floor);

/// Boundary edges of `mesh` once its vertices are welded at `tol`: edges of one face only
/// (edges that welding collapses are dropped).
int welded_boundary_edges(const PolyMesh& mesh, double tol);

/// Runs `command` on `input_file` with the time limit and compares what it writes with
/// `conventions` (core's first). A subject normal fits where it matches the normal of some core sample at its
/// position (a seam's vertex has one per piece). Crashes, hangs, a nonzero exit, no file, an
/// unreadable line (file:line), a non-finite number and a count of `vn` other than of `v` are
/// named outcomes.
SurfaceSubjectComparison compare_surface_subject(const std::string& input_file, std::span<const SurfaceSamples> conventions,
                                                 const std::string& subject, const TaskCommand& command,
                                                 double timeout_seconds);

}  // namespace crossdiv::verification
