#include "crossdiv/verification/studies/pages_study.h"

#include <filesystem>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/bundled_curves.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/pages/editor_page.h"
#include "crossdiv/verification/pages/levels_page.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// Levels on the page: 3, the seed's GUI's usual depth; the largest entry (the torus under
/// Loop) then has 18k triangles, which a browser turns in real time in four views.
constexpr int kPageLevels = 3;

/// The meshes each scheme is shown on: a closed and, where the scheme has a boundary rule that
/// shows, an open one.
const std::vector<std::pair<std::string, Scheme>>& page_entries() {
    static const std::vector<std::pair<std::string, Scheme>> entries = {
        {"icosahedron", Scheme::Loop},           {"open-patch", Scheme::Loop},
        {"torus", Scheme::Loop},                 {"quad-cube", Scheme::CatmullClark},
        {"prism-5", Scheme::CatmullClark},       {"quad-cube", Scheme::DooSabin},
        {"icosahedron", Scheme::Sqrt3},          {"octahedron", Scheme::Butterfly},
        {"open-patch", Scheme::ModifiedButterfly},
    };
    return entries;
}

void curve_page(const std::string& out_dir, CheckReport& out) {
    std::vector<CurveFile> files;
    for (const auto& b : datasets::bundled_curves())
        if (b.format == "swp") files.push_back(datasets::bundled_curve_file(b.name));
    json data = editor_data(files, "Bundled curves: de Casteljau, core's tessellations and frames", true);
    data["solo"] = true;  // curves of several files, each in its own place: one at a time
    long runs = 0, over = 0;
    double worst = 0;
    for (const json& c : data["curves"])
        for (const json& r : c["core"]["tessellations"]) {
            if (r["mode"] != "distance") continue;
            ++runs;
            const double ratio = r["deviation"].get<double>() / r["tol"].get<double>();
            worst = std::max(worst, ratio);
            if (!(ratio <= 1)) ++over;
        }
    out.checks.push_back(count_check("curves page", "distance mode within tolerance", "measured deviation", static_cast<double>(over),
                                     std::to_string(runs) + " distance-mode runs on the page's " +
                                         std::to_string(data["curves"].size()) + " curves; largest deviation / tolerance " +
                                         std::to_string(worst)));
    out.tables["pages"]["curves"] = {{"page", "curves/editor.html"}, {"curves", data["curves"].size()},
                                     {"skipped", data["skipped"]}, {"distance_runs", runs}, {"worst_ratio", worst}};
    write_editor_page((fs::path(out_dir) / "curves").string(), data);
}

void levels_page(const std::string& out_dir, CheckReport& out) {
    std::vector<LevelsEntry> entries;
    json rows = json::array();
    for (const auto& [mesh, scheme] : page_entries()) {
        const PolyMesh input = datasets::bundled_mesh(mesh);
        RefineRequest request{scheme, SchemeRule{}, kPageLevels};
        LevelsEntry e{mesh, to_string(scheme), rule_name(scheme, request.rule), core_implementation().refine(input, request)};
        const MeshTopology t0 = mesh_topology(e.levels.front());
        long changed = 0;
        json counts = json::array();
        for (const PolyMesh& m : e.levels) {
            const MeshTopology t = mesh_topology(m);
            changed += (t.euler != t0.euler) + (t.boundary_loops != t0.boundary_loops);
            counts.push_back({{"vertices", t.vertices}, {"faces", t.faces}, {"euler", t.euler}});
        }
        out.checks.push_back(count_check(mesh + " " + e.scheme, "levels keep the topology", "input",
                                         static_cast<double>(changed),
                                         "levels whose Euler characteristic or boundary loop count differs from the input's"));
        rows.push_back({{"mesh", mesh}, {"scheme", e.scheme}, {"levels", counts}});
        entries.push_back(std::move(e));
    }
    out.tables["pages"]["levels"] = {{"page", "levels/levels.html"}, {"entries", rows}};
    write_levels_page((fs::path(out_dir) / "levels").string(), entries);
}

}  // namespace

CheckReport pages_study(const std::string& out_dir) {
    CheckReport out;
    curve_page(out_dir, out);
    levels_page(out_dir, out);
    return out;
}

}  // namespace crossdiv::verification
