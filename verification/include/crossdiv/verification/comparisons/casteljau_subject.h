#pragma once
/// @file
/// A program's de Casteljau put in core's place (the course's task): it is given a file with
/// one Bezier curve of any degree ({in}: BZC, or SWP with one segment; the parameter t is a
/// literal of its command) and writes every level of the construction at t ({out}): one line
/// per level, from the control points (level 0) to the point on the curve, each line the
/// level's points as numbers, two or three per point as the input has them. Each level is
/// compared point by point with core's at t and at 1 - t (the weights swapped, a classic
/// slip), and the parameter that fits is named.

#include <string>
#include <vector>

#include "crossdiv/curves/curve_record.h"
#include "crossdiv/verification/harness/isolate.h"
#include "crossdiv/verification/implementations/task_program.h"

namespace crossdiv::verification {

struct CasteljauSubjectComparison {
    std::string input, subject;
    RunOutcome outcome;
    double t = 0.5;
    int levels = 0;                   ///< core's: degree + 1
    double max_at_t = INFINITY;       ///< largest distance over the control polygon's diagonal, at t
    double max_at_one_minus_t = INFINITY;
    int worst_level = -1;             ///< where it is farthest from core at t
    std::string parameter;            ///< "t", "1 - t" (the weights swapped), or "" when neither fits
    bool passed() const { return outcome.status == RunStatus::Ok && parameter == "t"; }
    std::string summary() const;
};

/// Runs the program with the time limit and compares its levels with core's for the single
/// Bezier curve of `file`. Crashes, hangs, a nonzero exit, no file, an unreadable line
/// (file:line), a non-finite number, and another count of levels or of points in a level
/// (WrongCount, naming the level) are named outcomes.
/// @throws InputError when the file is not one Bezier curve.
CasteljauSubjectComparison compare_casteljau_subject(const std::string& input, const CurveFile& file, double t,
                                                     const std::string& subject, const TaskCommand& command,
                                                     double timeout_seconds);

}  // namespace crossdiv::verification
