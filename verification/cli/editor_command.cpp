#include "editor_command.h"

#include <fmt/format.h>

#include <filesystem>

#include "command.h"
#include "crossdiv/verification/properties/curve_checks.h"
#include "crossdiv/verification/pages/editor_page.h"

namespace crossdiv::cli {
namespace {

struct EditorArgs {
    std::string input;
    std::string out = "editor";
    void add_to(CLI::App& app) {
        app.add_option("input", input, "Curve file (.swp) or curve:NAME to start from; without it, one small Bezier curve");
        app.add_option("--out", out, "Folder to write the page into (editor.html)")->capture_default_str();
    }
};

int run_editor(const EditorArgs& a) {
    std::vector<CurveFile> files;
    if (!a.input.empty()) files.push_back(verification::load_curve_input(a.input));
    nlohmann::json data = verification::editor_data(files, a.input.empty() ? "Curve editor" : "Curve editor: " + a.input, false);
    // An empty start gets the page's own example curve.
    if (a.input.empty()) data.erase("curves");
    for (const auto& s : data["skipped"])
        fmt::print(stderr, "not editable in the page (it edits bez, bsp, crm and crc records), left out: {}\n", s.get<std::string>());
    verification::write_editor_page(a.out, data);
    fmt::print("wrote {}: open it in a browser; its Download SWP button writes what `crossdiv tessellate` reads\n",
               (std::filesystem::path(a.out) / "editor.html").string());
    return 0;
}

}  // namespace

void add_editor_command(CLI::App& app, int& status) {
    add_command<EditorArgs>(app, "editor", "Write the curve editor page (add, drag, remove control points; export SWP)", status,
                            run_editor);
}

}  // namespace crossdiv::cli
