#include "crossdiv/verification/pages/levels_page.h"

#include <filesystem>
#include <fstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/pages/editor_page.h"
#include "crossdiv/verification/pages/page_arrays.h"

namespace crossdiv::verification {

namespace fs = std::filesystem;

std::string levels_data_script(const std::vector<LevelsEntry>& entries) {
    using nlohmann::json;
    json out = json::array();
    for (const LevelsEntry& e : entries) {
        json levels = json::array();
        for (const PolyMesh& m : e.levels)
            levels.push_back({{"positions", positions64(m)}, {"triangles", triangles32(m)},
                              {"edges", edges32(mesh_topology(m).edge_list)}, {"faces", m.num_faces()}});
        out.push_back({{"mesh", e.mesh}, {"scheme", e.scheme}, {"rule", e.rule}, {"levels", levels}});
    }
    return "window.CROSSDIV_LEVELS = " + json{{"entries", out}}.dump(-1, ' ', false, json::error_handler_t::replace) + ";\n";
}

void write_levels_page(const std::string& dir, const std::vector<LevelsEntry>& entries) {
    prepare_page_folder(dir, "levels", {"levels.html", "levels.js"});
    write_text_file((fs::path(dir) / "levels-data.js").string(), levels_data_script(entries));
}

}  // namespace crossdiv::verification
