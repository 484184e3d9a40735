// PLY (Turk's polygon file format): the header, then each element's records in ASCII or in
// binary of either byte order. Only `vertex` (x, y, z) and `face` (the index list) are kept;
// every other property and element is read past, so that its size is known in binary.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "crossdiv/io/mesh_io.h"
#include "line_reader.h"

namespace crossdiv {
namespace {

/// The scalar types of PLY 1.0, under both of their names.
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<PlyType> ply_type(std::string_view name) {
    struct Named {
        std::string_view a, b;
        PlyType type;
    };
    static constexpr Named types[] = {{"char", "int8", PlyType::Int8},       {"uchar", "uint8", PlyType::UInt8},
                                      {"short", "int16", PlyType::Int16},    {"ushort", "uint16", PlyType::UInt16},
                                      {"int", "int32", PlyType::Int32},      {"uint", "uint32", PlyType::UInt32},
                                      {"float", "float32", PlyType::Float32}, {"double", "float64", PlyType::Float64}};
    for (const Named& n : types)
        if (name == n.a || name == n.b) return n.type;
    return std::nullopt;
}

size_t size_of(PlyType t) {
    switch (t) {
        case PlyType::Int8:
        case PlyType::UInt8: return 1;
        case PlyType::Int16:
        case PlyType::UInt16: return 2;
        case PlyType::Int32:
        case PlyType::UInt32:
        case PlyType::Float32: return 4;
        case PlyType::Float64: return 8;
    }
    return 0;
}

bool is_integer(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

struct Property {
    std::string name;
    PlyType type = PlyType::Float32;
    bool list = false;
    PlyType count_type = PlyType::UInt8;  ///< lists: the type of the count
};

struct Element {
    std::string name;
    long long count = 0;
    int line = 0;  ///< the header line that declares it
    std::vector<Property> properties;
};

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };

/// Reads one value of `type` from the binary body as a double (integers are exact up to 2^53).
class BinaryReader {
public:
    BinaryReader(std::istream& in, bool little_endian) : in_(in), swap_(little_endian != (std::endian::native == std::endian::little)) {}

