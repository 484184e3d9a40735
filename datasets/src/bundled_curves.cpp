#include "crossdiv/datasets/bundled_curves.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"
#include "crossdiv/datasets/data_paths.h"

namespace crossdiv::datasets {

const std::vector<BundledCurve>& bundled_curves() {
    static const std::vector<BundledCurve> all{
        {"s-curve", "piecewise cubic Bezier, C1 joint and a C0 corner", "swp",
         "bez2 s 24 10\n[0 0] [1 2] [3 2] [4 0]\n[5 -2] [7 -2] [8 0]\n[8 1] [9 2] [10 2]\n"},
        {"cusp", "cubic Bezier with a cusp (derivative zero at t = 1/2)", "swp",
         "bez2 cusp 32 4\n[0 0] [1 1] [0 1] [1 0]\n"},
        {"flower", "closed uniform B-spline (last three points repeat the first three)", "swp",
         "bsp2 flower 12 11\n[0 -0.25] [0.75 -0.75] [0.25 0] [0.75 0.75] [0 0.25] [-0.75 0.75]\n"
         "[-0.25 0] [-0.75 -0.75] [0 -0.25] [0.75 -0.75] [0.25 0]\n"},
        {"catmull-rom-open", "open Catmull-Rom through five points (our crm2 record)", "swp",
         "crm2 path 16 7\n[-1 0] [0 0] [1 1] [2 -1] [3 0.5] [4 0] [5 0]\n"},
        {"catmull-rom-star", "closed Catmull-Rom star (our crc2 record)", "swp",
         "crc2 star 16 10\n[0 3] [0.7 1] [2.9 0.9] [1.1 -0.4] [1.8 -2.4] [0 -1.2] [-1.8 -2.4] [-1.1 -0.4] "
         "[-2.9 0.9] [-0.7 1]\n"},
        {"space-bspline", "closed cubic B-spline in space (the course's weird.swp sweep)", "swp",
         "bsp3 knot 16 11\n[-1.427273 0.424545 0.929339] [-1.767273 -1.585455 0.371157] [0.912727 -1.585455 -0.278843]\n"
         "[1.922727 -0.255455 -0.080661] [1.582727 1.374545 -1.050661] [0.912727 2.034545 -0.760661]\n"
         "[0.242727 2.094545 -0.410661] [-1.097273 1.444545 0.259339] [-1.427273 0.424545 0.929339]\n"
         "[-1.767273 -1.585455 0.371157] [0.912727 -1.585455 -0.278843]\n"},
        {"tcb-family", "Kochanek-Bartels through six keys: Catmull-Rom, then tension, continuity and bias at +-0.5 "
                       "(our tcb2 record)",
         "swp",
         "tcb2 catmull-rom 16 6 [0 0 0 0 0] [1 2 0 0 0] [3 3 0 0 0] [4 1 0 0 0] [6 0 0 0 0] [7 2 0 0 0]\n"
         "tcb2 tension+0.5 16 6 [0 0 0.5 0 0] [1 2 0.5 0 0] [3 3 0.5 0 0] [4 1 0.5 0 0] [6 0 0.5 0 0] [7 2 0.5 0 0]\n"
         "tcb2 tension-0.5 16 6 [0 0 -0.5 0 0] [1 2 -0.5 0 0] [3 3 -0.5 0 0] [4 1 -0.5 0 0] [6 0 -0.5 0 0] [7 2 -0.5 0 0]\n"
         "tcb2 continuity+0.5 16 6 [0 0 0 0.5 0] [1 2 0 0.5 0] [3 3 0 0.5 0] [4 1 0 0.5 0] [6 0 0 0.5 0] [7 2 0 0.5 0]\n"
         "tcb2 continuity-0.5 16 6 [0 0 0 -0.5 0] [1 2 0 -0.5 0] [3 3 0 -0.5 0] [4 1 0 -0.5 0] [6 0 0 -0.5 0] [7 2 0 -0.5 0]\n"
         "tcb2 bias+0.5 16 6 [0 0 0 0 0.5] [1 2 0 0 0.5] [3 3 0 0 0.5] [4 1 0 0 0.5] [6 0 0 0 0.5] [7 2 0 0 0.5]\n"
         "tcb2 bias-0.5 16 6 [0 0 0 0 -0.5] [1 2 0 0 -0.5] [3 3 0 0 -0.5] [4 1 0 0 -0.5] [6 0 0 0 -0.5] [7 2 0 0 -0.5]\n"
         "tcb2 mixed 16 6 [0 0] [1 2 0.3 -0.4 0.2] [3 3 -0.2 0.8 -0.6] [4 1] [6 0 0.9 0 0] [7 2]\n"},
        {"bessel-overhauser", "Bessel-Overhauser through unevenly spaced points, open and closed (our ovh2, ovc2)", "swp",
         "ovh2 uneven 16 7 [0 0] [0.2 0.5] [1 1] [3.5 1.2] [4 0] [4.2 -0.3] [7 -1]\n"
         "ovc2 loop 16 6 [0 0] [3 0] [3.3 0.4] [3 2] [0.5 2.5] [-0.2 1]\n"},
        {"kappa-curves", "closed kappa-curves (our kpc2 record): a blob with inflections, a sharp 10-degree spike, "
                         "nearly collinear points (1e-6 off the line), a star whose tips become cusps, and the "
                         "four points of Yan's reference code",
         "swp",
         "kpc2 blob 16 12 [1 0] [1.126 0.65] [0.5 0.866] [0 0.7] [-0.5 0.866] [-1.126 0.65] [-1 0] [-0.606 -0.35]\n"
         "[-0.5 -0.866] [0 -1.3] [0.5 -0.866] [0.606 -0.35]\n"
         "kpc2 spike-10deg 16 4 [0 0] [10 0.874887] [0 1.749773] [-3 0.874887]\n"
         "kpc2 nearly-collinear 16 6 [0 0] [1 0.000001] [2 0] [3 0.000001] [4 0] [2 2]\n"
         "kpc2 star 16 10 [1 0] [0.323607 0.235114] [0.309017 0.951057] [-0.123607 0.380423] [-0.809017 0.587785]\n"
         "[-0.4 0] [-0.809017 -0.587785] [-0.123607 -0.380423] [0.309017 -0.951057] [0.323607 -0.235114]\n"
         "kpc2 yan 16 4 [0 0] [0 1] [2 2] [1 0]\n"},
        {"camera-path", "a camera flying a two-piece cubic path, turning and banking (our cam3 record: position "
                        "and orientation quaternion w x y z per control point)",
         "swp",
         "cam3 fly 24 7 [0 0 0 1 0 0 0] [2 0 0.5 0.98 0 0 0.2] [4 1 1 0.92 0.1 0 0.38] [5 3 1 0.7 0.1 0.1 0.7]\n"
         "[6 5 1 0.6 0.2 0 0.77] [8 6 0.5 0.5 0 0.2 0.84] [10 6 0 0.38 0 0 0.92]\n"},
        {"helix", "three turns of a helix (our helx record)", "swp", "helx spring 96 1 0.5 3\n"},
        {"trefoil", "trefoil knot (our trfl record)", "swp", "trfl knot 120 1\n"},
        {"circles", "the course's circles.swp: two circles", "swp", "circ . 30 1\ncirc . 50 2\n"},
        {"degree-9", "one Bezier curve of degree 9 (BZC)", "bzc",
         "10\n0 0  1 2  2 -1  3 3  4 -2  5 4  6 -1  7 2  8 0  9 1\n"},
    };
    return all;
}

CurveFile bundled_curve_file(const std::string& name) {
    std::string known;
    for (const BundledCurve& c : bundled_curves()) {
        if (c.name == name) {
            std::istringstream in(c.text);
            return c.format == "bzc" ? read_bzc(in, "curve:" + name) : read_swp(in, "curve:" + name);
        }
        known += (known.empty() ? "" : ", ") + c.name;
    }
    throw InputError("unknown bundled curve '" + name + "' (known: " + known + ")");
}

std::vector<std::string> course_curve_files() {
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    auto collect = [&](const fs::path& dir, const char* ext, bool recursive) {
        if (!fs::is_directory(dir)) return;
        std::vector<std::string> found;
        auto take = [&](const fs::directory_entry& e) {
            if (e.is_regular_file() && e.path().extension() == ext) found.push_back(e.path().string());
        };
        if (recursive)
            for (const auto& e : fs::recursive_directory_iterator(dir)) take(e);
        else
            for (const auto& e : fs::directory_iterator(dir)) take(e);
        std::sort(found.begin(), found.end());
        out.insert(out.end(), found.begin(), found.end());
    };
    const fs::path data = shared_data_dir();
    collect(data / "c3100" / "swp", ".swp", true);
    collect(data / "meshedit" / "bzc", ".bzc", false);
    return out;
}

}  // namespace crossdiv::datasets
