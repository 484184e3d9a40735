#pragma once
/// @file
/// One implementation refining one mesh outside a comparison (`crossdiv subdivide --impl`, the
/// Python module's subdivide), where a failure has no record to go to: it is an error naming
/// the implementation. A reference library runs in a forked child, as every comparison runs it
/// (refine_isolated), so that its crash, abort, hang or unbounded allocation on a hostile mesh
/// is that error instead of the death of the caller.

#include <string>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::verification {

/// `implementation`'s levels of `mesh` as `request` asks. Core runs here (it refuses bad input by
/// an InputError and does not crash); every other implementation as refine_isolated runs it,
/// with `timeout_seconds`.
/// @throws InputError "<name> refused <input>: <its words>" when it rejects the input, and
///   "<name> failed on <input>: <outcome>" (crashed: signal 11 ..., timeout, non-finite-output:
///   ...) otherwise.
adapters::LevelTrace refine_or_throw(const Implementation& implementation, const PolyMesh& mesh, const RefineRequest& request,
                                     const std::string& input_name, double timeout_seconds);

/// The last level alone, as refine_or_throw makes it: core keeps no earlier level (its
/// refine_last), a library's levels come back from its child and the last is kept.
PolyMesh refine_last_or_throw(const Implementation& implementation, const PolyMesh& mesh, const RefineRequest& request,
                              const std::string& input_name, double timeout_seconds);

}  // namespace crossdiv::verification
