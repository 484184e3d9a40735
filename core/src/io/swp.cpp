// The SWP reader: one branch per record kind over the shared curve tokens. Every error
// carries file:line.

#include <fstream>
#include <map>
#include <string>

#include "crossdiv/error.h"
#include "crossdiv/io/input_file.h"
#include "crossdiv/io/curve_io.h"
#include "curve_tokens.h"

namespace crossdiv {

namespace {

using io_detail::lex;
using io_detail::Parser;
using io_detail::Token;

struct NamedSpline {
    const char* keyword;
    SplineKeyword spline;
};
constexpr NamedSpline kSplines[] = {
    {"bez2", {CurveType::BezierChain, 2}},      {"bez3", {CurveType::BezierChain, 3}},
    {"bsp2", {CurveType::BSpline, 2}},          {"bsp3", {CurveType::BSpline, 3}},
    {"crm2", {CurveType::CatmullRom, 2}},       {"crm3", {CurveType::CatmullRom, 3}},
    {"crc2", {CurveType::CatmullRomClosed, 2}}, {"crc3", {CurveType::CatmullRomClosed, 3}},
    {"tcb2", {CurveType::Tcb, 2}},              {"tcb3", {CurveType::Tcb, 3}},
    {"tcc2", {CurveType::TcbClosed, 2}},        {"tcc3", {CurveType::TcbClosed, 3}},
    {"ovh2", {CurveType::BesselOverhauser, 2}}, {"ovh3", {CurveType::BesselOverhauser, 3}},
    {"ovc2", {CurveType::BesselOverhauserClosed, 2}}, {"ovc3", {CurveType::BesselOverhauserClosed, 3}},
    {"kpc2", {CurveType::KappaClosed, 2}},
    {"cam3", {CurveType::CameraPath, 3}},
};

const char* kKnown =
    "bez2, bez3, bsp2, bsp3, crm2, crm3, crc2, crc3, tcb2, tcb3, tcc2, tcc3, ovh2, ovh3, ovc2, ovc3, kpc2, cam3, circ, helx, "
    "trfl, srev, gcyl";

/// A TCB key: `[x y]` (tension, continuity and bias 0) or `[x y t c b]` (3D: `[x y z t c b]`).
void read_tcb_keys(Parser& p, CurveRecord& r, long n) {
    std::vector<TcbParameters> given(static_cast<size_t>(n));
    bool any = false;
    for (long i = 0; i < n; ++i) {
        const int line = p.line();
        auto [point, extras] = p.point_with_extras(r.dim, 3, static_cast<int>(i), n);
        r.control.push_back(point);
        if (extras.empty()) continue;
        const TcbParameters key{extras[0], extras[1], extras[2]};
        try {  // here, to name the key's own line
            check_tcb_parameters(key);
        } catch (const InputError& e) {
            p.fail_at(line, "key " + std::to_string(i + 1) + " of " + std::to_string(n) + ": " + e.what());
        }
        given[static_cast<size_t>(i)] = key;
        any = true;
    }
    if (any) r.tcb = std::move(given);
}

/// A camera path's control point: `[x y z w qx qy qz]`, a position and a unit quaternion.
void read_camera_points(Parser& p, CurveRecord& r, long n) {
    for (long i = 0; i < n; ++i) {
        const int line = p.line();
        auto [point, q] = p.point_with_extras(3, 4, static_cast<int>(i), n);
        if (q.empty())
            p.fail_at(line, "point " + std::to_string(i + 1) + " of " + std::to_string(n) +
                                " has 3 numbers, expected 7 (x y z w qx qy qz)");
        r.control.push_back(point);
        r.orientations.emplace_back(q[0], q[1], q[2], q[3]);  // Eigen's order: w, x, y, z
    }
}

}  // namespace

std::optional<SplineKeyword> spline_keyword(std::string_view keyword) {
    for (const NamedSpline& k : kSplines)
        if (keyword == k.keyword) return k.spline;
    return std::nullopt;
}

CurveFile read_swp(std::istream& in, const std::string& name) {
    Parser p(lex(in), name);
    CurveFile f;
    f.path = name;
    std::map<std::string, int> by_name;  // curve name -> index; read-time only
    auto define = [&](CurveRecord r) {
        if (!r.name.empty()) {
            if (auto it = by_name.find(r.name); it != by_name.end())
                p.fail_at(r.line, "curve '" + r.name + "' is already defined on line " +
                                      std::to_string(f.curves[it->second].line));
            by_name[r.name] = static_cast<int>(f.curves.size());
        }
        f.curves.push_back(std::move(r));
    };
    auto lookup = [&](const std::string& curve, int line) {
        auto it = by_name.find(curve);
        if (it == by_name.end()) p.fail_at(line, "undefined curve '" + curve + "' (curves must be defined before use)");
        return it->second;
    };
    while (!p.done()) {
        const Token head = p.next("a record");
        if (head.text == "[" || head.text == "]")
            p.fail_at(head.line, "unbalanced bracket: '" + head.text + "' outside a point list (too many points?)");
        CurveRecord r;
        r.keyword = head.text;
        r.line = head.line;
        if (const std::optional<SplineKeyword> spline = spline_keyword(head.text)) {
            r.type = spline->type;
            r.dim = spline->dim;
            r.name = p.word("a curve name");
            r.steps = static_cast<int>(p.integer("STEPS", 1, kMaxSteps));
            const long n = p.integer("the point count", 1);
            if (r.type == CurveType::Tcb || r.type == CurveType::TcbClosed)
                read_tcb_keys(p, r, n);
            else if (r.type == CurveType::CameraPath)
                read_camera_points(p, r, n);
            else
                for (long i = 0; i < n; ++i) r.control.push_back(p.point(r.dim, static_cast<int>(i), n));
            try {
                if (r.type == CurveType::KappaClosed)  // solved once, here
                    r.kappa = std::make_shared<const KappaCurve>(converged_kappa_curve(r.control));
                (void)r.chain();  // the count rules: 3n + 1 for Bezier, >= 4 for B-splines, ...
                if (r.type == CurveType::CameraPath) r.orientations = quaternion_chain(r.orientations).control;
            } catch (const InputError& e) {
                p.fail_at(r.line, head.text + " '" + (r.name == "." ? "." : r.name) + "': " + e.what());
            }
        } else if (head.text == "circ" || head.text == "helx" || head.text == "trfl") {
            r.type = CurveType::Primitive;
            r.dim = head.text == "circ" ? 2 : 3;
            r.name = p.word("a curve name");
            r.steps = static_cast<int>(p.integer("STEPS", 1, kMaxSteps));
            Primitive& prim = r.primitive;
            if (head.text == "circ") {
                prim.kind = PrimitiveKind::Circle;
                prim.radius = p.real("RADIUS");
            } else if (head.text == "helx") {
                prim.kind = PrimitiveKind::Helix;
                prim.radius = p.real("RADIUS");
                prim.pitch = p.real("PITCH");
                prim.turns = p.real("TURNS");
                if (prim.turns <= 0) p.fail_at(r.line, "helx: TURNS must be positive");
            } else {
                prim.kind = PrimitiveKind::Trefoil;
                prim.scale = p.real("SCALE");
            }
            if (prim.radius <= 0 || prim.scale <= 0) p.fail_at(r.line, head.text + ": the size must be positive");
        } else if (head.text == "srev" || head.text == "gcyl") {
            SweepRecord s;
            s.line = head.line;
            s.name = p.word("a surface name");
            if (head.text == "srev") {
                s.kind = SweepRecord::Kind::Revolution;
                s.steps = static_cast<int>(p.integer("STEPS", 1, kMaxSteps));
                s.profile = p.word("the profile curve name");
                s.profile_index = lookup(s.profile, s.line);
            } else {
                s.kind = SweepRecord::Kind::Cylinder;
                s.profile = p.word("the profile curve name");
                s.profile_index = lookup(s.profile, s.line);
                s.sweep = p.word("the sweep curve name");
                s.sweep_index = lookup(s.sweep, s.line);
                // Our extension: an optional scale curve on the same line (the course
                // format has none, and records never share a line, so this is unambiguous).
                if (!p.done() && p.peek().line == s.line) {
                    s.scale = p.word("the scale curve name");
                    s.scale_index = lookup(s.scale, s.line);
                }
            }
            if (s.name == ".") s.name.clear();
            f.sweeps.push_back(std::move(s));
            continue;
        } else {
            p.fail_at(head.line, "unknown record '" + head.text + "' (known: " + kKnown + ")");
        }
        if (r.name == ".") r.name.clear();
        define(std::move(r));
    }
    return f;
}

CurveFile read_swp(const std::string& path) {
    std::ifstream in = open_input_file(path);
    return read_swp(in, path);
}

}  // namespace crossdiv
