#pragma once
/// @file
/// A C++ function as the implementation under test (or as a reference): the way a library
/// user puts their own subdivision, linked into their program, through every comparison
/// without writing a command-line tool. The function gets the input mesh and the request
/// (scheme, named rule, number of levels) and returns the refined mesh in its own numbering.
///
/// It runs like a library reference: in a forked child with a time limit (refine_isolated),
/// so that a crash, an exception or a hang is the run's outcome; its result passes the
/// checks of a program's (finite, the scheme's counts, triangles where the scheme makes them).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {

/// Refines `mesh` by `request.levels` levels of `request.scheme` under `request.rule`.
using RefineFunction = std::function<PolyMesh(const PolyMesh& mesh, const RefineRequest& request)>;

/// `refine` as an implementation of `schemes` (each with core's named rules declared; what it
/// applies is measured). Each level k of a comparison is one call with levels = k.
/// @throws InputError for an empty name, no scheme or an empty function.
std::unique_ptr<Implementation> make_callback_implementation(const std::string& name, std::vector<Scheme> schemes,
                                                             RefineFunction refine);

}  // namespace crossdiv::verification
