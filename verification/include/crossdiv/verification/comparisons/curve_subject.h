#pragma once
/// @file
/// A program's curve tessellation put in core's place (the course's curve task): it is given
/// an SWP or BZC file and writes, for every record, the uniform samples (the record's STEPS
/// intervals per segment, as `crossdiv tessellate` makes them) with their tangent, normal and
/// binormal. Each curve is compared sample by sample with core under every convention that
/// could explain it, and the one that fits is named:
///   positions  as written (the record's own basis), or the other cubic basis where the
///              record is a Bezier chain or a uniform B-spline (a student's swapped basis matrix);
///   tangents   unit tangents of that curve, by direction; their length is checked apart;
///   frames     recursive (the assignment's update from B = +z), rotation-minimizing (double
///              reflection), planar with N = +z x T (left of travel) or N = T x +z (right).
///
/// The program's output is CSV with a header naming its columns: `curve` (the record's index
/// in the file, or crossdiv's own label "#3 bsp2"), `index` (the sample), `x,y,z`, and when it
/// has them `tx,ty,tz`, `nx,ny,nz` (or `fnx,fny,fnz`, which win: crossdiv's frame columns) and
/// `bx,by,bz`. Other columns are ignored.

#include <string>
#include <vector>

#include "crossdiv/curves/curve_record.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {

/// How far a subject's curve lies from core under one convention.
struct CurveConventionFit {
    std::string name;  ///< "as written", "bezier basis", "b-spline basis"; "recursive", "rmf", "planar-left", ...
    double max = 0;    ///< positions: distance over the curve's diagonal; directions: degrees
    bool fits = false;
};

/// One record of the file, compared.
struct CurveSubjectCurve {
    std::string curve;          ///< the record's label ("#0 bez2")
    int core_samples = 0, subject_samples = 0;
    std::string problem;        ///< why nothing was compared ("no samples", "21 samples where core makes 31")
    std::vector<CurveConventionFit> positions;  ///< every position convention of the record
    std::string position_rule;  ///< the first that fits ("" none)
    double tangent_deg = -1;    ///< largest angle to the tangents of position_rule (-1: no tangents written)
    double tangent_length = 0;  ///< largest | |t| - 1 | of the written tangents
    std::vector<CurveConventionFit> frames;     ///< every frame convention (empty: no normals written)
    std::string frame_rule;     ///< the first that fits ("" none)
    double binormal_deg = -1;   ///< largest angle between the written B and T x N (-1: none written)
};

struct CurveSubjectComparison {
    std::string input, subject;
    RunOutcome outcome;  ///< the program's run (status Ok: it wrote a readable table)
    std::vector<CurveSubjectCurve> curves;
    /// Every curve compared, its positions named, its tangents along them and its frames named
    /// where it wrote them.
    bool passed() const;
    /// "positions as written on 4 of 4 curves; frames recursive on 4 of 4 curves", or the run's failure.
    std::string summary() const;
};

/// Runs `command` (a command template: {in} the curve file, {out} the CSV it writes) with the
/// time limit, reads its table and compares every record of `file` (read from `input`) with
/// core's uniform tessellation. A program that crashes, hangs, exits nonzero, writes nothing,
/// an unreadable table (file:line) or a non-finite number gets that outcome.
/// @throws InputError for a command template that cannot run.
CurveSubjectComparison compare_curve_subject(const std::string& input, const CurveFile& file, const std::string& subject,
                                             const TaskCommand& command, double timeout_seconds);

}  // namespace crossdiv::verification
