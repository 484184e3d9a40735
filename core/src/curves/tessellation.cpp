#include "crossdiv/curves/tessellation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv {

std::string_view to_string(TessellationMode m) {
    switch (m) {
        case TessellationMode::Uniform: return "uniform";
        case TessellationMode::Angle: return "angle";
        case TessellationMode::Distance: return "distance";
    }
    return "?";
}

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    // Below 1e-150 the squares underflow (a curve at the scale of 1e-300 would measure 0):
    // such a configuration is measured at unit scale, by a power of two, exactly.
    const double extent = std::max(ab.cwiseAbs().maxCoeff(), (p - a).cwiseAbs().maxCoeff());
    if (extent > 0.0 && extent < 1e-150) {
        int exponent = 0;
        (void)std::frexp(extent, &exponent);
        const double up = std::ldexp(1.0, -exponent);
        return std::ldexp(point_segment_distance(up * p, up * a, up * b), exponent);
    }
    const double len2 = ab.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + s * ab)).norm();
}

std::vector<Vec3> curve_normals(std::span<const Vec3> positions, std::span<const Vec3> tangents) {
    const bool planar = std::all_of(positions.begin(), positions.end(), [](const Vec3& p) { return p.z() == 0.0; });
    const std::vector<Frame> frames =
        curve_frames(positions, tangents, planar ? FrameMethod::Planar : FrameMethod::DoubleReflection);
    std::vector<Vec3> normals(frames.size());
    for (size_t i = 0; i < frames.size(); ++i) normals[i] = frames[i].N;
    return normals;
}

