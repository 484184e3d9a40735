#include "crossdiv/verification/implementations/refine_or_throw.h"

#include "crossdiv/error.h"
#include "crossdiv/verification/harness/isolate.h"

namespace crossdiv::verification {

adapters::LevelTrace refine_or_throw(const Implementation& implementation, const PolyMesh& mesh, const RefineRequest& request,
                                     const std::string& input_name, double timeout_seconds) {
    if (implementation.kind() == ImplementationKind::Core) return implementation.refine(mesh, request);
    IsolatedTrace run = refine_isolated(implementation, mesh, request, timeout_seconds, true);
    if (run.outcome.status == RunStatus::Rejected)
        throw InputError(implementation.name() + " refused " + input_name + ": " + run.outcome.message);
    if (run.outcome.status != RunStatus::Ok)
        throw InputError(implementation.name() + " failed on " + input_name + ": " + run.outcome.summary());
    return std::move(*run.trace);
}

PolyMesh refine_last_or_throw(const Implementation& implementation, const PolyMesh& mesh, const RefineRequest& request,
                              const std::string& input_name, double timeout_seconds) {
    if (implementation.kind() == ImplementationKind::Core) return implementation.refine_last(mesh, request);
    return std::move(refine_or_throw(implementation, mesh, request, input_name, timeout_seconds).back());
}

}  // namespace crossdiv::verification
