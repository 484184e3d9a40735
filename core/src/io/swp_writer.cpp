// SWP output: the control-point records, in the layout read_swp reads (swp.cpp).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <ostream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/io/curve_io.h"

namespace crossdiv {
namespace {

std::string describe(const CurveRecord& r, size_t index) {
    return "curve " + std::to_string(index) + (r.name.empty() ? "" : " '" + r.name + "'") + " (" + r.keyword + ")";
}

}  // namespace

void write_swp(std::ostream& out, const CurveFile& curves) {
    if (!curves.sweeps.empty()) throw InputError("write_swp: surfaces (srev, gcyl) are not written, only curves");
    out << std::setprecision(17);
    for (size_t i = 0; i < curves.curves.size(); ++i) {
        const CurveRecord& r = curves.curves[i];
        // The record's own keyword, when it names the record's type and dimension; a camera
        // path's quaternions are not written.
        const std::optional<SplineKeyword> spline = spline_keyword(r.keyword);
        if (!spline || r.type == CurveType::CameraPath)
            throw InputError("write_swp: " + describe(r, i) + " is not a control-point record SWP holds (" +
                             std::string(to_string(r.type)) + ")");
        if (spline->type != r.type || spline->dim != r.dim)
            throw InputError("write_swp: " + describe(r, i) + " is a " + std::string(to_string(r.type)) + " in " +
                             std::to_string(r.dim) + "D, which its keyword does not name");
        const bool with_tcb = r.tcb.size() == r.control.size() && std::any_of(r.tcb.begin(), r.tcb.end(), [](const TcbParameters& p) {
            return !(p == TcbParameters{});
        });
        out << r.keyword << ' ' << (r.name.empty() ? "." : r.name) << ' ' << r.steps << ' ' << r.control.size() << '\n';
        for (size_t k = 0; k < r.control.size(); ++k) {
            const Vec3& p = r.control[k];
            if (!p.allFinite()) throw InputError("write_swp: " + describe(r, i) + " point " + std::to_string(k) + " is not finite");
            out << "[ " << p.x() << ' ' << p.y();
            if (r.dim == 3) out << ' ' << p.z();
            if (with_tcb) out << ' ' << r.tcb[k].tension << ' ' << r.tcb[k].continuity << ' ' << r.tcb[k].bias;
            out << " ]\n";
        }
    }
}

void write_swp(const std::string& path, const CurveFile& curves) {
    OutputFile out(path);
    write_swp(out.stream(), curves);
    out.close();
}

}  // namespace crossdiv