namespace {

double max_magnitude(std::span<const Vec3> points) {
    double m = 0;
    for (const Vec3& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
    return m;
}

void require_segments(const BezierChain& chain) {
    if (chain.num_segments() == 0) throw InputError("the curve has no segments to tessellate");
}

/// Below this magnitude of the control points the curve's sums cannot overflow (squares and
/// cubic weights stay far under DBL_MAX): a non-finite tangent there is a curve standing still.
constexpr double kDegenerateCurveMagnitude = 1e100;

void emit(Polyline& out, const BezierPointTangent& pt, double u) {
    out.positions.push_back(pt.position);
    out.tangents.push_back(pt.tangent);
    out.params.push_back(u);
}

/// Closes a polyline: the end of the last segment, then the normals. A finite control
/// polygon can still overflow in the Bernstein sums and the derivative's differences (points
/// near DBL_MAX): refused, naming the sample, rather than written as NaN or inf.
void finish(const BezierChain& chain, Polyline& out) {
    const int last = chain.num_segments() - 1;
    emit(out, bezier_point_tangent(chain.segment(last), 1.0), static_cast<double>(last + 1));
    out.normals = curve_normals(out.positions, out.tangents);
    const double magnitude = chain.points.empty() ? 0.0 : max_magnitude(chain.points);
    for (int i = 0; i < out.size(); ++i) {
        if (out.positions[i].allFinite() && out.tangents[i].allFinite() && out.normals[i].allFinite()) continue;
        const std::string where = "sample " + std::to_string(i) + " at u = " + std::to_string(out.params[i]) + " (segment " +
                                  std::to_string(std::min(static_cast<int>(out.params[i]), last)) + "): ";
        // A finite position of a curve of ordinary size whose tangent is not: the curve
        // stands still there (coincident control points), and has no direction to frame.
        if (out.positions[i].allFinite() && magnitude < kDegenerateCurveMagnitude)
            throw InputError(where + "the curve stands still there (its control points coincide), so it has no tangent and no frame");
        throw InputError(where + "its position, tangent or normal is not finite; the control points (up to " +
                         std::to_string(magnitude) + " in magnitude) overflow double in the curve's sums, so scale the curve down");
    }
}

/// Unit tangent at the start of a piece: the first control point that differs from c_0
/// gives the direction of the first non-vanishing derivative there.
Vec3 start_tangent(std::span<const Vec3> c) {
    for (size_t j = 1; j < c.size(); ++j) {
        const Vec3 v = c[j] - c[0];
        if ((v.array() != 0.0).any()) return v.stableNormalized();
    }
    return Vec3::Zero();
}

/// Recursive halving at t = 1/2 with one preallocated buffer: depth k keeps its two halves
/// and a scratch row in buf[3 n k .. 3 n (k+1)), so the recursion never allocates.
class Halver {
public:
    Halver(int points_per_piece, int max_depth)
        : n_(points_per_piece), buf_(static_cast<size_t>(3 * points_per_piece) * (max_depth + 1)) {}

    /// Splits `c` (n points) into the depth's left and right halves.
    void split(std::span<const Vec3> c, int depth) {
        std::span<Vec3> l = left(depth), r = right(depth), w = row(depth, 2);
        std::copy(c.begin(), c.end(), w.begin());
        for (int k = 0; k < n_; ++k) {
            l[k] = w[0];
            r[n_ - 1 - k] = w[n_ - 1 - k];
            for (int i = 0; i + 1 < n_ - k; ++i) w[i] = 0.5 * (w[i] + w[i + 1]);
        }
    }
    std::span<Vec3> left(int depth) { return row(depth, 0); }
    std::span<Vec3> right(int depth) { return row(depth, 1); }

private:
    std::span<Vec3> row(int depth, int which) {
        return std::span<Vec3>(buf_).subspan(static_cast<size_t>(3 * depth + which) * n_, n_);
    }
    int n_;
    std::vector<Vec3> buf_;
};

/// The angle mode's recursion (the CS4620 seed's): emits the start of every accepted piece of
/// `c` on [t0, t1] of segment k, in order; a piece at max_depth is accepted as it is.
template <class Accept>
void refine(Halver& h, std::span<const Vec3> c, int k, double t0, double t1, int depth, int max_depth,
            const Accept& accept, Polyline& out) {
    if (depth >= max_depth || accept(c)) {
        emit(out, {c[0], start_tangent(c)}, k + t0);
        return;
    }
    h.split(c, depth);
    const double mid = 0.5 * (t0 + t1);
    refine(h, h.left(depth), k, t0, mid, depth + 1, max_depth, accept, out);
    refine(h, h.right(depth), k, mid, t1, depth + 1, max_depth, accept, out);
}

template <class Accept>
Polyline adaptive(const BezierChain& chain, int max_depth, const Accept& accept) {
    require_segments(chain);
    Polyline out;
    Halver h(chain.degree + 1, max_depth);
    for (int k = 0; k < chain.num_segments(); ++k) refine(h, chain.segment(k), k, 0.0, 1.0, 0, max_depth, accept, out);
    finish(chain, out);
    return out;
}

/// Turning angle between consecutive control-polygon edges, skipping edges of zero length
/// (a repeated control point has no direction; the turn is measured across it).
double max_turning_angle(std::span<const Vec3> c) {
    double worst = 0;
    Vec3 prev = Vec3::Zero();
    for (size_t i = 1; i < c.size(); ++i) {
        const Vec3 e = c[i] - c[i - 1];
        if (e.squaredNorm() == 0.0) continue;
        if (prev.squaredNorm() > 0.0) worst = std::max(worst, std::atan2(prev.cross(e).norm(), prev.dot(e)));
        prev = e;
    }
    return worst;
}

/// Scratch for the distance mode, reused across calls so that splitting and bounding never
/// allocate once grown to the curve's size: de Casteljau rows, and the Bezier coefficients
/// polynomial_max_bound splits.
struct SplitScratch {
    std::vector<Vec3> rest, work, discard, span_points;
    std::vector<double> perpendicular[2], pieces;
    std::vector<int> depths;
};

/// An upper bound of max |f| on [0, 1] for the polynomial f with Bezier coefficients b,
/// tight to 1e-9 relative: branch and bound, halving (de Casteljau) every piece whose hull
/// bound max |b_i| could still exceed the largest value found at a piece's ends. The pieces
/// waiting are a stack of coefficient rows in `pieces` (b.size() each) with their depths.
double polynomial_max_bound(std::span<const double> b, std::vector<double>& pieces, std::vector<int>& depths) {
    const size_t n = b.size();
    pieces.assign(b.begin(), b.end());
    depths.assign(1, 0);
    double found = std::max(std::abs(b.front()), std::abs(b.back()));
    double bound = found;  // the largest hull bound of a piece no longer split
    while (!depths.empty()) {
        const int depth = depths.back();
        depths.pop_back();
        const size_t at = pieces.size() - n;
        double hull = 0;
        for (size_t i = 0; i < n; ++i) hull = std::max(hull, std::abs(pieces[at + i]));
        if (hull <= found * (1 + 1e-9) || depth >= 40) {
            if (depth >= 40) bound = std::max(bound, hull);
            pieces.resize(at);
            continue;
        }
        // Halve in place: the left half replaces the piece, the right half goes on top.
        pieces.resize(at + 2 * n);
        double* left = pieces.data() + at;
        double* right = left + n;
        // After step lvl, left[i] for i > lvl holds de Casteljau level lvl + 1 and left[lvl]
        // is final; the last entry of each level is the right half's coefficient.
        for (size_t lvl = 0; lvl < n; ++lvl) {
            right[n - 1 - lvl] = left[n - 1];
            for (size_t i = n - 1; i > lvl; --i) left[i] = 0.5 * (left[i - 1] + left[i]);
        }
        found = std::max(found, std::abs(right[0]));  // the value at the midpoint
        depths.push_back(depth + 1);
        depths.push_back(depth + 1);
    }
    return std::max(found * (1 + 1e-9), bound);
}

/// An upper bound of a piece's largest distance from the line through `a` along the unit
/// vector `u`: the perpendicular part's two components (along e1, the direction of the
/// farthest control point's perpendicular offset, and e2 = u x e1) are polynomials bounded
/// tightly by polynomial_max_bound; the bound is the root of the sum of their squares, plus
/// `slack` for the rounding of the coordinates.
double line_distance_bound(std::span<const Vec3> c, const Vec3& a, const Vec3& u, double slack, SplitScratch& s) {
    Vec3 farthest = Vec3::Zero();
    for (const Vec3& p : c) {
        const Vec3 perpendicular = (p - a) - (p - a).dot(u) * u;
        if (perpendicular.norm() > farthest.norm()) farthest = perpendicular;
    }
    if (farthest.norm() == 0) return slack;
    const Vec3 e[2] = {farthest.normalized(), u.cross(farthest.normalized())};
    double sum_of_squares = 0;
    for (int k = 0; k < 2; ++k) {
        std::vector<double>& f = s.perpendicular[k];
        f.resize(c.size());
        for (size_t i = 0; i < c.size(); ++i) f[i] = (c[i] - a).dot(e[k]);
        const double m = polynomial_max_bound(f, s.pieces, s.depths);
        sum_of_squares += m * m;
    }
    // The perpendicular part is computed from rounded coordinates: the slack covers it.
    return std::sqrt(sum_of_squares) + slack;
}

/// Bound (d) of flatness(): for a piece that runs monotonically along its chord (its
/// along-chord Bezier coefficients nondecreasing within the chord's length, so that no point
/// projects beyond the chord's ends) the distance to the chord is that to its line, the norm
/// of the perpendicular part, whose two components (along e1, the direction of the farthest
/// control point's perpendicular offset, and e2 = u x e1) are polynomials bounded tightly by
/// polynomial_max_bound; the bound is the root of the sum of their squares. Infinite when the
/// piece is not monotone.
double monotone_chord_distance(std::span<const Vec3> c, SplitScratch& s) {
    const size_t d = c.size() - 1;
    const Vec3 chord = c.back() - c.front();
    const double length = chord.norm();
    if (d < 2 || !(length > 0)) return INFINITY;
    const Vec3 u = chord / length;
    // Monotone up to the rounding of the projections (slack), which moves a point's
    // distance to the chord by no more than the slack added to the bound below.
    const double slack = 1e-12 * length;
    double previous = -slack;
    for (const Vec3& p : c) {
        const double along = (p - c.front()).dot(u);
        if (along < previous - slack) return INFINITY;
        previous = std::max(previous, along);
    }
    if (previous > length + slack) return INFINITY;
    return line_distance_bound(c, c.front(), u, slack, s);
}

/// An upper bound of the Hausdorff distance between a piece and its chord: the smallest of
/// four valid bounds. (a) The control points' largest distance from the chord segment (the
/// piece lies in their convex hull). (b) (1 - 2^(1-d)) max_i |p_i - l_i|, l_i = p_0 +
/// (i/d)(p_d - p_0): the piece minus the linearly parametrized chord is sum_i B_i(t) (p_i - l_i),
/// and the interior Bernstein weights sum to at most 1 - 2^(1-d). (c) Wang's d (d - 1) / 8
/// max_i |p_{i+2} - 2 p_{i+1} + p_i|, the one-step case of wang_intervals. (b) and (c) bound
/// the distance to the parametrized chord, which bounds the Hausdorff distance by the
/// projection argument in the header. (d) monotone_chord_distance, exact to 1e-9 where it
/// applies.
double flatness(std::span<const Vec3> c, SplitScratch& scratch) {
    const size_t d = c.size() - 1;
    double hull = 0, parametric = 0, second = 0;
    for (size_t i = 1; i < d; ++i) {
        hull = std::max(hull, point_segment_distance(c[i], c.front(), c.back()));
        const Vec3 l = c.front() + (static_cast<double>(i) / d) * (c.back() - c.front());
        parametric = std::max(parametric, (c[i] - l).norm());
        second = std::max(second, (c[i + 1] - 2.0 * c[i] + c[i - 1]).norm());
    }
    return std::min({hull, (1.0 - std::ldexp(1.0, 1 - static_cast<int>(d))) * parametric, d * (d - 1) / 8.0 * second,
                     monotone_chord_distance(c, scratch)});
}


/// Peels the piece [0, t] of s.rest (de Casteljau) onto `dest`; s.rest becomes [t, 1].
void peel(double t, std::vector<Vec3>& dest, SplitScratch& s) {
    const size_t n = s.rest.size();
    s.work.assign(s.rest.begin(), s.rest.end());
    for (size_t lvl = 0; lvl < n; ++lvl) {
        dest.push_back(s.work[0]);
        s.rest[n - 1 - lvl] = s.work[n - 1 - lvl];
        for (size_t i = 0; i + 1 < n - lvl; ++i) s.work[i] = (1.0 - t) * s.work[i] + t * s.work[i + 1];
    }
}

/// Splits `c` into k equal parameter pieces appended to `dest` (k (d + 1) points): peel
/// [0, 1/k] off the rest, then 1/(k-1) of what remains, and so on.
void split_equal(std::span<const Vec3> c, int k, std::vector<Vec3>& dest, SplitScratch& s) {
    s.rest.assign(c.begin(), c.end());
    for (int piece = 0; piece < k - 1; ++piece) peel(1.0 / (k - piece), dest, s);
    dest.insert(dest.end(), s.rest.begin(), s.rest.end());
}

/// Samples per segment of the flattening integral.
constexpr int kFlatteningSamples = 128;

/// Samples of the flattening integral of one segment: cumulative[j] is the integral of
/// sqrt(kappa) ds over [0, j / kFlatteningSamples] (trapezoids). sqrt(kappa) |c'| is
/// sqrt(|c' x c''| / |c'|), taken as 0 where c' vanishes (a cusp, where it tends to 0 too).
void flattening_integral(std::span<const Vec3> c, std::vector<double>& cumulative) {
    const std::vector<Vec3> d1 = bezier_derivative(c);
    const std::vector<Vec3> d2 = d1.size() > 1 ? bezier_derivative(d1) : std::vector<Vec3>{Vec3::Zero()};
    const auto density = [&](double t) {
        const Vec3 a = bezier_point(d1, t), b = bezier_point(d2, t);
        const double speed = a.norm();
        return speed > 0 ? std::sqrt(a.cross(b).norm() / speed) : 0.0;
    };
    cumulative.assign(kFlatteningSamples + 1, 0.0);
    double previous = density(0.0);
    for (int j = 1; j <= kFlatteningSamples; ++j) {
        const double next = density(static_cast<double>(j) / kFlatteningSamples);
        cumulative[j] = cumulative[j - 1] + 0.5 * (previous + next) / kFlatteningSamples;
        previous = next;
    }
}

/// The distance mode on one piece: accept it when flat enough, else split it into
/// k = ceil(sqrt(flatness / tol)) equal pieces (flatness falls as 1/k^2 under splitting, so
/// one split usually suffices; halving would overshoot to the next power of two) and treat
/// each the same way. `rows[depth]` holds the pieces of a depth, reused across calls;
/// `known_flatness` is the piece's flatness when the caller has it (negative: computed here).
void refine_distance(std::span<const Vec3> c, int segment, double t0, double t1, double tol, int depth,
                     std::vector<std::vector<Vec3>>& rows, SplitScratch& scratch, Polyline& out,
                     double known_flatness = -1) {
    const double f = known_flatness >= 0 ? known_flatness : flatness(c, scratch);
    if (f <= tol) {
        emit(out, {c[0], start_tangent(c)}, segment + t0);
        return;
    }
    // 40 levels of at least halving take any piece at or above the tolerance floor below it
    // with a wide margin; reaching the cap is a bug, not an input problem.
    if (depth >= 40) throw std::logic_error("distance tessellation reached its depth cap without meeting the tolerance");
    constexpr int kMaxPieces = 64;  // bounds one level's buffer; deeper levels continue
    const int k = static_cast<int>(std::clamp(std::ceil(std::sqrt(f / tol)), 2.0, static_cast<double>(kMaxPieces)));
    if (rows.size() <= static_cast<size_t>(depth)) rows.resize(depth + 1);
    std::vector<Vec3>& row = rows[depth];
    row.clear();
    split_equal(c, k, row, scratch);
    const size_t n = c.size();
    for (int i = 0; i < k; ++i) {
        // Each child reads its own points; deeper levels write only to rows[depth + 1 ...].
        const std::span<const Vec3> child(rows[depth].data() + i * n, n);
        refine_distance(child, segment, t0 + (t1 - t0) * i / k, i + 1 == k ? t1 : t0 + (t1 - t0) * (i + 1) / k, tol,
                        depth + 1, rows, scratch, out);
    }
}

/// The piece [t0, t1] (0 <= t0 < t1 <= 1) of segment `c`, its control points in `dest`.
void extract(std::span<const Vec3> c, double t0, double t1, std::vector<Vec3>& dest, SplitScratch& s) {
    s.rest.assign(c.begin(), c.end());
    if (t0 > 0.0) {
        s.discard.clear();
        peel(t0, s.discard, s);  // the rest is [t0, 1]
    }
    dest.clear();
    if (t1 < 1.0) peel((t1 - t0) / (1.0 - t0), dest, s);
    else dest.assign(s.rest.begin(), s.rest.end());
}

/// An upper bound of the distance from piece `c` to the segment [a, b], a chord that other
/// pieces share (an edge across a joint of the chain): the smaller of the control points'
/// largest distance from it (the convex hull) and, when every control point projects between
/// a and b (so the distance to the segment is that to its line), the perpendicular
/// components' bounds by branch and bound (as monotone_chord_distance, against this chord).
double chord_distance_bound(std::span<const Vec3> c, const Vec3& a, const Vec3& b, SplitScratch& s) {
    double hull = 0;
    for (const Vec3& p : c) hull = std::max(hull, point_segment_distance(p, a, b));
    const double length = (b - a).norm();
    if (!(length > 0)) return hull;
    const Vec3 u = (b - a) / length;
    const double slack = 1e-12 * length;
    for (const Vec3& p : c) {
        const double along = (p - a).dot(u);
        if (along < -slack || along > length + slack) return hull;
    }
    return std::min(hull, line_distance_bound(c, a, u, slack, s));
}

/// The largest |x| of control points: a bound of the arc's distance from the y axis.
double largest_abs_x(std::span<const Vec3> c) {
    double r = 0;
    for (const Vec3& p : c) r = std::max(r, std::abs(p.x()));
    return r;
}

/// What the distance mode reads of an arc: its bound from its chord, and how far from the y
/// axis it reaches (a DistanceBudget's tolerance shrinks with that).
struct SpanCheck {
    double bound = 0;   ///< span_bound
    double radius = 0;  ///< largest |x| of the pieces' control points (0 unless asked)
};

/// The chain on [u0, u1] (global parameters) against its chord: within one segment the
/// piece's flatness; across joints the largest chord_distance_bound of its pieces against the
/// chord from the first piece's start to the last one's end. Valid upper bounds of the
/// Hausdorff distance between the arc and the chord either way (the arc runs continuously from
/// one end of the chord to the other). With `radius`, also the arc's reach from the y axis.
SpanCheck span_bound(const BezierChain& chain, double u0, double u1, bool radius, SplitScratch& s) {
    const int segments = chain.num_segments();
    const int first = std::clamp(static_cast<int>(std::floor(u0)), 0, segments - 1);
    const int last = std::clamp(static_cast<int>(std::ceil(u1)) - 1, first, segments - 1);
    SpanCheck out;
    if (first == last) {
        extract(chain.segment(first), u0 - first, u1 - first, s.span_points, s);
        if (radius) out.radius = largest_abs_x(s.span_points);
        out.bound = flatness(s.span_points, s);
        return out;
    }
    // The chord's ends: the first piece's start and the last piece's end.
    extract(chain.segment(first), u0 - first, 1.0, s.span_points, s);
    const Vec3 a = s.span_points.front();
    extract(chain.segment(last), 0.0, u1 - last, s.span_points, s);
    const Vec3 b = s.span_points.back();
    out.bound = chord_distance_bound(s.span_points, a, b, s);
    if (radius) out.radius = largest_abs_x(s.span_points);
    for (int k = first; k < last; ++k) {
        extract(chain.segment(k), k == first ? u0 - k : 0.0, 1.0, s.span_points, s);
        out.bound = std::max(out.bound, chord_distance_bound(s.span_points, a, b, s));
        if (radius) out.radius = std::max(out.radius, largest_abs_x(s.span_points));
    }
    return out;
}

/// The chain's flattening integral at every sample (kFlatteningSamples per segment) from its
/// start, and the parameter where it reaches a value: where an edge holding sqrt(8 tol) of the
/// integral ends, about as far as an edge within tol reaches.
struct FlatteningProfile {
    std::vector<double> cumulative;  ///< at u = j / kFlatteningSamples
    explicit FlatteningProfile(const BezierChain& chain) {
        std::vector<double> segment;
        cumulative.push_back(0.0);
        for (int k = 0; k < chain.num_segments(); ++k) {
            flattening_integral(chain.segment(k), segment);
            const double base = cumulative.back();
            for (int j = 1; j <= kFlatteningSamples; ++j) cumulative.push_back(base + segment[j]);
        }
    }
    double at(double u) const {
        const double x = u * kFlatteningSamples;
        const size_t j = std::min(static_cast<size_t>(x), cumulative.size() - 2);
        return cumulative[j] + (x - j) * (cumulative[j + 1] - cumulative[j]);
    }
    double reaching(double value) const {
        const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), value);
        if (it == cumulative.end()) return static_cast<double>(cumulative.size() - 1) / kFlatteningSamples;
        const size_t j = static_cast<size_t>(it - cumulative.begin());
        if (j == 0) return 0.0;
        const double span = cumulative[j] - cumulative[j - 1];
        const double within = span > 0 ? (value - cumulative[j - 1]) / span : 1.0;
        return (j - 1 + std::clamp(within, 0.0, 1.0)) / kFlatteningSamples;
    }
};

}  // namespace

