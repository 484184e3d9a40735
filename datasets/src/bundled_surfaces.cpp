#include "crossdiv/datasets/bundled_surfaces.h"

#include <algorithm>
#include <filesystem>

#include "crossdiv/error.h"
#include "crossdiv/datasets/data_paths.h"

namespace crossdiv::datasets {

const std::vector<BundledCurve>& bundled_surfaces() {
    static const std::vector<BundledCurve> all{
        {"vase", "srev: a B-spline profile from the axis round to the axis (closed, two poles)", "swp",
         "bsp2 profile 12 9\n[0 1.5] [0 1.5] [0 1.5] [-0.6 1.2] [-0.4 0.2] [-1.0 -0.8] [0 -1] [0 -1] [0 -1]\n"
         "srev vase 48 profile\n"},
        {"bottle-cs", "srev: a closed Catmull-Rom profile away from the axis (a closed ring)", "swp",
         "crc2 section 12 5\n[-2 1] [-3 0] [-2.5 -1] [-1.5 -0.5] [-1.2 0.4]\nsrev ring 40 section\n"},
        {"knot-tube", "gcyl: a circle along a trefoil knot (closed sweep, closure distributed)", "swp",
         "circ profile 16 0.25\ntrfl sweep 180 1\ngcyl knot-tube profile sweep\n"},
        {"bean-ring", "gcyl: a closed non-circular B-spline section along a circle", "swp",
         "bsp2 section 8 9\n[0 -0.25] [0.55 -0.55] [0.25 0] [0.55 0.55] [-0.55 0.55] [-0.25 0] [0 -0.25] [0.55 -0.55] [0.25 0]\n"
         "circ sweep 60 2.2\ngcyl bean-ring section sweep\n"},
        {"horn", "gcyl with a scale curve (our extension): a circle along a space B-spline, growing", "swp",
         "circ profile 24 0.3\nbsp3 sweep 16 5 [0 0 0] [1 0 0] [2 1 0] [3 1 1] [4 0 2]\n"
         "bez2 size 8 4 [0 0.4] [1 0.6] [2 1.4] [3 2.5]\ngcyl horn profile sweep size\n"},
        {"square-frame", "gcyl with corners: a unit square section around a square path of side 4, mitred at the "
                         "four corners (closed; volume 4 L a^2 = 16)",
         "swp",
         "bez2 section 1 13 [-0.5 -0.5] [-0.16666666666666669 -0.5] [0.16666666666666663 -0.5] [0.5 -0.5] "
         "[0.5 -0.16666666666666669] [0.5 0.16666666666666663] [0.5 0.5] [0.16666666666666669 0.5] "
         "[-0.16666666666666663 0.5] [-0.5 0.5] [-0.5 0.16666666666666669] [-0.5 -0.16666666666666663] [-0.5 -0.5]\n"
         "bez3 path 1 13 [0 0 0] [1.3333333333333333 0 0] [2.6666666666666665 0 0] [4 0 0] [4 1.3333333333333333 0] "
         "[4 2.6666666666666665 0] [4 4 0] [2.666666666666667 4 0] [1.3333333333333335 4 0] [0 4 0] "
         "[0 2.666666666666667 0] [0 1.3333333333333335 0] [0 0 0]\n"
         "gcyl square-frame section path\n"},
        {"cornered-tube", "gcyl with corners: a circle along a space Bezier chain whose pieces meet at two corners "
                          "(mitred, open)",
         "swp",
         "circ profile 24 0.3\n"
         "bez3 path 8 10 [0 0 0] [1 0 0] [2 0 0] [3 0 0] [3.5 1 0.2] [4 2 0.5] [4 3 1] [3 3.5 2] [2 4 2.5] [1 4 3]\n"
         "gcyl cornered-tube profile path\n"},
        {"saddle-pair", "two bicubic patches sharing an edge (open)", "bez",
         "2\n"
         "0 0 0  1 0 0.3  2 0 -0.3  3 0 0\n0 1 0.3  1 1 0.8  2 1 0.1  3 1 0.2\n"
         "0 2 -0.3  1 2 0.1  2 2 0.9  3 2 -0.2\n0 3 0  1 3 -0.2  2 3 0.4  3 3 0\n"
         "3 0 0  4 0 0.3  5 0 0.2  6 0 0\n3 1 0.2  4 1 -0.4  5 1 0.3  6 1 0\n"
         "3 2 -0.2  4 2 0.5  5 2 -0.1  6 2 0\n3 3 0  4 3 0.2  5 3 0.1  6 3 0\n"},
        {"pillow", "six bicubic patches on a cube's faces, bulging out, sharing their edges (closed)", "bez",
         "6\n"
         "1 -1 -1  1 -0.333333 -1  1 0.333333 -1  1 1 -1\n"
         "1 -1 -0.333333  1.3 -0.333333 -0.333333  1.3 0.333333 -0.333333  1 1 -0.333333\n"
         "1 -1 0.333333  1.3 -0.333333 0.333333  1.3 0.333333 0.333333  1 1 0.333333\n"
         "1 -1 1  1 -0.333333 1  1 0.333333 1  1 1 1\n"
         "-1 -1 -1  -1 -1 -0.333333  -1 -1 0.333333  -1 -1 1\n"
         "-1 -0.333333 -1  -1.3 -0.333333 -0.333333  -1.3 -0.333333 0.333333  -1 -0.333333 1\n"
         "-1 0.333333 -1  -1.3 0.333333 -0.333333  -1.3 0.333333 0.333333  -1 0.333333 1\n"
         "-1 1 -1  -1 1 -0.333333  -1 1 0.333333  -1 1 1\n"
         "-1 1 -1  -1 1 -0.333333  -1 1 0.333333  -1 1 1\n"
         "-0.333333 1 -1  -0.333333 1.3 -0.333333  -0.333333 1.3 0.333333  -0.333333 1 1\n"
         "0.333333 1 -1  0.333333 1.3 -0.333333  0.333333 1.3 0.333333  0.333333 1 1\n"
         "1 1 -1  1 1 -0.333333  1 1 0.333333  1 1 1\n"
         "-1 -1 -1  -0.333333 -1 -1  0.333333 -1 -1  1 -1 -1\n"
         "-1 -1 -0.333333  -0.333333 -1.3 -0.333333  0.333333 -1.3 -0.333333  1 -1 -0.333333\n"
         "-1 -1 0.333333  -0.333333 -1.3 0.333333  0.333333 -1.3 0.333333  1 -1 0.333333\n"
         "-1 -1 1  -0.333333 -1 1  0.333333 -1 1  1 -1 1\n"
         "-1 -1 1  -0.333333 -1 1  0.333333 -1 1  1 -1 1\n"
         "-1 -0.333333 1  -0.333333 -0.333333 1.3  0.333333 -0.333333 1.3  1 -0.333333 1\n"
         "-1 0.333333 1  -0.333333 0.333333 1.3  0.333333 0.333333 1.3  1 0.333333 1\n"
         "-1 1 1  -0.333333 1 1  0.333333 1 1  1 1 1\n"
         "-1 -1 -1  -1 -0.333333 -1  -1 0.333333 -1  -1 1 -1\n"
         "-0.333333 -1 -1  -0.333333 -0.333333 -1.3  -0.333333 0.333333 -1.3  -0.333333 1 -1\n"
         "0.333333 -1 -1  0.333333 -0.333333 -1.3  0.333333 0.333333 -1.3  0.333333 1 -1\n"
         "1 -1 -1  1 -0.333333 -1  1 0.333333 -1  1 1 -1\n"},
    };
    return all;
}

const BundledCurve& bundled_surface(const std::string& name) {
    std::string known;
    for (const BundledCurve& s : bundled_surfaces()) {
        if (s.name == name) return s;
        known += (known.empty() ? "" : ", ") + s.name;
    }
    throw InputError("unknown bundled surface '" + name + "' (known: " + known + ")");
}

std::vector<std::string> course_surface_files() {
    namespace fs = std::filesystem;
    std::vector<std::string> out;
    const fs::path data = shared_data_dir();
    for (const fs::path& dir : {data / "c3100/swp/srev", data / "c3100/swp/gcyl", data / "meshedit/bez"}) {
        if (!fs::is_directory(dir)) continue;
        std::vector<std::string> found;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file() && (e.path().extension() == ".swp" || e.path().extension() == ".bez"))
                found.push_back(e.path().string());
        std::sort(found.begin(), found.end());
        out.insert(out.end(), found.begin(), found.end());
    }
    return out;
}

}  // namespace crossdiv::datasets
