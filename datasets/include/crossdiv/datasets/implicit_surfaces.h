#pragma once
/// @file implicit_surfaces.h
/// Surfaces f(p) = 0 (f < 0 inside) with what is known exactly about them, sampled on grids of
/// chosen resolution: the inputs of marching cubes' convergence and topology tables, and a
/// field whose cubes are ambiguous by construction.

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "crossdiv/volume/scalar_grid.h"

namespace crossdiv::datasets {

struct ImplicitSurface {
    std::string name;
    std::string description;
    std::function<double(const Vec3&)> f;
    std::function<Vec3(const Vec3&)> gradient;
    Vec3 lo, hi;                              ///< a box holding the surface with a margin (or cutting it: the gyroid)
    bool signed_distance = false;             ///< f is the signed distance itself
    std::optional<int> euler_characteristic;  ///< of the closed surface
    std::optional<double> volume;             ///< enclosed, exact
};

/// sphere (radius 1, centred off the grid's symmetry), torus (R 1, r 0.4), genus2 (a tube round
/// Bernoulli's lemniscate: L(x, y)^2 + z^2 = 0.04, L = (x^2 + y^2)^2 - x^2 + y^2), gyroid
/// (sin x cos y + sin y cos z + sin z cos x over one period, cut by the box).
const std::vector<ImplicitSurface>& implicit_surfaces();
/// @throws InputError naming the known surfaces for another name.
const ImplicitSurface& implicit_surface(std::string_view name);

/// The surface sampled on cubic cells, `resolution` samples along the box's longest side.
/// @throws InputError for resolution < 3 or a grid over kMaxGridSamples.
ScalarGrid sample(const ImplicitSurface& surface, int resolution);

/// The distance from p to the surface: |f(p)| for a signed distance, else |p - q| for the
/// point q of the surface that Newton's iteration along the gradient reaches from p (an upper
/// bound on the distance, equal to it up to O(distance^2 x curvature)).
double distance_to(const ImplicitSurface& surface, const Vec3& p);

/// A grid whose inner samples are pseudo-random in [-1, 1) inside a shell of samples at 1: many
/// faces are ambiguous, between cubes with a minority of inside corners and cubes with a
/// majority, and the surface at 0 is closed. `n` samples along each axis (n >= 3).
ScalarGrid ambiguous_field(int n);

}  // namespace crossdiv::datasets