Polyline tessellate_uniform(const BezierChain& chain, int intervals) {
    require_segments(chain);
    if (intervals < 1) throw InputError("uniform tessellation needs at least 1 interval per segment, got " + std::to_string(intervals));
    return tessellate_uniform(chain, std::vector<int>(chain.num_segments(), intervals));
}

Polyline tessellate_uniform(const BezierChain& chain, std::span<const int> intervals) {
    require_segments(chain);
    if (intervals.size() != static_cast<size_t>(chain.num_segments()))
        throw InputError("uniform tessellation: " + std::to_string(intervals.size()) + " interval counts for " +
                         std::to_string(chain.num_segments()) + " segments");
    Polyline out;
    long long total = 1;
    for (int n : intervals) total += std::max(n, 0);
    if (total > kMaxCurveSamples)
        throw InputError("uniform tessellation would make " + std::to_string(total) + " samples (" +
                         std::to_string(intervals.size()) + " segments), more than the limit of " +
                         std::to_string(kMaxCurveSamples) + "; use fewer steps");
    out.positions.reserve(static_cast<size_t>(total));
    out.tangents.reserve(static_cast<size_t>(total));
    out.params.reserve(static_cast<size_t>(total));
    for (int k = 0; k < chain.num_segments(); ++k) {
        const int n = intervals[k];
        if (n < 1) throw InputError("segment " + std::to_string(k) + ": at least 1 interval needed, got " + std::to_string(n));
        for (int i = 0; i < n; ++i) {
            const double t = static_cast<double>(i) / n;
            emit(out, bezier_point_tangent(chain.segment(k), t), k + t);
        }
    }
    finish(chain, out);
    return out;
}