    /// False at end of file.
    bool read(PlyType type, double& value) {
        unsigned char b[8];
        const size_t n = size_of(type);
        if (!in_.read(reinterpret_cast<char*>(b), static_cast<std::streamsize>(n))) return false;
        if (swap_) std::reverse(b, b + n);
        switch (type) {
            case PlyType::Int8: value = static_cast<int8_t>(b[0]); break;
            case PlyType::UInt8: value = b[0]; break;
            case PlyType::Int16: value = load<int16_t>(b); break;
            case PlyType::UInt16: value = load<uint16_t>(b); break;
            case PlyType::Int32: value = load<int32_t>(b); break;
            case PlyType::UInt32: value = load<uint32_t>(b); break;
            case PlyType::Float32: value = load<float>(b); break;
            case PlyType::Float64: value = load<double>(b); break;
        }
        return true;
    }

private:
    template <class T>
    static T load(const unsigned char* b) {
        T t;
        std::memcpy(&t, b, sizeof t);
        return t;
    }
    std::istream& in_;
    bool swap_;
};

}  // namespace

PolyMesh read_ply(std::istream& in, const std::string& name) {
    io_detail::LineReader r(in, name);
    if (!r.next() || r.token() != "ply") r.fail("expected 'ply' on the first line");
    std::optional<Format> format;
    std::vector<Element> elements;
    for (;;) {
        if (!r.next()) r.fail("unexpected end of file in the PLY header (no end_header)");
        const std::string_view key = r.token();
        if (key.empty() || key == "comment" || key == "obj_info") continue;
        if (key == "end_header") break;
        if (key == "format") {
            const std::string_view f = r.token();
            if (f == "ascii") format = Format::Ascii;
            else if (f == "binary_little_endian") format = Format::BinaryLittleEndian;
            else if (f == "binary_big_endian") format = Format::BinaryBigEndian;
            else r.fail("unknown PLY format '" + std::string(f) + "' (known: ascii, binary_little_endian, binary_big_endian)");
            if (r.token() != "1.0") r.fail("only PLY version 1.0 is known");
        } else if (key == "element") {
            Element e;
            e.name = std::string(r.token());
            e.count = r.integer("element count");
            e.line = r.line_number();
            if (e.name.empty() || e.count < 0) r.fail("expected: element NAME COUNT with COUNT >= 0");
            elements.push_back(std::move(e));
        } else if (key == "property") {
            if (elements.empty()) r.fail("a property before any element");
            Property p;
            std::string_view t = r.token();
            if (t == "list") {
                p.list = true;
                const std::string_view ct = r.token(), it = r.token();
                const auto c = ply_type(ct), i = ply_type(it);
                if (!c || !i || !is_integer(*c) || !is_integer(*i))
                    r.fail("expected: property list COUNT_TYPE INDEX_TYPE NAME with integer types");
                p.count_type = *c;
                p.type = *i;
            } else {
                const auto type = ply_type(t);
                if (!type) r.fail("unknown property type '" + std::string(t) + "'");
                p.type = *type;
            }
            p.name = std::string(r.token());
            if (p.name.empty()) r.fail("a property without a name");
            elements.back().properties.push_back(std::move(p));
        } else {
            r.fail("unknown PLY header keyword '" + std::string(key) + "'");
        }
    }
    if (!format) r.fail("the PLY header has no format line");

    PolyMesh mesh;
    mesh.source.file = name;
    long long nv = -1;
    for (const Element& e : elements)
        if (e.name == "vertex") {
            nv = e.count;
            if (nv > std::numeric_limits<int>::max()) r.fail_at(e.line, "more vertices than 32-bit indices address");
        }
    BinaryReader bin(in, *format == Format::BinaryLittleEndian);
    std::vector<int> corners;
    std::vector<double> values;  // one record's scalars
    for (const Element& e : elements) {
        const bool vertex = e.name == "vertex", face = e.name == "face";
        int xyz[3] = {-1, -1, -1}, indices = -1;
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const Property& p = e.properties[k];
            if (vertex && !p.list) {
                if (p.name == "x") xyz[0] = static_cast<int>(k);
                if (p.name == "y") xyz[1] = static_cast<int>(k);
                if (p.name == "z") xyz[2] = static_cast<int>(k);
            }
            if (face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) indices = static_cast<int>(k);
        }
        if (vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)) r.fail_at(e.line, "the vertex element lacks x, y or z");
        if (face && indices < 0) r.fail_at(e.line, "the face element has no vertex_indices list");
        for (long long i = 0; i < e.count; ++i) {
            const std::string where = e.name + " " + std::to_string(i);
            int line = e.line;
            if (*format == Format::Ascii) {
                do {
                    if (!r.next()) r.fail("unexpected end of file, expecting " + where);
                } while (r.at_end_of_line());
                line = r.line_number();
            }
            auto scalar = [&](PlyType type, const char* what) {
                if (*format == Format::Ascii) return is_integer(type) ? static_cast<double>(r.integer(what)) : r.real(what);
                double x = 0;
                if (!bin.read(type, x)) r.fail_at(e.line, "unexpected end of the binary data in " + where);
                if (!std::isfinite(x))
                    throw NonFiniteNumber(name, e.line, where + ": a " + std::string(what) + " is not finite (binary data)");
                return x;
            };
            values.assign(e.properties.size(), 0.0);
            corners.clear();
            for (size_t k = 0; k < e.properties.size(); ++k) {
                const Property& p = e.properties[k];
                if (!p.list) {
                    values[k] = scalar(p.type, p.name.c_str());
                    continue;
                }
                const double n = scalar(p.count_type, "list count");
                if (n < 0) r.fail_at(line, where + ": negative list count");
                for (long long j = 0; j < static_cast<long long>(n); ++j) {
                    const double v = scalar(p.type, "list entry");
                    if (face && static_cast<int>(k) == indices) {
                        if (v < 0 || v >= static_cast<double>(nv))
                            r.fail_at(line, where + ": vertex index " + std::to_string(static_cast<long long>(v)) +
                                                " out of range [0, " + std::to_string(nv) + ")");
                        corners.push_back(static_cast<int>(v));
                    }
                }
            }
            if (*format == Format::Ascii && !r.at_end_of_line()) r.fail("more values than the header declares for " + where);
            if (vertex) {
                mesh.positions.emplace_back(values[xyz[0]], values[xyz[1]], values[xyz[2]]);
                mesh.source.vertex_line.push_back(line);
            } else if (face) {
                if (corners.size() < 3) r.fail_at(line, where + ": a face needs at least 3 vertices, got " + std::to_string(corners.size()));
                mesh.add_face(corners);
                mesh.source.face_line.push_back(line);
            }
        }
    }
    if (nv < 0) r.fail_at(1, "the PLY file has no vertex element");
    return mesh;
}

void write_ply(std::ostream& out, const PolyMesh& mesh) {
    std::string s = "ply\nformat ascii 1.0\ncomment crossdiv\nelement vertex ";
    io_detail::append_int(s, mesh.num_vertices());
    s += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
    io_detail::append_int(s, mesh.num_faces());
    int largest = 0;
    for (int f = 0; f < mesh.num_faces(); ++f) largest = std::max(largest, mesh.face_size(f));
    // uchar counts are what most readers expect; a face of more corners needs a wider count.
    s += largest <= 255 ? "\nproperty list uchar int vertex_indices\nend_header\n"
                        : "\nproperty list int int vertex_indices\nend_header\n";
    for (const Vec3& p : mesh.positions) {
        io_detail::append_real(s, p.x());
        s += ' ';
        io_detail::append_real(s, p.y());
        s += ' ';
        io_detail::append_real(s, p.z());
        s += '\n';
    }
    for (int f = 0; f < mesh.num_faces(); ++f) {
        io_detail::append_int(s, mesh.face_size(f));
        for (int k = 0; k < mesh.face_size(f); ++k) {
            s += ' ';
            io_detail::append_int(s, mesh.face(f)[k]);
        }
        s += '\n';
    }
    out << s;
}

}  // namespace crossdiv
