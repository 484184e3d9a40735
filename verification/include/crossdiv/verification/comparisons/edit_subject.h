#pragma once
/// @file
/// A program's edge flips and splits put in core's place (the course's half-edge task): it is
/// given a triangle mesh ({in}: OBJ) and a list of operations ({ops}: one `flip A B` or
/// `split A B` per line, vertex indices 0-based, applied in order; a split appends the edge's
/// midpoint as the next vertex), and writes the mesh after them ({out}: OBJ). It is run once
/// per prefix of the list, and each result is compared with core's half-edge mesh after the
/// same operations: the vertex count, every position by index (a split's point), and the faces
/// as a set of oriented triangles. Core refuses a flip of a boundary edge or one that would
/// join two vertices already joined; a subject that flips it anyway, or refuses one core makes,
/// differs in its faces at that step.

#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {

struct EditOperation {
    enum class Kind { Flip, Split };
    Kind kind = Kind::Flip;
    int a = 0, b = 0;
    /// "flip 3 7", "split 0 1": the line of the operations file.
    std::string text() const;
};

/// The mesh after one more operation, compared.
struct EditStep {
    std::string operation;      ///< EditOperation::text()
    std::string core;           ///< what core did: "flipped to 2-5", "refused: boundary edge", "new vertex 9"
    RunOutcome outcome;         ///< the program's run for this prefix
    int core_vertices = 0, subject_vertices = 0;
    int faces_only_in_subject = 0, faces_only_in_core = 0;
    double max_position = 0;    ///< largest distance at one index, over the input's diagonal
    int worst_vertex = -1;
    bool agrees() const;
};

struct EditSubjectComparison {
    std::string input, subject;
    std::vector<EditStep> steps;  ///< up to the first step whose run failed
    bool passed() const;
    /// "4 of 4 operations agree", or the first step that does not and how.
    std::string summary() const;
};

/// Parses `flip A B` / `split A B` lines (or the CLI's comma-separated list of them).
/// @throws InputError naming the item.
std::vector<EditOperation> parse_edit_operations(const std::string& text);

/// Runs `command` once per prefix of `operations` with the time limit and compares each result.
/// @throws InputError for an operation naming no edge of the mesh core has at that point.
EditSubjectComparison compare_edit_subject(const std::string& input, const TriMesh& mesh,
                                           const std::vector<EditOperation>& operations, const std::string& subject,
                                           const TaskCommand& command, double timeout_seconds);

}  // namespace crossdiv::verification
