#include "crossdiv/verification/implementations/callback_implementation.h"

#include "crossdiv/error.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

Capabilities callback_capabilities(const std::vector<Scheme>& schemes) {
    Capabilities c;
    for (Scheme s : schemes) c.schemes.push_back({s, core_implementation().support(s)->rules, false, 0, ""});
    return c;
}

class Callback final : public Implementation {
public:
    Callback(const std::string& name, const std::vector<Scheme>& schemes, RefineFunction refine)
        : Implementation(name, "C++ function", ImplementationKind::Callback, callback_capabilities(schemes)),
          refine_(std::move(refine)) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& request) const override {
        check_refinable(request.scheme);
        return trace_from_input(mesh, request, 1, [&](const RefineRequest& one) { return refine_last(mesh, one); });
    }

    PolyMesh refine_last(const PolyMesh& mesh, const RefineRequest& request) const override {
        check_refinable(request.scheme);
        PolyMesh result = refine_(mesh, request);
        check_program_result(result, request.scheme, mesh, request.levels, name() + "'s result");
        return result;
    }

private:
    RefineFunction refine_;
};

}  // namespace

std::unique_ptr<Implementation> make_callback_implementation(const std::string& name, std::vector<Scheme> schemes,
                                                             RefineFunction refine) {
    if (name.empty()) throw InputError("a callback implementation needs a name");
    if (schemes.empty()) throw InputError("callback '" + name + "' implements no scheme");
    if (!refine) throw InputError("callback '" + name + "' has no function");
    return std::make_unique<Callback>(name, schemes, std::move(refine));
}

}  // namespace crossdiv::verification
