#include "crossdiv/verification/pages/editor_page.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/curves/frames.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/install_paths.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// Debian's libjs-three: release 111 ships classic scripts, which a page opened from disk runs
/// (it may not import ES modules).
constexpr const char* kThreeFiles[] = {"/usr/share/javascript/three/build/three.min.js",
                                       "/usr/share/javascript/three/examples/js/controls/OrbitControls.js"};

/// Distance tolerances of the page's adaptive runs, as fractions of the curve's diagonal, and
/// angle tolerances in degrees: coarse enough that each run's polygon is seen apart from the curve.
constexpr double kPageDistanceTols[] = {3e-2, 1e-2, 3e-3};
constexpr double kPageAngleTolsDeg[] = {30, 15, 5};

json point_json(const Vec3& p) { return json::array({p.x(), p.y(), p.z()}); }

json points_json(const std::vector<Vec3>& points) {
    json out = json::array();
    for (const Vec3& p : points) out.push_back(point_json(p));
    return out;
}

void copy_file(const fs::path& from, const fs::path& to, const std::string& why) {
    std::error_code ec;
    if (!fs::is_regular_file(from, ec)) throw InputError(from.string() + ": missing (" + why + ")");
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (ec) throw InputError(to.string() + ": cannot write (" + ec.message() + ")");
}

void write_text(const fs::path& path, const std::string& text) {
    write_text_file(path.string(), text);
}

}  // namespace

bool editor_edits(const CurveRecord& r) {
    switch (r.type) {
        case CurveType::BezierChain:
        case CurveType::BSpline:
        case CurveType::CatmullRom:
        case CurveType::CatmullRomClosed: return true;
        default: return false;
    }
}

json core_curve_views(const CurveRecord& r) {
    const BezierChain chain = r.chain();
    const double size = bounding_box_diagonal(chain.points);
    const auto evaluate = record_evaluator(r);
    json runs = json::array();
    auto add = [&](const char* mode, double tol, const TessellationOptions& o) {
        const Polyline poly = tessellate_record(r, o);
        const Deviation d = chordal_deviation(chain, poly);
        runs.push_back({{"mode", mode}, {"tol", tol}, {"edges", poly.size() - 1}, {"deviation", d.max},
                        {"points", points_json(poly.positions)}, {"worst", point_json(evaluate(d.at_param).position)}});
    };
    for (double f : kPageDistanceTols) {
        TessellationOptions o;
        o.mode = TessellationMode::Distance;
        o.tol = f * size;
        add("distance", o.tol, o);
    }
    for (double deg : kPageAngleTolsDeg) {
        TessellationOptions o;
        o.mode = TessellationMode::Angle;
        o.angle_tol = deg * M_PI / 180;
        add("angle (degrees)", deg, o);
    }
    const Polyline uniform = tessellate_record(r, TessellationOptions{});
    json frames = json::object();
    for (const auto& [name, method] : {std::pair{"recursive", FrameMethod::Recursive}, std::pair{"rmf", FrameMethod::DoubleReflection}}) {
        const std::vector<Frame> f = curve_frames(uniform.positions, uniform.tangents, method);
        json T = json::array(), N = json::array(), B = json::array();
        for (const Frame& x : f) {
            T.push_back(point_json(x.T));
            N.push_back(point_json(x.N));
            B.push_back(point_json(x.B));
        }
        frames[name] = {{"points", points_json(uniform.positions)}, {"T", T}, {"N", N}, {"B", B}};
    }
    return {{"tessellations", runs}, {"frames", frames}};
}

json editor_data(const std::vector<CurveFile>& files, const std::string& title, bool with_core) {
    json curves = json::array(), skipped = json::array();
    for (const CurveFile& file : files) {
        std::string stem = fs::path(file.path).stem().string();
        if (stem.starts_with("curve:")) stem.erase(0, 6);  // a bundled curve, curve:NAME
        for (size_t i = 0; i < file.curves.size(); ++i) {
            const CurveRecord& r = file.curves[i];
            const std::string label = r.label(static_cast<int>(i));
            if (!editor_edits(r)) {
                skipped.push_back(stem + ": " + label + " (" + r.keyword + ", line " + std::to_string(r.line) + ")");
                continue;
            }
            // Names stay SWP words and stay apart when several files share the page.
            std::string name = r.name.empty() ? (files.size() > 1 ? stem + "." + std::to_string(i) : ".") : r.name;
            if (files.size() > 1 && !r.name.empty()) name = stem + "." + r.name;
            json c = {{"name", name}, {"keyword", r.keyword}, {"steps", r.steps}, {"points", points_json(r.control)}};
            if (with_core) c["core"] = core_curve_views(r);
            curves.push_back(std::move(c));
        }
    }
    return {{"title", title}, {"curves", curves}, {"skipped", skipped}};
}

void prepare_page_folder(const std::string& dir, const std::string& page, std::initializer_list<const char*> files) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw InputError(dir + ": cannot create the folder (" + ec.message() + ")");
    for (const char* f : kThreeFiles)
        copy_file(f, fs::path(dir) / fs::path(f).filename(), "Debian's three.js: apt-get install libjs-three");
    const fs::path source = fs::path(reports_dir()) / page;
    for (const char* f : files) copy_file(source / f, fs::path(dir) / f, "crossdiv's " + page + " page");
}

void write_editor_page(const std::string& dir, const json& data) {
    prepare_page_folder(dir, "editor", {"editor.html", "editor.js", "spline_math.js"});
    // The data as a script: a page opened from disk may run a script beside it, not fetch a file.
    write_text(fs::path(dir) / "curves.js", "window.CROSSDIV_EDITOR_DATA = " + data.dump(-1, ' ', false, json::error_handler_t::replace) + ";\n");
}

}  // namespace crossdiv::verification
