#pragma once
/// @file
/// A curve as a file defines it (an SWP record or a BZC file), and its tessellation with a
/// named mode. The readers are in crossdiv/io/curve_io.h.

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crossdiv/curves/kappa_curve.h"
#include "crossdiv/curves/kochanek_bartels.h"
#include "crossdiv/curves/primitives.h"
#include "crossdiv/curves/quaternion_bezier.h"

namespace crossdiv {

/// What a record's control points mean.
enum class CurveType {
    BezierChain,       ///< SWP bez2/bez3: piecewise cubic, 3n + 1 points
    BSpline,           ///< SWP bsp2/bsp3: uniform cubic, sliding window
    CatmullRom,        ///< SWP crm2/crm3 (our extension): open Catmull-Rom
    CatmullRomClosed,  ///< SWP crc2/crc3 (our extension): closed, wraps around
    Tcb,               ///< SWP tcb2/tcb3 (our extension): open Kochanek-Bartels, keys as Catmull-Rom's
    TcbClosed,         ///< SWP tcc2/tcc3 (our extension): closed Kochanek-Bartels
    BesselOverhauser,        ///< SWP ovh2/ovh3 (our extension): open, chord-length knots
    BesselOverhauserClosed,  ///< SWP ovc2/ovc3 (our extension): closed
    KappaClosed,       ///< SWP kpc2 (our extension): closed kappa-curve, one quadratic piece per point
    CameraPath,        ///< SWP cam3 (our extension): a bez3 chain of positions with a quaternion each
    Bezier,            ///< BZC: one Bezier curve of any degree
    Primitive,         ///< SWP circ, helx, trfl
};
std::string_view to_string(CurveType t);

/// The largest STEPS an SWP record may give (intervals per segment, slices of a surface of
/// revolution): far beyond any course model (they use 8 to 90), small enough that one
/// segment's samples stay far below kMaxCurveSamples.
inline constexpr long kMaxSteps = 1'000'000;

/// One curve record.
struct CurveRecord {
    std::string name;     ///< "" for SWP's anonymous '.'
    std::string keyword;  ///< bez2, bsp3, circ, ... ("bzc" for a BZC file)
    CurveType type = CurveType::BezierChain;
    int dim = 2;          ///< 2 (points in the xy-plane, z = 0) or 3
    int steps = 1;        ///< SWP STEPS: uniform intervals per segment (primitives: in all)
    std::vector<Vec3> control;
    /// Tension, continuity and bias per key (Tcb, TcbClosed): one per control point, or none
    /// for all 0.
    std::vector<TcbParameters> tcb;
    /// One unit quaternion per control point (CameraPath): a quaternion Bezier chain with the
    /// positions' segments.
    std::vector<Quat> orientations;
    /// KappaClosed: the converged iteration through `control`, solved once by the SWP reader
    /// (it is the expensive part of the record, and every check reads it); chain() solves it
    /// when a record was built without the reader.
    std::shared_ptr<const KappaCurve> kappa;
    Primitive primitive;  ///< when type == Primitive
    int line = 0;         ///< where the record starts

    /// "name" or "#index keyword" for anonymous records.
    std::string label(int index) const;
    /// The Bezier segments of a spline record. @throws InputError for a primitive.
    BezierChain chain() const;
    /// Whether the record is a closed interpolating spline (crc, tcc, ovc, kpc): one that
    /// wraps around its points and has as many segments as points.
    bool wraps() const;
    /// Whether the curve closes on itself: a wrapping spline or closed primitive, or a
    /// spline whose first and last point coincide (the course files close B-splines by
    /// repeating three control points).
    bool closed() const;
};

/// An srev or gcyl record (built into surfaces by the surfaces module).
struct SweepRecord {
    enum class Kind { Revolution, Cylinder };
    Kind kind = Kind::Revolution;
    std::string name;
    int steps = 0;            ///< srev: slices around the axis
    std::string profile;      ///< curve name
    std::string sweep;        ///< gcyl: curve name
    std::string scale;        ///< gcyl, optional (our extension: `gcyl NAME PROFILE SWEEP SCALE`)
    int profile_index = -1;   ///< into CurveFile::curves
    int sweep_index = -1;
    int scale_index = -1;     ///< -1 without a scale curve
    int line = 0;
};

/// Everything one curve file defines.
struct CurveFile {
    std::string path;
    std::vector<CurveRecord> curves;
    std::vector<SweepRecord> sweeps;
};

/// How to tessellate.
struct TessellationOptions {
    TessellationMode mode = TessellationMode::Uniform;
    std::optional<int> intervals;  ///< uniform: per segment; default the record's STEPS
    double angle_tol = 0;          ///< radians, for Angle
    double tol = 0;                ///< distance, for Distance
};

/// Tessellates one record. Splines use the chain's tessellation; primitives are sampled
/// uniformly in their parameter: with the record's steps (or `intervals`) in uniform mode,
/// and otherwise with the fewest steps, doubling from the record's, whose largest turn per
/// edge (Angle) or measured deviation (Distance) is within the tolerance.
Polyline tessellate_record(const CurveRecord& record, const TessellationOptions& options);

/// Exact evaluation of a record at its global parameter (the parameter Polyline::params
/// holds): position, first and second derivative. The chain is built once, here, and owned
/// by the returned function. @throws InputError as CurveRecord::chain().
std::function<ChainJet(double)> record_evaluator(const CurveRecord& record);

/// The end of a record's parameter range: its chain's segment count, or the primitive's
/// param_end().
double record_param_end(const CurveRecord& record);

/// Measured chordal deviation of a primitive's samples from the exact curve (dense sampling
/// with golden-section refinement per edge, as chordal_deviation for splines).
Deviation primitive_deviation(const Primitive& p, const Polyline& samples);

}  // namespace crossdiv
