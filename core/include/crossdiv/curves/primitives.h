#pragma once
/// @file
/// Curves that are not splines, evaluated exactly (closed-form position and derivatives):
/// the circle of the CS-C3100 seed's evalCircle, a circular helix, and the trefoil knot.
/// They are the analytic truth of the frame and sweep checks.

#include <string_view>

#include "crossdiv/curves/tessellation.h"

namespace crossdiv {

enum class PrimitiveKind {
    Circle,   ///< radius r in the xy-plane, counterclockwise from (r, 0, 0)
    Helix,    ///< (r cos s, r sin s, pitch s / 2 pi), s in [0, 2 pi turns]
    Trefoil,  ///< scale (sin s + 2 sin 2s, cos s - 2 cos 2s, -sin 3s), s in [0, 2 pi]
};
std::string_view to_string(PrimitiveKind k);

/// A primitive with its parameters; s runs over [0, param_end()].
struct Primitive {
    PrimitiveKind kind = PrimitiveKind::Circle;
    double radius = 1;  ///< circle, helix
    double pitch = 1;   ///< helix: rise per turn
    double turns = 1;   ///< helix
    double scale = 1;   ///< trefoil

    double param_end() const;
    bool closed() const { return kind != PrimitiveKind::Helix; }
    /// Exact position, first and second derivative with respect to s.
    ChainJet jet(double s) const;
};

/// steps + 1 samples at s = param_end() i / steps (the seed's evalCircle: the last point
/// repeats the first on closed curves), exact unit tangents, normals by curve_normals
/// (the circle's are the seed's: N = (-cos s, -sin s, 0)). @throws InputError if steps < 1.
Polyline sample_primitive(const Primitive& p, int steps);

}  // namespace crossdiv
