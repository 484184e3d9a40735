#pragma once
/// @file
/// A program's surface tessellation put in core's place (the course's Bezier-patch task and
/// its surfaces of revolution and generalized cylinders): it is given the input file ({in}:
/// BEZ or SWP; the resolution is a literal of its command) and writes an OBJ with a `vn` per
/// `v` ({out}), welded or not, in any order, with or without faces. Its vertices and core's
/// are matched by position both ways (nearest neighbours), so the two point sets must cover
/// each other; at matched points its normals are held to core's and to their reversal, and
/// the one that fits is named; where it writes faces, each face is checked to turn towards its
/// vertices' normals.

#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/isolate.h"

namespace crossdiv::verification {

struct SurfaceNormalFit {
    std::string name;  ///< "as core's" or "reversed"
    double max_deg = 0;
    int off = 0;       ///< vertices beyond the tolerance
    bool fits = false;
};

struct SurfaceSubjectComparison {
    std::string input, subject;
    RunOutcome outcome;
    int core_vertices = 0, subject_vertices = 0;
    double subject_to_core = 0;  ///< largest distance from a subject vertex to core's nearest, over core's diagonal
    double core_to_subject = 0;  ///< ... and back: a part of the surface it left out
    bool positions_fit = false;
    std::vector<SurfaceNormalFit> normals;
    std::string normal_rule;     ///< the first that fits ("" none)
    int zero_normals = 0;        ///< its vertices with a zero normal (a degenerate point it left undecided): not held
    int faces = 0, faces_against_normals = 0;
    bool passed() const;
    std::string summary() const;
};

/// Core's samples of the surface before welding: a point of a seam or a corner once per patch
/// (or sweep piece) that has it, each with that piece's normal.
struct SurfaceSamples {
    std::vector<Vec3> positions, normals;
    int welded_vertices = 0;  ///< how many vertices core's welded tessellation has
};

/// Runs `command` on `input_file` with the time limit and compares what it writes with
/// `core`. A subject normal fits where it matches the normal of some core sample at its
/// position (a seam's vertex has one per piece). Crashes, hangs, a nonzero exit, no file, an
/// unreadable line (file:line), a non-finite number and a count of `vn` other than of `v` are
/// named outcomes.
SurfaceSubjectComparison compare_surface_subject(const std::string& input_file, const SurfaceSamples& core,
                                                 const std::string& subject, const std::string& command,
                                                 double timeout_seconds);

}  // namespace crossdiv::verification
