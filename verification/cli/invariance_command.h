#pragma once
// The invariance subcommand's work: each implementation refines each input and the input
// written otherwise (comparisons/input_transformation.h), and the two are compared
// (comparisons/invariance.h); one line per implementation and transformation.

#include <cstdint>
#include <string>
#include <vector>

#include "scheme_commands.h"
#include "crossdiv/verification/implementations/implementation.h"

namespace crossdiv::cli {

struct InvarianceOptions {
    std::vector<std::string> inputs;
    PolySchemeArgs scheme;
    std::string weights = "loop";           ///< Loop's weight family
    std::vector<std::string> impls;         ///< empty: core and every reference of the scheme
    std::vector<std::string> transforms;    ///< empty: every transformation
    std::uint64_t seed = 1;
    double tolerance = 1e-12;               ///< the weak tier's, relative to the diagonal
    double timeout = 120;
    bool isolate = true;
    std::string json;
    std::string out = "invariance-out";  ///< where the minimal inputs of the findings go
};

/// `crossdiv invariance IN... --scheme S --levels N [--impl NAME,... | --subject CMD]
/// [--transform NAME,...] [--seed K]`: exit 1 when some implementation is not invariant (or is
/// nondeterministic, or could not be compared), 0 when every one is. `subject`, when given, is
/// the only implementation checked. Each implementation's first non-invariant check on an
/// input of at most 500 faces is shrunk to a minimal input, written to `out` with the line
/// that reproduces it.
int run_invariance(const InvarianceOptions& o, const verification::Implementation* subject);

}  // namespace crossdiv::cli
