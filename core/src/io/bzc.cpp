// The BZC reader (meshedit): a control point count, then that many x y pairs.

#include <fstream>
#include <string>

#include "crossdiv/curves/bezier.h"
#include "crossdiv/error.h"
#include "crossdiv/io/input_file.h"
#include "crossdiv/io/curve_io.h"
#include "curve_tokens.h"

namespace crossdiv {

CurveFile read_bzc(std::istream& in, const std::string& name) {
    io_detail::Parser p(io_detail::lex(in), name);
    CurveFile f;
    f.path = name;
    CurveRecord r;
    r.keyword = "bzc";
    r.type = CurveType::Bezier;
    r.dim = 2;
    r.line = p.line();
    const long n = p.integer("the control point count", 1, kMaxBezierDegree + 1);
    // STEPS is not in the format; 16 intervals draw any of the course curves smoothly.
    r.steps = 16;
    for (long i = 0; i < n; ++i) {
        const std::string which = "x of point " + std::to_string(i + 1) + " of " + std::to_string(n);
        const double x = p.real(which.c_str());
        const double y = p.real(("y of point " + std::to_string(i + 1) + " of " + std::to_string(n)).c_str());
        r.control.emplace_back(x, y, 0.0);
    }
    if (!p.done()) p.fail("unexpected '" + p.peek().text + "' after " + std::to_string(n) + " points");
    f.curves.push_back(std::move(r));
    return f;
}

CurveFile read_bzc(const std::string& path) {
    std::ifstream in = open_input_file(path);
    return read_bzc(in, path);
}

}  // namespace crossdiv
