#include "crossdiv/verification/harness/tier.h"

#include "crossdiv/error.h"

namespace crossdiv::verification {

const char* to_string(Tier tier) {
    switch (tier) {
        case Tier::Strict: return "strict";
        case Tier::Weak: return "weak";
        case Tier::Geometric: return "geometric";
    }
    return "unknown";
}

Tier tier_from_string(const std::string& name) {
    for (Tier t : {Tier::Strict, Tier::Weak, Tier::Geometric})
        if (name == to_string(t)) return t;
    throw InputError("unknown tier '" + name + "' (known: strict, weak, geometric)");
}

}  // namespace crossdiv::verification
