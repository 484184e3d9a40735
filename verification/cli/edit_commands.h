#pragma once
// The half-edge subcommands of the crossdiv CLI: edit (flips and splits in order) and normals
// (our weightings against OpenMesh and CGAL); the half-edge part of check.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "command.h"

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::cli {

struct EditArgs {
    std::string input, out;
    /// Operations in command-line order: ("flip" | "split", "A-B").
    std::vector<std::pair<std::string, std::string>> ops;
    bool check = false;
    TaskSubjectOptions subject;  ///< a program put in core's place (edit_subject.h)
    void add_to(CLI::App& app);
};
/// Applies the flips and splits in order (edges by endpoint indices, 0-based in the input's
/// vertex order; new vertices appended), printing each refusal with its reason; with --check
/// runs the half-edge validity check after every operation. Exit 0, or 1 when an operation was
/// refused or a check failed; 2 for bad input (an edge that does not exist, a bad name).
int run_edit(const EditArgs& a);

struct NormalsArgs {
    std::string input, weighting = "area", against, json;
    /// A program put in core's place (normals_subject.h).
    TaskSubjectOptions subject;
    void add_to(CLI::App& app);
};
/// Vertex normals with the named weighting, compared with each reference asked for: the
/// largest angle between ours and theirs, which of our weightings theirs matches, and the
/// vertex where they differ most. JSON: {"normals": [[x, y, z], ...], "weighting", "references"}.
int run_normals(const NormalsArgs& a);

/// Adds edit and normals; the one selected stores its exit status in `status`.
void add_edit_commands(CLI::App& app, int& status);

/// The half-edge view of `mesh` for `crossdiv check`: counts, boundary loops and every broken
/// invariant, or why no half-edge mesh can be built. Returns the number of errors.
int print_halfedge_report(const PolyMesh& mesh);

}  // namespace crossdiv::cli
