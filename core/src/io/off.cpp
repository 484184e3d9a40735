#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "crossdiv/io/mesh_io.h"
#include "line_reader.h"

namespace crossdiv {

PolyMesh read_off(std::istream& in, const std::string& name) {
    io_detail::LineReader r(in, name);
    PolyMesh mesh;
    mesh.source.file = name;
    auto next_content_line = [&](const char* expecting) {
        do {
            if (!r.next()) r.fail(std::string("unexpected end of file, expecting ") + expecting);
        } while (r.at_end_of_line());
    };

    next_content_line("the OFF header");
    std::string_view header = r.token();
    const bool coff = header == "COFF";
    if (header != "OFF" && !coff) r.fail("expected 'OFF' or 'COFF' header, got '" + std::string(header) + "'");
    if (r.at_end_of_line()) next_content_line("vertex, face and edge counts");
    const int nv = r.index(r.integer("vertex count"), "vertex count");
    const int nf = r.index(r.integer("face count"), "face count");
    // The header's counts are claims until the lines are read: reserve no more than a
    // modest start, so a header announcing 2^31 vertices fails at its missing line, not in
    // an allocation.
    constexpr int kTrustedReserve = 1 << 20;
    mesh.positions.reserve(static_cast<size_t>(std::min(nv, kTrustedReserve)));
    for (int v = 0; v < nv; ++v) {
        next_content_line("a vertex");
        Vec3 p;
        p.x() = r.real("x coordinate");
        p.y() = r.real("y coordinate");
        p.z() = r.real("z coordinate");
        mesh.positions.push_back(p);
        mesh.source.vertex_line.push_back(r.line_number());
        if (coff) {
            Vec3 c;
            c.x() = r.real("red component");
            c.y() = r.real("green component");
            c.z() = r.real("blue component");
            mesh.colors.push_back(c);
        }
    }
    std::vector<int> corners;
    for (int f = 0; f < nf; ++f) {
        next_content_line("a face");
        const long n = r.integer("corner count");
        if (n < 3) r.fail("a face needs at least 3 vertices, got " + std::to_string(n));
        corners.clear();
        for (long k = 0; k < n; ++k) {
            const long v = r.integer("vertex index");
            if (v < 0 || v >= nv)
                r.fail("vertex index " + std::to_string(v) + " out of range [0, " + std::to_string(nv) + ")");
            corners.push_back(static_cast<int>(v));
        }
        mesh.add_face(corners);
        mesh.source.face_line.push_back(r.line_number());
    }
    return mesh;
}

void write_off(std::ostream& out, const PolyMesh& mesh) {
    using io_detail::append_int;
    using io_detail::append_real;
    std::string buf = "OFF\n";
    append_int(buf, mesh.num_vertices());
    buf += ' ';
    append_int(buf, mesh.num_faces());
    buf += " 0\n";
    for (const Vec3& p : mesh.positions) {
        append_real(buf, p.x()); buf += ' ';
        append_real(buf, p.y()); buf += ' ';
        append_real(buf, p.z()); buf += '\n';
    }
    for (int f = 0; f < mesh.num_faces(); ++f) {
        append_int(buf, mesh.face_size(f));
        for (int k = 0; k < mesh.face_size(f); ++k) { buf += ' '; append_int(buf, mesh.face(f)[k]); }
        buf += '\n';
    }
    out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

}  // namespace crossdiv