Polyline tessellate_angle(const BezierChain& chain, double angle_tol, int max_levels) {
    if (!(angle_tol > 0.0 && angle_tol <= M_PI))
        throw InputError("the angle tolerance must be in (0, 180] degrees, got " + std::to_string(angle_tol * 180.0 / M_PI));
    if (max_levels < 0 || max_levels > 30) throw InputError("angle tessellation: max levels must be 0..30");
    const double half = 0.5 * angle_tol;
    return adaptive(chain, max_levels, [half](std::span<const Vec3> c) { return max_turning_angle(c) <= half; });
}

Polyline tessellate_distance(const BezierChain& chain, double tol) { return tessellate_distance(chain, DistanceBudget{tol, 0.0}); }

Polyline tessellate_distance(const BezierChain& chain, const DistanceBudget& budget) {
    require_segments(chain);
    const double tol = budget.tol;
    if (!(budget.radial >= 0 && std::isfinite(budget.radial)))
        throw InputError("the distance budget's radial share must be finite and not negative, got " + std::to_string(budget.radial));
    const double scale = bounding_box_diagonal(chain.points);
    if (!std::isfinite(tol) || tol <= 0.0 || tol < kMinDistanceTolRelative * scale)
        throw InputError("the distance tolerance must be finite and at least " + std::to_string(kMinDistanceTolRelative) +
                         " x the curve's size (" + std::to_string(scale) + "), got " + std::to_string(tol));
    Polyline out;
    SplitScratch scratch;
    const FlatteningProfile profile(chain);
    const double end = chain.num_segments(), step = std::sqrt(8.0 * tol);
    const auto emit_at = [&](double u) {
        const int k = std::min(static_cast<int>(u), chain.num_segments() - 1);
        emit(out, bezier_point_tangent(chain.segment(k), u - k), u);
    };
    // Certified with a margin of 1e-9 of tol: the farthest end sits at the bound, and the
    // vertex evaluated there and any measurement of the distance round differently from the
    // piece the bound was computed on (by ulps).
    const double certified = tol * (1.0 - 1e-9);
    const bool radial = budget.radial > 0;
    const auto fits = [&](double u0, double u1) {
        const SpanCheck c = span_bound(chain, u0, u1, radial, scratch);
        return c.bound <= certified - budget.radial * c.radius;
    };
    std::vector<std::vector<Vec3>> rows;
    for (double u = 0.0; u < end;) {
        // The farthest end within tol, bracketed from where the flattening integral says an
        // edge within tol ends (each test reads the segments the edge spans, so a long chain
        // costs about its length).
        const double reach = farthest_reach(u, end, profile.reaching(profile.at(u) + step), fits);
        if (reach > u) {
            emit_at(u);
            u = reach;
            continue;
        }
        // No end was found fitting (the bound's slack at a tolerance near the floor): certify
        // the rest of this segment by splitting, which always ends.
        const int k = std::min(static_cast<int>(u), chain.num_segments() - 1);
        extract(chain.segment(k), u - k, 1.0, scratch.span_points, scratch);
        const std::vector<Vec3> piece = scratch.span_points;
        const double allowed = tol - budget.radial * largest_abs_x(piece);
        if (!(allowed > 0))
            throw InputError("the distance budget leaves no tolerance on segment " + std::to_string(k) + " (tol " +
                             std::to_string(tol) + " less " + std::to_string(budget.radial) + " times its distance from the axis)");
        refine_distance(piece, k, u - k, 1.0, allowed, 0, rows, scratch, out);
        u = k + 1;
    }
    finish(chain, out);
    return out;
}

