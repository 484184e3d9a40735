#pragma once
/// @file
/// A program's vertex normals put in core's place (the course's vertex-normal task): it is
/// given a triangle mesh as OBJ ({in}) and writes one normal per vertex, in the vertex order of
/// the input ({out}: OBJ `vn` lines, or plain `x y z` lines). Every normal is compared, by
/// angle, with core's under each weighting (area, angle, uniform; vertex_normals.h) and each
/// one reversed, and the weighting that fits is named.

#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {

/// How far the subject's normals lie from core's under one weighting, in degrees.
struct WeightingFit {
    std::string name;  ///< "area", "angle", "uniform", or one of them with ", reversed"
    double max_deg = 0;
    int worst_vertex = -1;
    bool fits = false;
};

struct NormalsSubjectComparison {
    std::string input, subject;
    RunOutcome outcome;
    int vertices = 0;
    int compared = 0;            ///< vertices core gives a normal (a vertex without faces has none)
    std::vector<WeightingFit> weightings;
    std::string weighting;       ///< the first that fits ("" none)
    double length_error = 0;     ///< largest | |n| - 1 | over the compared vertices
    /// A weighting fits, not reversed, and the normals are unit.
    bool passed() const;
    std::string summary() const;
};

/// Writes `mesh` as OBJ, runs `command` on it with the time limit and compares what it writes.
/// Crashes, hangs, a nonzero exit, no file, an unreadable line (file:line), a non-finite number
/// and another count of normals than vertices are named outcomes.
NormalsSubjectComparison compare_normals_subject(const std::string& input, const TriMesh& mesh, const std::string& subject,
                                                 const TaskCommand& command, double timeout_seconds);

}  // namespace crossdiv::verification
