#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/io/mesh_io.h"
#include "line_reader.h"

namespace crossdiv {

PolyMesh read_obj(std::istream& in, const std::string& name) {
    io_detail::LineReader r(in, name);
    PolyMesh mesh;
    mesh.source.file = name;
    bool any_color = false;
    std::vector<int> corners;
    int unknown_lines = 0, first_unknown = 0;
    std::string first_unknown_word;
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
        } else if (kw == "f") {
            corners.clear();
            for (std::string_view t = r.token(); !t.empty(); t = r.token()) {
                const long idx = r.integer(t.substr(0, t.find('/')), "vertex index");
                const long nv = static_cast<long>(mesh.positions.size());
                if (idx == 0) r.fail("vertex index 0: OBJ indices start at 1");
                const long v = idx > 0 ? idx - 1 : nv + idx;  // negative: relative to the last vertex
                if (v < 0) r.fail("relative vertex index " + std::to_string(idx) + " points before the first vertex");
                corners.push_back(static_cast<int>(v));
            }
            if (corners.size() < 3) r.fail("a face needs at least 3 vertices, got " + std::to_string(corners.size()));
            mesh.add_face(corners);
            mesh.source.face_line.push_back(r.line_number());
        } else if (kw == "vt" || kw == "vn" || kw == "vp" || kw == "g" || kw == "o" || kw == "s" ||
                   kw == "usemtl" || kw == "mtllib" || kw == "l" || kw == "p" || kw == "t") {
            continue;  // not geometry the schemes use
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
                r.fail_at(mesh.source.face_line[f], "vertex index " + std::to_string(mesh.face(f)[k] + 1) +
                                                        " out of range: the file has " + std::to_string(nv) +
                                                        " vertices");
    if (!any_color) mesh.colors.clear();
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
            if (with_normals) {  // vertex i has normal i: "v//v"
                buf += "//";
                append_int(buf, mesh.face(f)[k] + 1);
            }
        }
        buf += '\n';
    }
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

}  // namespace crossdiv