double flattening_estimate(const BezierChain& chain, double tol) {
    require_segments(chain);
    if (!std::isfinite(tol) || tol <= 0.0) throw InputError("the flattening estimate needs a positive tolerance, got " + std::to_string(tol));
    std::vector<double> cumulative;
    double total = 0;
    for (int k = 0; k < chain.num_segments(); ++k) {
        flattening_integral(chain.segment(k), cumulative);
        total += cumulative.back();
    }
    return total / std::sqrt(8.0 * tol);
}

std::vector<int> wang_intervals(const BezierChain& chain, double tol) {
    require_segments(chain);
    if (!std::isfinite(tol) || tol <= 0.0) throw InputError("Wang's bound needs a positive tolerance, got " + std::to_string(tol));
    const int d = chain.degree;
    std::vector<int> n(chain.num_segments(), 1);
    for (int k = 0; k < chain.num_segments(); ++k) {
        const std::span<const Vec3> c = chain.segment(k);
        double m = 0;
        for (int i = 0; i + 2 <= d; ++i) m = std::max(m, (c[i + 2] - 2.0 * c[i + 1] + c[i]).norm());
        const double bound = std::ceil(std::sqrt(d * (d - 1) * m / (8.0 * tol)));
        n[k] = std::max(1, static_cast<int>(std::min(bound, 1e9)));
    }
    return n;
}

