#pragma once
// The curve subcommands of the crossdiv CLI: tessellate and casteljau.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command.h"

#include "crossdiv/verification/suite/case_record.h"

namespace crossdiv::cli {

struct TessellateArgs {
    std::string input, out, mode = "uniform", frames = "none", normal_side = "left";
    int intervals = 0;  ///< 0: the record's STEPS
    double angle_tol_deg = 0, tol = 0;
    bool close_frames = false;
    /// A program put in core's place (curve_subject.h): its table compared with core's.
    TaskSubjectOptions subject;
    void add_to(CLI::App& app);
};
int run_tessellate(const TessellateArgs& a);

struct CasteljauArgs {
    std::string input, json;
    double t = 0.5;
    TaskSubjectOptions subject;
    void add_to(CLI::App& app);
};
int run_casteljau(const CasteljauArgs& a);

/// Adds tessellate and casteljau; the one selected stores its exit status in `status`.
void add_curve_commands(CLI::App& app, int& status);

/// The curve half of `crossdiv bench`: on every bundled spline and the course's wineglass
/// profile (when ../shared/data is present), the edge counts and measured deviations of each
/// tessellation mode at tolerances 1e-2, 1e-3, 1e-4 of the curve's size; and the time of our
/// uniform evaluation (de Casteljau, position and derivatives) against Eigen's at the same
/// parameters, as a ratio. Prints the tables; returns {"tessellation": [...], "timing": [...]}.
nlohmann::json run_curve_bench(int repeats);

/// Prints the curve tables of suite records (checks, frame convergence, degree study,
/// tessellation counts) so the run's output carries the figures, not only results.json.
void print_curve_tables(const std::vector<verification::CaseRecord>& records);

}  // namespace crossdiv::cli
