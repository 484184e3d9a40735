#include "invariance_command.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "command.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/io/output_file.h"
#include "crossdiv/verification/comparisons/invariance.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/implementations/output_size.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/suite/invariance_case.h"

namespace crossdiv::cli {

using namespace crossdiv::verification;

namespace {

/// A file name's stem for an input spec: "bundled:torus" -> "bundled-torus", "a/b.obj" -> "b".
std::string file_stem(const std::string& spec) {
    std::string s = std::filesystem::path(spec).stem().string();
    std::replace(s.begin(), s.end(), ':', '-');
    return s;
}

}  // namespace

int run_invariance(const InvarianceOptions& o, const Implementation* subject) {
    const Scheme scheme = scheme_from_string(o.scheme.scheme);
    std::vector<InputTransformation> transforms;
    for (const std::string& t : o.transforms) transforms.push_back(input_transformation_from_string(t));
    if (transforms.empty()) transforms.assign(kInputTransformations.begin(), kInputTransformations.end());
    std::vector<const Implementation*> impls;
    if (subject) {
        impls.push_back(subject);
    } else if (!o.impls.empty()) {
        for (const std::string& name : o.impls) impls.push_back(&find_implementation(name));
    } else {
        impls.push_back(&core_implementation());
        for (const Implementation* r : references_for(scheme)) impls.push_back(r);
    }
    for (const Implementation* impl : impls)
        if (!impl->support(scheme))
            throw InputError(impl->name() + " has no " + std::string(to_string(scheme)) + " refinement");

    const std::vector<std::string> inputs = expand_inputs(o.inputs);
    if (inputs.empty()) throw InputError("no inputs (a collection folder may be absent)");
    nlohmann::json results = nlohmann::json::array();
    int failures = 0, checks = 0, not_compared = 0;
    for (const std::string& in : inputs) {
        PolyMesh mesh = load_input(in, o.scheme.unknown_tags);
        require_refined_size(mesh, scheme, o.scheme.levels, o.scheme.max_faces, in, "--max-faces");
        RefineRequest request{scheme, rule_with_tags(scheme, o.scheme, mesh), o.scheme.levels};
        if (scheme == Scheme::Loop) request.rule.loop.weights = loop_weights_from_string(o.weights);
        request.face_varying = face_varying_rule_noted(scheme, o.scheme.face_varying, mesh);
        fmt::print("{} ({} vertices, {} faces) {} {} levels={} seed={}\n", in, mesh.num_vertices(), mesh.num_faces(),
                   to_string(scheme), rule_name(scheme, request.rule), o.scheme.levels, o.seed);
        for (const Implementation* impl : impls) {
            const InvarianceReport r = check_invariance(*impl, mesh, request, transforms, o.seed, o.tolerance, o.timeout, o.isolate);
            nlohmann::json rows = nlohmann::json::array();
            nlohmann::json minimal = nullptr;
            if (r.outcome.status != RunStatus::Ok) {
                // Its run on the input itself failed: nothing to compare, said once.
                fmt::print("  {:<17} {}\n", impl->name(), r.outcome.summary());
            }
            // What each finding measures to be (a reference's class in the suite), every finding at once.
            const std::vector<std::optional<InvarianceCause>> causes =
                causes_of(*impl, mesh, request, r, o.seed, o.tolerance, o.timeout, o.isolate);
            for (size_t i = 0; i < r.checks.size(); ++i) {
                const InvarianceCheck& c = r.checks[i];
                ++checks;
                failures += c.finding();
                not_compared += c.result == InvarianceResult::NotCompared;
                if (r.outcome.status == RunStatus::Ok)
                    fmt::print("  {:<17} {:<22} {:<16} {}\n", impl->name(), to_string(c.transformation), to_string(c.result),
                               c.explanation);
                nlohmann::json cause = nullptr;
                if (const std::optional<InvarianceCause>& why = causes[i]) {
                    fmt::print("  {:<17} {:<22} cause: {}: {}\n", "", "", to_string(why->cls), why->why);
                    cause = {{"class", to_string(why->cls)}, {"why", why->why}};
                }
                nlohmann::json row = to_json(c);
                row["cause"] = cause;
                rows.push_back(std::move(row));
            }
            // The first finding shrunk (within kInvarianceShrinkSeconds).
            if (const std::optional<InvarianceMinimal> m = shrink_first_finding(
                    *impl, subject != nullptr, impl == subject || impl == &core_implementation(), mesh, request, r, causes,
                    o.seed, o.tolerance, o.timeout, o.isolate, o.out, file_stem(in))) {
                fmt::print("  {:<17} minimal input: {} faces ({} checks{}): {}\n  {:<17} reproduce: {}\n", impl->name(), m->faces,
                           m->tests, m->cut_short ? ", cut short by the time limit" : "", m->explanation, "", m->reproduce);
                minimal = to_json(*m);
            }
            results.push_back({{"input", in},
                               {"minimal", minimal},
                               {"implementation", impl->name()},
                               {"outcome", r.outcome.summary()},
                               {"invariant", r.invariant()},
                               {"checks", rows}});
        }
    }
    if (!o.json.empty())
        write_json(o.json, {{"tool", "crossdiv invariance"}, {"scheme", to_string(scheme)}, {"levels", o.scheme.levels},
                            {"seed", o.seed}, {"tolerance", o.tolerance}, {"results", results}});
    fmt::print("\n{} of {} checks invariant, {} not invariant or nondeterministic, {} not compared (a refused input, "
               "or the reason each check gives above){}\n",
               checks - failures - not_compared, checks, failures, not_compared,
               failures ? "; some implementation depends on how the input is written (see above)" : "");
    return failures ? 1 : 0;
}

}  // namespace crossdiv::cli
