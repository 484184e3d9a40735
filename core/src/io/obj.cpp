#include <algorithm>
#include <array>
#include <optional>
#include <charconv>
#include <limits>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/io/mesh_io.h"
#include "line_reader.h"

namespace crossdiv {
namespace {

/// A hole tag's face index and its line, range-checked once every face is read.
struct HoleTag {
    long face;
    int line;
};

/// The edits of one `t vertexedit`, `t edgeedit` or `t faceedit` line, as Hbr's regression
/// reader takes them (hbr_utils.h applyTags): the integers are paths `length face child...
/// element` (faceedit: `length face child...`); the strings are operations, `op P value` or
/// `op P sharpness` (op set, add or subtract), or `hole` for faceedit; each path takes its
/// values in turn, 3 per value and 1 per sharpness, and the edits are made operation by
/// operation, path by path. Ranges are checked once the faces are read.
void read_hierarchical_edits(io_detail::LineReader& r, std::string_view name, const std::vector<long>& ints,
                             const std::vector<double>& reals, const std::vector<std::string_view>& strings,
                             std::vector<HierarchicalEdit>& edits, std::vector<std::string>& notes) {
    const std::string tag = "tag '" + std::string(name) + "': ";
    const bool face_edit = name == "faceedit";
    struct Path {
        long face;
        std::vector<int> children;
        int element;
    };
    std::vector<Path> paths;
    for (size_t k = 0; k < ints.size();) {
        const long length = ints[k];
        const long least = face_edit ? 1 : 2;  // a face, then (but for faces) an element
        if (length < least || length > 64 || k + static_cast<size_t>(length) >= ints.size())
            r.fail(tag + "path length " + std::to_string(length) + " at integer " + std::to_string(k + 1) +
                   (length < least ? " is too short" : length > 64 ? " is longer than 64 levels" : " runs past the integers given"));
        Path p{ints[k + 1], {}, -1};
        const size_t children_end = k + 1 + static_cast<size_t>(face_edit ? length : length - 1);
        for (size_t i = k + 2; i < children_end; ++i) {
            if (ints[i] < 0 || ints[i] > 1'000'000) r.fail(tag + "path component " + std::to_string(ints[i]) + " out of range");
            p.children.push_back(static_cast<int>(ints[i]));
        }
        if (!face_edit) {
            if (ints[k + static_cast<size_t>(length)] < 0 || ints[k + static_cast<size_t>(length)] > 1'000'000)
                r.fail(tag + "element " + std::to_string(ints[k + static_cast<size_t>(length)]) + " out of range");
            p.element = static_cast<int>(ints[k + static_cast<size_t>(length)]);
        }
        paths.push_back(std::move(p));
        k += static_cast<size_t>(length) + 1;
    }
    if (paths.empty()) r.fail(tag + "needs at least one path");
    auto add = [&](const Path& p, EditTarget target, EditOperation op, std::array<double, 3> value) {
        if (p.face < 0 || p.face > 1'000'000'000) r.fail(tag + "face " + std::to_string(p.face) + " out of range");
        edits.push_back({target, op, static_cast<int>(p.face), p.children, p.element, value, r.line_number()});
    };
    if (face_edit) {
        if (!reals.empty()) r.fail(tag + "takes no float arguments, got " + std::to_string(reals.size()));
        if (strings.empty()) r.fail(tag + "needs an operation ('hole')");
        for (std::string_view op : strings)
            if (op != "hole")
                r.fail(tag + "operation '" + std::string(op) + "' is not supported (only 'hole' is; Hbr has no other either)");
        for (const Path& p : paths)
            for (size_t i = 0; i < strings.size(); ++i) add(p, EditTarget::Hole, EditOperation::Set, {});
        return;
    }
    if (strings.empty() || strings.size() % 3 != 0)
        r.fail(tag + "operations come as 'op P value' or 'op P sharpness' triples, got " + std::to_string(strings.size()) + " string(s)");
    struct Operation {
        EditOperation op;
        EditTarget target;
        size_t width;
    };
    std::vector<Operation> ops;
    size_t stride = 0;
    for (size_t j = 0; j < strings.size(); j += 3) {
        const std::string_view op = strings[j], variable = strings[j + 1], kind = strings[j + 2];
        Operation o{};
        if (op == "set") o.op = EditOperation::Set;
        else if (op == "add") o.op = EditOperation::Add;
        else if (op == "subtract") o.op = EditOperation::Subtract;
        else r.fail(tag + "operation '" + std::string(op) + "' is not set, add or subtract");
        if (variable != "P") r.fail(tag + "variable '" + std::string(variable) + "' is not supported (only P, the position, is)");
        if (kind == "sharpness") o.target = name == "edgeedit" ? EditTarget::EdgeSharpness : EditTarget::VertexSharpness;
        else if (kind == "value" && name == "vertexedit") o.target = EditTarget::Position;
        else r.fail(tag + "'" + std::string(kind) + "' is not " + (name == "vertexedit" ? "value or sharpness" : "sharpness"));
        o.width = o.target == EditTarget::Position ? 3 : 1;
        stride += o.width;
        ops.push_back(o);
    }
    // Hbr's reader takes `stride` floats per path and ignores any after them (OpenSubdiv's
    // catmark_square_hedit shapes give 6 per path for one `add P value`); so does this one,
    // and says so.
    if (reals.size() < stride * paths.size())
        r.fail(tag + std::to_string(reals.size()) + " float(s) for " + std::to_string(paths.size()) + " path(s) of " +
               std::to_string(stride) + " value(s) each");
    if (reals.size() > stride * paths.size())
        notes.push_back(tag + "at " + r.name() + ":" + std::to_string(r.line_number()) + " gives " +
                        std::to_string(reals.size()) + " floats for " + std::to_string(paths.size()) + " path(s) of " +
                        std::to_string(stride) + " value(s); the first " + std::to_string(stride * paths.size()) +
                        " are read, as Hbr's reader reads them");
    size_t offset = 0;
    for (const Operation& o : ops) {
        for (size_t p = 0; p < paths.size(); ++p) {
            std::array<double, 3> value{};
            for (size_t i = 0; i < o.width; ++i) value[i] = reals[offset + p * stride + i];
            if (o.target != EditTarget::Position && value[0] < 0)
                r.fail(tag + "sharpness " + std::to_string(value[0]) + " is negative");
            add(paths[p], o.target, o.op, value);
        }
        offset += o.width;
    }
}

/// Reads the arguments of a tag line after its name, `t NAME nint/nfloat/nstring ints floats
/// strings` (the shape-file tag format of OpenSubdiv's regression suite), and stores the
/// crease, corner, hole, creasemethod, interpolateboundary, smoothtriangles and
/// facevaryinginterpolateboundary tags; facevaryingpropagatecorners (an option OpenSubdiv 3
/// dropped) is noted. Returns false for a tag name it does not know.
bool read_tag(io_detail::LineReader& r, std::string_view name, CreaseTags& tags, std::vector<HoleTag>& holes,
              std::vector<std::string>& notes) {
    const std::string_view counts = r.token();
    const size_t s1 = counts.find('/'), s2 = s1 == std::string_view::npos ? s1 : counts.find('/', s1 + 1);
    if (s2 == std::string_view::npos)
        r.fail("tag '" + std::string(name) + "': expected counts as nint/nfloat/nstring, got '" + std::string(counts) + "'");
    const long ni = r.integer(counts.substr(0, s1), "tag integer count");
    const long nf = r.integer(counts.substr(s1 + 1, s2 - s1 - 1), "tag float count");
    const long ns = r.integer(counts.substr(s2 + 1), "tag string count");
    if (ni < 0 || nf < 0 || ns < 0 || ni > 1'000'000 || nf > 1'000'000 || ns > 1'000'000)
        r.fail("tag '" + std::string(name) + "': counts out of range");
    std::vector<long> ints;
    std::vector<double> reals;
    std::vector<std::string_view> strings;
    for (long k = 0; k < ni; ++k) ints.push_back(r.integer("tag integer argument"));
    for (long k = 0; k < nf; ++k) reals.push_back(r.real("tag float argument"));
    for (long k = 0; k < ns; ++k) {
        strings.push_back(r.token());
        if (strings.back().empty()) r.fail("tag '" + std::string(name) + "': missing string argument");
    }
    if (!r.at_end_of_line()) r.fail("tag '" + std::string(name) + "': more arguments than its counts announce");

    auto sharpness = [&](size_t k, size_t items) {
        // One value for all, or one per item (the pair or vertex), in order. (OpenSubdiv's own
        // regression reader, far_utils.h, indexes per-pair values by integer position,
        // floatargs[j], which is a different value from the second pair on; its shape files
        // give one pair per tag, where the two readings agree.)
        if (reals.size() != 1 && reals.size() != items)
            r.fail("tag '" + std::string(name) + "': " + std::to_string(reals.size()) + " sharpness values for " +
                   std::to_string(items) + " item(s); give 1 or " + std::to_string(items));
        const double s = reals.size() == 1 ? reals[0] : reals[k];
        if (s < 0) r.fail("tag '" + std::string(name) + "': sharpness " + std::to_string(s) + " is negative");
        return static_cast<float>(s);
    };
    if (name == "crease") {
        if (ints.size() < 2 || ints.size() % 2 != 0)
            r.fail("tag 'crease': needs vertex index pairs, got " + std::to_string(ints.size()) + " integer(s)");
        for (size_t k = 0; k < ints.size(); k += 2) {
            if (ints[k] == ints[k + 1]) r.fail("tag 'crease': edge (" + std::to_string(ints[k]) + ", " +
                                               std::to_string(ints[k]) + ") joins a vertex to itself");
            tags.edges.push_back({r.index(ints[k], "tag vertex index"), r.index(ints[k + 1], "tag vertex index"),
                                  sharpness(k / 2, ints.size() / 2)});
            tags.edge_line.push_back(r.line_number());
        }
        return true;
    }
    if (name == "corner") {
        if (ints.empty()) r.fail("tag 'corner': needs at least one vertex index");
        for (size_t k = 0; k < ints.size(); ++k) {
            tags.vertices.push_back({r.index(ints[k], "tag vertex index"), sharpness(k, ints.size())});
            tags.vertex_line.push_back(r.line_number());
        }
        return true;
    }
    if (name == "creasemethod") {
        if (strings.size() != 1 || (strings[0] != "normal" && strings[0] != "chaikin"))
            r.fail("tag 'creasemethod': expects one string, 'normal' or 'chaikin'");
        tags.method = strings[0] == "normal" ? CreaseMethod::Uniform : CreaseMethod::Chaikin;
        return true;
    }
    if (name == "hole") {
        if (ints.empty()) r.fail("tag 'hole': needs at least one face index");
        for (long f : ints) holes.push_back({f, r.line_number()});
        return true;
    }
    if (name == "interpolateboundary") {
        if (ints.size() != 1 || ints[0] < 0 || ints[0] > 2)
            r.fail("tag 'interpolateboundary': expects one integer, 0 (none), 1 (edge-and-corner) or 2 (edge-only)");
        tags.boundary = ints[0] == 0 ? BoundaryTag::None : ints[0] == 1 ? BoundaryTag::EdgeAndCorner : BoundaryTag::EdgeOnly;
        return true;
    }
    if (name == "smoothtriangles") {
        if (strings.size() != 1 || (strings[0] != "smooth" && strings[0] != "catmark"))
            r.fail("tag 'smoothtriangles': expects one string, 'smooth' or 'catmark'");
        tags.smooth_triangles = strings[0] == "smooth";
        return true;
    }
    if (name == "facevaryinginterpolateboundary") {
        const std::optional<FaceVaryingRule> rule = ints.size() == 1 ? face_varying_rule_from_tag(ints[0]) : std::nullopt;
        if (!rule)
            r.fail("tag 'facevaryinginterpolateboundary': expects one integer, 0 (none), 1 (corners-only), 2 "
                   "(corners-plus1), 3 (corners-plus2), 4 (boundaries) or 5 (all)");
        tags.face_varying = *rule;
        return true;
    }
    if (name == "vertexedit" || name == "edgeedit" || name == "faceedit") {
        read_hierarchical_edits(r, name, ints, reals, strings, tags.edits, notes);
        return true;
    }
    if (name == "facevaryingpropagatecorners") {
        notes.push_back("tag 'facevaryingpropagatecorners' at " + r.name() + ":" + std::to_string(r.line_number()) +
                        " is ignored: OpenSubdiv 3 has no such option (its regression reader asserts on it); the "
                        "face-varying rule alone decides corners");
        return true;
    }
    return false;
}

/// A 1-based OBJ index (negative: counted back from the last element read, of which there
/// are `count`) as a 0-based one; its range above is checked once the file is read, as
/// positive indices may name elements defined later.
int obj_index(io_detail::LineReader& r, std::string_view token, long count, const std::string& what,
              const char* plural) {
    const long idx = r.integer(token, (what + " index").c_str());
    if (idx == 0) r.fail(what + " index 0: OBJ indices start at 1");
    if (idx > std::numeric_limits<int>::max())
        r.fail(what + " index " + std::to_string(idx) + " is out of range: 32-bit indices address at most " +
               std::to_string(std::numeric_limits<int>::max()) + " " + plural);
    const long i = idx > 0 ? idx - 1 : count + idx;  // negative: relative to the last element
    if (i < 0) r.fail("relative " + what + " index " + std::to_string(idx) + " points before the first " + what);
    return static_cast<int>(i);
}

/// Hole tags name faces from 0; sorted and made unique once every face is read.
std::vector<int> checked_holes(const io_detail::LineReader& r, std::vector<HoleTag>& holes, int num_faces) {
    std::vector<int> out;
    out.reserve(holes.size());
    for (const HoleTag& h : holes) {
        if (h.face < 0 || h.face >= num_faces)
            r.fail_at(h.line, "tag face index " + std::to_string(h.face) +
                                  " out of range: tags count from 0 and the file has " + std::to_string(num_faces) +
                                  " faces");
        out.push_back(static_cast<int>(h.face));
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

/// Tag indices are 0-based vertex indices; checked once every vertex is read.
void check_tag_indices(const io_detail::LineReader& r, const PolyMesh& mesh) {
    const long nv = mesh.num_vertices();
    auto check = [&](long v, int line) {
        if (v < 0 || v >= nv)
            r.fail_at(line, "tag vertex index " + std::to_string(v) + " out of range: tags count from 0 and the file has " +
                                std::to_string(nv) + " vertices");
    };
    for (size_t k = 0; k < mesh.creases.edges.size(); ++k) {
        check(mesh.creases.edges[k].a, mesh.creases.edge_line[k]);
        check(mesh.creases.edges[k].b, mesh.creases.edge_line[k]);
    }
    for (size_t k = 0; k < mesh.creases.vertices.size(); ++k)
        check(mesh.creases.vertices[k].v, mesh.creases.vertex_line[k]);
}

}  // namespace

PolyMesh read_obj(std::istream& in, const std::string& name) {
    io_detail::LineReader r(in, name);
    PolyMesh mesh;
    mesh.source.file = name;
    bool any_color = false;
    std::vector<int> corners;
    int unknown_lines = 0, first_unknown = 0;
    std::string first_unknown_word;
    std::vector<HoleTag> holes;
    std::vector<std::array<double, 3>> texcoords;
    bool uvw = false;                    // a texture coordinate with a w
    std::vector<int> corner_texcoords;   // per corner, when the faces give them
    int texture_corners_from = 0;        // the line of the first corner: whether corners give one decides for all
    bool texture_corners = false;
    int mixed_texture_line = 0;          // the first corner that does otherwise than the first one
    while (r.next()) {
        const std::string_view kw = r.token();
        if (kw.empty()) continue;
        if (kw == "v") {
            Vec3 p;
            p.x() = r.real("x coordinate");
            p.y() = r.real("y coordinate");
            p.z() = r.real("z coordinate");
            Vec3 color = Vec3::Zero();
            if (!r.at_end_of_line()) {  // optional per-vertex color (a common OBJ extension)
                color.x() = r.real("red component");
                color.y() = r.real("green component");
                color.z() = r.real("blue component");
                if (!r.at_end_of_line()) r.fail("a vertex has 3 coordinates and optionally 3 color components");
                any_color = true;
            }
            mesh.positions.push_back(p);
            mesh.colors.push_back(color);
            mesh.source.vertex_line.push_back(r.line_number());
        } else if (kw == "vt") {
            // u [v [w]], v and w 0 when absent (the OBJ specification).
            std::array<double, 3> t{r.real("texture coordinate u"), 0.0, 0.0};
            int n = 1;
            for (; n < 3 && !r.at_end_of_line(); ++n) t[n] = r.real(n == 1 ? "texture coordinate v" : "texture coordinate w");
            if (!r.at_end_of_line()) r.fail("a texture coordinate has at most 3 components (u v w)");
            if (n == 3) uvw = true;
            texcoords.push_back(t);
        } else if (kw == "f") {
            corners.clear();
            for (std::string_view t = r.token(); !t.empty(); t = r.token()) {
                const size_t slash = t.find('/');
                corners.push_back(obj_index(r, t.substr(0, slash), static_cast<long>(mesh.positions.size()), "vertex", "vertices"));
                // "v/vt", "v/vt/vn", "v//vn" or "v": the texture index, when there is one.
                const std::string_view rest = slash == std::string_view::npos ? std::string_view{} : t.substr(slash + 1);
                const std::string_view tex = rest.substr(0, rest.find('/'));
                const bool has_tex = !tex.empty();
                if (texture_corners_from > 0 && has_tex != texture_corners && mixed_texture_line == 0)
                    mixed_texture_line = r.line_number();
                if (texture_corners_from == 0) {
                    texture_corners_from = r.line_number();
                    texture_corners = has_tex;
                }
                if (has_tex)
                    corner_texcoords.push_back(
                        obj_index(r, tex, static_cast<long>(texcoords.size()), "texture coordinate", "texture coordinates"));
            }
            if (corners.size() < 3) r.fail("a face needs at least 3 vertices, got " + std::to_string(corners.size()));
            mesh.add_face(corners);
            mesh.source.face_line.push_back(r.line_number());
        } else if (kw == "vn" || kw == "vp" || kw == "g" || kw == "o" || kw == "s" ||
                   kw == "usemtl" || kw == "mtllib" || kw == "l" || kw == "p") {
            continue;  // not geometry the schemes use
        } else if (kw == "t") {
            const std::string name(r.token());
            if (name.empty()) r.fail("a tag line needs a tag name");
            if (!read_tag(r, name, mesh.creases, holes, mesh.source.notes))
                mesh.source.unknown_tags.push_back("'" + name.substr(0, 40) + "' at " + r.name() + ":" +
                                                   std::to_string(r.line_number()));
        } else if (unknown_lines++ == 0) {
            first_unknown = r.line_number();
            first_unknown_word = std::string(kw.substr(0, 40));
        }
    }
    if (unknown_lines > 0)
        mesh.source.notes.push_back("skipped " + std::to_string(unknown_lines) +
                                    " line(s) with an unknown statement, the first at " + name + ":" +
                                    std::to_string(first_unknown) + " ('" + first_unknown_word + "')");
    // Positive indices may name vertices defined later in the file, so range is checked here.
    const int nv = mesh.num_vertices();
    for (int f = 0; f < mesh.num_faces(); ++f)
        for (int k = 0; k < mesh.face_size(f); ++k)
            if (mesh.face(f)[k] >= nv)
                r.fail_at(mesh.source.face_line[f], "vertex index " + std::to_string(mesh.face(f)[k] + 1L) +
                                                        " out of range: the file has " + std::to_string(nv) +
                                                        " vertices");
    check_tag_indices(r, mesh);
    for (const HierarchicalEdit& e : mesh.creases.edits) {
        const std::string problem = hierarchical_edit_problem(
            e, mesh.num_faces(), e.face >= 0 && e.face < mesh.num_faces() ? mesh.face_size(e.face) : 0);
        if (!problem.empty()) r.fail_at(e.line, "hierarchical edit: " + problem);
    }
    mesh.creases.holes = checked_holes(r, holes, mesh.num_faces());
    if (!any_color) mesh.colors.clear();
    if (mixed_texture_line > 0) {
        // Files made by modelling tools often give texture coordinates to some objects only: the
        // geometry is read, the texture coordinates are not (a channel needs a value at every
        // corner), and a note says why.
        mesh.source.notes.push_back(r.name() + ": texture coordinates not read: the corners of line " +
                                    std::to_string(mixed_texture_line) + " " + (texture_corners ? "have none" : "have one") +
                                    ", those of line " + std::to_string(texture_corners_from) + " " +
                                    (texture_corners ? "have one" : "have none") + " (a channel needs one at every corner)");
        texture_corners = false;
    }
    if (texture_corners) {
        const long nt = static_cast<long>(texcoords.size());
        int corner = 0;
        for (int f = 0; f < mesh.num_faces(); ++f)
            for (int k = 0; k < mesh.face_size(f); ++k, ++corner)
                if (corner_texcoords[corner] >= nt)
                    r.fail_at(mesh.source.face_line[f], "texture coordinate index " +
                                                            std::to_string(corner_texcoords[corner] + 1L) +
                                                            " out of range: the file has " + std::to_string(nt) +
                                                            " texture coordinates");
        FaceVaryingChannel uv;
        uv.name = "uv";
        uv.dimension = uvw ? 3 : 2;
        uv.values.reserve(texcoords.size() * static_cast<size_t>(uv.dimension));
        for (const auto& t : texcoords) uv.values.insert(uv.values.end(), t.begin(), t.begin() + uv.dimension);
        uv.corner_values = std::move(corner_texcoords);
        mesh.face_varying.push_back(std::move(uv));
    }
    return mesh;
}

void write_obj(std::ostream& out, const PolyMesh& mesh, std::span<const Vec3> normals) {
    using io_detail::append_int;
    using io_detail::append_real;
    const bool colors = !mesh.colors.empty() && mesh.colors.size() == mesh.positions.size();
    const bool with_normals = !normals.empty();
    if (with_normals && normals.size() != mesh.positions.size())
        throw std::logic_error("write_obj: " + std::to_string(normals.size()) + " normals for " +
                               std::to_string(mesh.positions.size()) + " vertices");
    std::string buf;
    buf.reserve(static_cast<size_t>(mesh.num_vertices()) * (with_normals ? 128 : 64) + mesh.face_vertices.size() * 16);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        buf += 'v';
        for (double x : mesh.positions[v]) { buf += ' '; append_real(buf, x); }
        if (colors)
            for (double x : mesh.colors[v]) { buf += ' '; append_real(buf, x); }
        buf += '\n';
    }
    // OBJ carries one texture channel: the first face-varying channel, as `vt`.
    const FaceVaryingChannel* uv = mesh.face_varying.empty() ? nullptr : &mesh.face_varying.front();
    if (uv) {
        if (uv->corner_values.size() != mesh.face_vertices.size() || uv->dimension < 1 || uv->dimension > 3)
            throw std::logic_error("write_obj: face-varying channel '" + uv->name + "' does not fit the mesh or has " +
                                   std::to_string(uv->dimension) + " components (OBJ's vt has 1 to 3)");
        for (int i = 0; i < uv->num_values(); ++i) {
            buf += "vt";
            for (int k = 0; k < uv->dimension; ++k) { buf += ' '; append_real(buf, uv->value(i)[k]); }
            buf += '\n';
        }
    }
    for (const Vec3& n : normals) {
        buf += "vn";
        for (double x : n) { buf += ' '; append_real(buf, x); }
        buf += '\n';
    }
    for (int f = 0; f < mesh.num_faces(); ++f) {
        buf += 'f';
        for (int k = 0; k < mesh.face_size(f); ++k) {
            buf += ' ';
            append_int(buf, mesh.face(f)[k] + 1);
            if (uv) {  // "v/t" or "v/t/v"
                buf += '/';
                append_int(buf, uv->corner_values[static_cast<size_t>(mesh.face_start[f] + k)] + 1);
                if (with_normals) buf += '/';
            } else if (with_normals) {
                buf += "//";  // vertex i has normal i: "v//v"
            }
            if (with_normals) append_int(buf, mesh.face(f)[k] + 1);
        }
        buf += '\n';
    }
    // Sharpness tags in the shape-file format, so OpenSubdiv's tools read them back; the
    // float is written with 9 significant digits, enough for every float to read back exactly.
    auto append_float = [&buf](float x) {
        char b[32];
        auto [p, ec] = std::to_chars(b, b + sizeof b, x, std::chars_format::general, 9);
        buf.append(b, p);
    };
    for (const SharpEdge& e : mesh.creases.edges) {
        buf += "t crease 2/1/0 ";
        append_int(buf, e.a);
        buf += ' ';
        append_int(buf, e.b);
        buf += ' ';
        append_float(e.sharpness);
        buf += '\n';
    }
    for (const SharpVertex& v : mesh.creases.vertices) {
        buf += "t corner 1/1/0 ";
        append_int(buf, v.v);
        buf += ' ';
        append_float(v.sharpness);
        buf += '\n';
    }
    if (mesh.creases.method && !mesh.creases.empty()) {
        buf += "t creasemethod 0/0/1 ";
        buf += *mesh.creases.method == CreaseMethod::Uniform ? "normal" : "chaikin";
        buf += '\n';
    }
    if (!mesh.creases.holes.empty()) {
        buf += "t hole ";
        append_int(buf, static_cast<long>(mesh.creases.holes.size()));
        buf += "/0/0";
        for (int f : mesh.creases.holes) {
            buf += ' ';
            append_int(buf, f);
        }
        buf += '\n';
    }
    // Hierarchical edits, one per line: `t vertexedit`/`t edgeedit`/`t faceedit` with one path.
    for (const HierarchicalEdit& e : mesh.creases.edits) {
        const bool hole = e.target == EditTarget::Hole, position = e.target == EditTarget::Position;
        const long length = 1 + e.level() + (hole ? 0 : 1);
        buf += e.target == EditTarget::EdgeSharpness ? "t edgeedit " : hole ? "t faceedit " : "t vertexedit ";
        append_int(buf, length + 1);
        buf += hole ? "/0/1 " : position ? "/3/3 " : "/1/3 ";
        append_int(buf, length);
        buf += ' ';
        append_int(buf, e.face);
        for (int c : e.children) {
            buf += ' ';
            append_int(buf, c);
        }
        if (!hole) {
            buf += ' ';
            append_int(buf, e.element);
            for (int i = 0; i < (position ? 3 : 1); ++i) {
                buf += ' ';
                append_real(buf, e.value[static_cast<size_t>(i)]);
            }
            buf += ' ';
            buf += to_string(e.op);
            buf += position ? " P value" : " P sharpness";
        } else {
            buf += " hole";
        }
        buf += '\n';
    }
    if (const auto& b = mesh.creases.boundary) {
        buf += "t interpolateboundary 1/0/0 ";
        buf += *b == BoundaryTag::None ? '0' : *b == BoundaryTag::EdgeAndCorner ? '1' : '2';
        buf += '\n';
    }
    if (const auto& t = mesh.creases.smooth_triangles) buf += *t ? "t smoothtriangles 0/0/1 smooth\n" : "t smoothtriangles 0/0/1 catmark\n";
    if (const auto& r = mesh.creases.face_varying) {
        buf += "t facevaryinginterpolateboundary 1/0/0 ";
        append_int(buf, face_varying_tag(*r));
        buf += '\n';
    }
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

}  // namespace crossdiv