Deviation sampled_maximum(const std::function<double(double)>& f, double a, double b) {
    const double step = (b - a) / (kDeviationSamples + 1);
    Deviation best{-1.0, a};
    int best_j = 1;
    for (int j = 1; j <= kDeviationSamples; ++j) {
        const double x = a + step * j, v = f(x);
        if (v > best.max) best = {v, x}, best_j = j;
    }
    double lo = a + step * (best_j - 1), hi = a + step * (best_j + 1);
    constexpr double kInvPhi = 0.6180339887498949;
    double x1 = hi - kInvPhi * (hi - lo), x2 = lo + kInvPhi * (hi - lo);
    double f1 = f(x1), f2 = f(x2);
    for (int it = 0; it < 40; ++it) {
        if (f1 > f2) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - kInvPhi * (hi - lo), f1 = f(x1);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + kInvPhi * (hi - lo), f2 = f(x2);
        }
    }
    if (f1 > best.max) best = {f1, x1};
    if (f2 > best.max) best = {f2, x2};
    return best;
}

Deviation chordal_deviation(const BezierChain& chain, const Polyline& poly) {
    Deviation dev;
    const int segments = chain.num_segments();
    // The chain at global parameter u; an edge may span joints (the distance mode's do).
    const auto point = [&](double u) {
        const int k = std::clamp(static_cast<int>(std::floor(u)), 0, segments - 1);
        return bezier_point(chain.segment(k), u - k);
    };
    for (int i = 0; i + 1 < poly.size(); ++i) {
        const Vec3 &a = poly.positions[i], &b = poly.positions[i + 1];
        const int first = std::clamp(static_cast<int>(std::floor(poly.params[i])), 0, segments - 1);
        const int last = std::clamp(static_cast<int>(std::ceil(poly.params[i + 1])) - 1, first, segments - 1);
        // Each segment the edge spans sampled on its own: the curve is smooth within one.
        for (int k = first; k <= last; ++k) {
            const double u0 = std::max(poly.params[i], static_cast<double>(k)),
                         u1 = std::min(poly.params[i + 1], static_cast<double>(k + 1));
            if (!(u1 > u0)) continue;
            const Deviation d = sampled_maximum([&](double u) { return point_segment_distance(point(u), a, b); }, u0, u1);
            if (d.max > dev.max) dev = d;
        }
    }
    return dev;
}

}  // namespace crossdiv
