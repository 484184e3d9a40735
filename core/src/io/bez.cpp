// The BEZ reader (meshedit): a patch count, then 16 points x y z per patch.

#include <fstream>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/io/input_file.h"
#include "crossdiv/io/patch_io.h"
#include "curve_tokens.h"

namespace crossdiv {

std::vector<BezierPatch> read_bez(std::istream& in, const std::string& name) {
    io_detail::Parser p(io_detail::lex(in), name);
    const long n = p.integer("the patch count", 1);
    std::vector<BezierPatch> patches;
    patches.reserve(static_cast<size_t>(std::min(n, 1L << 16)));
    const char* axis[] = {"x", "y", "z"};
    for (long k = 0; k < n; ++k) {
        BezierPatch patch;
        patch.rows = patch.cols = 4;
        patch.line = p.line();
        for (int i = 0; i < 16; ++i) {
            Vec3 c;
            for (int d = 0; d < 3; ++d) {
                const std::string what = std::string(axis[d]) + " of point " + std::to_string(i + 1) + " (row " +
                                         std::to_string(i / 4 + 1) + ") of patch " + std::to_string(k + 1) + " of " +
                                         std::to_string(n);
                c[d] = p.real(what.c_str());
            }
            patch.control.push_back(c);
        }
        patches.push_back(std::move(patch));
    }
    if (!p.done()) p.fail("unexpected '" + p.peek().text + "' after " + std::to_string(n) + " patches of 16 points");
    return patches;
}

std::vector<BezierPatch> read_bez(const std::string& path) {
    std::ifstream in = open_input_file(path);
    return read_bez(in, path);
}

}  // namespace crossdiv
