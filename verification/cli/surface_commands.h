#pragma once
// The surface subcommands of the crossdiv CLI: sweep and patch; the surface part of bench.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "command.h"
#include <vector>

#include "crossdiv/surfaces/surface_mesh.h"
#include "crossdiv/verification/suite/case_record.h"

namespace crossdiv::cli {

struct SweepArgs {
    std::string input, out, frames = "recursive";
    bool adaptive = false;
    double tol = 0;
    long long max_faces = kDefaultMaxSurfaceTriangles;
    TaskSubjectOptions subject;  ///< a program put in core's place (surface_subject.h)
    void add_to(CLI::App& app);
};
/// Builds every srev and gcyl record of the file into one OBJ with normals; prints per
/// surface its size, whether it is closed and watertight, and its signed volume.
int run_sweep(const SweepArgs& a);

struct PatchArgs {
    std::string input, out;
    int res = 8;
    long long max_faces = kDefaultMaxSurfaceTriangles;
    TaskSubjectOptions subject;  ///< a program put in core's place (surface_subject.h)
    void add_to(CLI::App& app);
};
/// Tessellates a BEZ file (res x res quads per patch, welded) into an OBJ with normals.
int run_patch(const PatchArgs& a);

/// Adds sweep and patch; the one selected stores its exit status in `status`.
void add_surface_commands(CLI::App& app, int& status);

/// The surface half of `crossdiv bench`: the wineglass (../shared/data/c3100/swp/srev, or
/// the bundled vase when absent) with the seed's uniform steps against the adaptive sweep
/// at the same measured deviation from the exact surface: both face counts, both
/// deviations, and the seed's own ratio (33120 / 18540) beside ours. Prints the table;
/// returns it as JSON.
nlohmann::json run_surface_bench();

/// Prints the surface tables of suite records (sphere, torus, Bfr, each surface built).
void print_surface_tables(const std::vector<verification::CaseRecord>& records);

}  // namespace crossdiv::cli
