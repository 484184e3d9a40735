#include "scheme_commands.h"

#include <fmt/core.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/verification/inputs.h"
#include "crossdiv/verification/scheme_comparison.h"
#ifdef CROSSDIV_HAS_OPENSUBDIV
#include "crossdiv/adapters/opensubdiv.h"
#endif
#ifdef CROSSDIV_HAS_OPENMESH
#include "crossdiv/adapters/openmesh.h"
#endif
#ifdef CROSSDIV_HAS_CGAL
#include "crossdiv/adapters/cgal.h"
#endif

namespace crossdiv::cli {
namespace {

using namespace crossdiv::verification;

CatmullClarkOptions catmull_clark_options(const PolySchemeArgs& s) {
    if (s.boundary == "edge-only") return {CatmullClarkBoundary::EdgeOnly};
    if (s.boundary == "edge-and-corner") return {CatmullClarkBoundary::EdgeAndCorner};
    if (s.boundary == "midpoint-average") return {CatmullClarkBoundary::MidpointAverage};
    throw InputError("catmull-clark has no boundary rule '" + s.boundary +
                     "' (edge-only, edge-and-corner, midpoint-average)");
}

/// Catmull-Clark output grows by the corner count each level (every face becomes quads):
/// refuse before any work past the same face limit as Loop.
void check_output_size(const PolyMesh& mesh, int levels, const std::string& name) {
    long long faces = static_cast<long long>(mesh.face_vertices.size());
    for (int l = 1; l < levels; ++l) faces *= 4;
    constexpr long long kMaxOutputFaces = 64LL << 20;
    if (levels > 0 && faces > kMaxOutputFaces)
        throw InputError(name + ": " + std::to_string(levels) + " levels would produce " + std::to_string(faces) +
                         " faces, over the limit of " + std::to_string(kMaxOutputFaces) + "; use fewer levels");
}

std::vector<std::string> split_commas(const std::string& s) {
    std::vector<std::string> out;
    for (size_t b = 0, e; b < s.size(); b = e + 1) {
        e = s.find(',', b);
        if (e == std::string::npos) e = s.size();
        if (e > b) out.push_back(s.substr(b, e - b));
    }
    return out;
}

}  // namespace

int run_scheme_subdivide(const std::string& in, const PolySchemeArgs& s, const std::string& impl, const std::string& out) {
    const Scheme scheme = scheme_from_string(s.scheme);
    (void)scheme;  // one polygon scheme so far: Catmull-Clark
    const CatmullClarkOptions o = catmull_clark_options(s);
    const PolyMesh mesh = load_input(in);
    check_output_size(mesh, s.levels, in);
    PolyMesh result;
    if (impl == "core") {
        result = catmull_clark_subdivide(mesh, o, s.levels);
    } else {
        try {
#ifdef CROSSDIV_HAS_OPENSUBDIV
            if (impl == "opensubdiv") result = adapters::opensubdiv::catmull_clark(mesh, o, s.levels).back();
#endif
#ifdef CROSSDIV_HAS_OPENMESH
            if (impl == "openmesh") {
                if (o.boundary != CatmullClarkBoundary::MidpointAverage)
                    fmt::print("note: openmesh applies the midpoint-average boundary rule, not {}\n", s.boundary);
                result = adapters::openmesh::catmull_clark(mesh, s.levels).back();
            }
#endif
#ifdef CROSSDIV_HAS_CGAL
            if (impl == "cgal") {
                if (o.boundary != CatmullClarkBoundary::EdgeOnly)
                    fmt::print("note: cgal applies the edge-only boundary rule, not {}\n", s.boundary);
                result = adapters::cgal::catmull_clark(mesh, s.levels).back();
            }
#endif
        } catch (const adapters::Rejected& e) {
            throw InputError(impl + " refused " + in + ": " + e.what());
        }
        if (result.num_vertices() == 0 && mesh.num_vertices() > 0)
            throw InputError(impl + " is not built into this binary, or has no " + s.scheme);
    }
    write_mesh(out, result);
    fmt::print("{}: {} vertices, {} faces -> {} ({} vertices, {} faces, {} level(s), {} {} {})\n", in,
               mesh.num_vertices(), mesh.num_faces(), out, result.num_vertices(), result.num_faces(), s.levels,
               s.scheme, s.boundary, impl);
    return 0;
}

int run_scheme_compare(const std::vector<std::string>& specs, const PolySchemeArgs& s, const std::string& against,
                       const std::string& json_path, double timeout, bool no_isolate) {
    SchemeRequest req;
    req.scheme = scheme_from_string(s.scheme);
    req.catmull_clark = catmull_clark_options(s);
    req.levels = s.levels;
    req.timeout_seconds = timeout;
    req.isolate = !no_isolate;
    // Only the references that have the scheme; naming one that lacks it is an error.
    const std::vector<std::string> have = scheme_reference_names(req.scheme);
    for (const std::string& r : split_commas(against))
        if (std::find(have.begin(), have.end(), r) != have.end()) req.references.push_back(r);
        else throw InputError("reference '" + r + "' has no " + s.scheme + " in this build");

    const std::vector<std::string> inputs = expand_inputs(specs);
    if (inputs.empty()) throw InputError("no inputs (a collection folder may be absent)");
    std::vector<PolyMesh> meshes;
    for (const std::string& in : inputs) {
        meshes.push_back(load_input(in));
        check_output_size(meshes.back(), s.levels, in);
    }
    nlohmann::json results = nlohmann::json::array();
    bool all_agree = true;
    for (size_t i = 0; i < inputs.size(); ++i) {
        const SchemeComparison c = compare_scheme(meshes[i], inputs[i], req);
        fmt::print("\n{} ({} vertices, {} faces) {} boundary={} levels={} (core {:.3f} s)\n", c.input, c.input_vertices,
                   c.input_faces, to_string(c.scheme), c.rule, c.levels, c.core_seconds);
        if (!c.core_error.empty()) fmt::print("  core refused: {}\n", c.core_error);
        fmt::print("  {:<11} {:<17} {:<13} {:>10}  {}\n", "reference", "rule", "verdict", "max rel", "class / explanation");
        for (const SchemeReferenceRun& r : c.runs)
            fmt::print("  {:<11} {:<17} {:<13} {:>10}  {}{}\n", r.reference, r.rule, r.verdict,
                       r.correspondence.method == MatchMethod::None ? "-" : fmt::format("{:.3g}", r.comparison.max_rel),
                       r.divergence_class.empty() ? "" : r.divergence_class + ": ", r.explanation);
        all_agree &= c.all_agree();
        results.push_back(to_json(c));
    }
    if (!json_path.empty()) {
        const std::filesystem::path p(json_path);
        if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
        std::ofstream out(json_path);
        if (!out) throw InputError(json_path + ": cannot write");
        out << nlohmann::json{{"tool", "crossdiv compare"}, {"comparisons", results}}.dump(2) << "\n";
        fmt::print("\nresults written to {}\n", json_path);
    }
    fmt::print("\n{}\n", all_agree ? "every reference agrees" : "some references disagree (see above)");
    return all_agree ? 0 : 1;
}

}  // namespace crossdiv::cli
