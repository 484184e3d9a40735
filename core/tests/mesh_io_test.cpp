// OBJ/OFF: order kept, polygons kept, bit-exact round trip, errors with file and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <sstream>

#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/tri_mesh.h"

#include "parse_errors.h"

namespace crossdiv {
namespace {

PolyMesh obj(const std::string& text) {
    std::istringstream in(text);
    return read_obj(in, "t.obj");
}

/// Written back in the same format, every tag reads back equal (their lines aside).
void expect_tags_written_back(const PolyMesh& m) {
    std::ostringstream out;
    write_obj(out, m);
    const CreaseTags back = obj(out.str()).creases;
    EXPECT_EQ(back.edges, m.creases.edges);
    EXPECT_EQ(back.vertices, m.creases.vertices);
    EXPECT_EQ(back.holes, m.creases.holes);
    EXPECT_EQ(back.method, m.creases.method);
    EXPECT_EQ(back.boundary, m.creases.boundary);
    EXPECT_EQ(back.smooth_triangles, m.creases.smooth_triangles);
    EXPECT_EQ(back.face_varying, m.creases.face_varying);
}

std::string obj_error(const std::string& text) {
    try {
        obj(text);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "no error";
}

TEST(MeshIo, ObjKeepsOrderPolygonsAndLines) {
    const PolyMesh m = obj("# comment\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\nf 3 -2 -1\n");
    ASSERT_EQ(m.num_vertices(), 4);
    ASSERT_EQ(m.num_faces(), 2);
    EXPECT_EQ(m.face_size(0), 4);
    EXPECT_EQ(std::vector<int>(m.face(0), m.face(0) + 4), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(std::vector<int>(m.face(1), m.face(1) + 3), (std::vector<int>{2, 2, 3}));  // -2 is vertex 3
    EXPECT_EQ(m.source.face_line, (std::vector<int>{7, 8}));
    EXPECT_EQ(m.source.vertex_line[0], 2);
    EXPECT_TRUE(m.colors.empty());
}

TEST(MeshIo, ObjRoundTripIsBitExact) {
    PolyMesh m;
    m.positions = {Vec3(0.1, 1.0 / 3.0, -2.718281828459045), Vec3(1e-300, 123456789.123456789, M_PI),
                   Vec3(-0.0, 5e-324, 1.7976931348623157e308)};
    m.colors = {Vec3(1, 0, 0), Vec3(0, 0.5, 0), Vec3(0, 0, 0.1)};
    m.add_face({0, 1, 2});
    std::ostringstream out;
    write_obj(out, m);
    const PolyMesh back = obj(out.str());
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.colors, m.colors);
    EXPECT_EQ(back.face_vertices, m.face_vertices);
    EXPECT_NE(out.str().find("v 0.10000000000000001 "), std::string::npos) << "17 significant digits";
}

TEST(MeshIo, OffRoundTripAndColors) {
    PolyMesh m;
    m.positions = {Vec3(0.1, 0.2, 0.3), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 1)};
    m.add_face({0, 1, 2});
    m.add_face({1, 3, 2, 0});
    std::ostringstream out;
    write_off(out, m);
    std::istringstream in(out.str());
    const PolyMesh back = read_off(in, "t.off");
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.face_start, m.face_start);
    EXPECT_EQ(back.face_vertices, m.face_vertices);
    std::istringstream coff("COFF\n# c\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2 255 0 0\n");
    const PolyMesh c = read_off(coff, "c.off");
    EXPECT_EQ(c.colors[1], Vec3(0, 1, 0));
    EXPECT_EQ(c.source.face_line, std::vector<int>{7});
}

TEST(MeshIo, ObjErrorsNameFileAndLine) {
    EXPECT_EQ(obj_error("v 0 0 0\nv 1 0\nf 1 2 1\n"), "t.obj:2: missing z coordinate");
    EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 nan\n"), "t.obj:2: z coordinate is nan; numbers must be finite");
    EXPECT_EQ(obj_error("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 4\n"),
              "t.obj:4: vertex index 4 out of range: the file has 3 vertices");
    EXPECT_EQ(obj_error("v 0 0 0\nf 0 1 1\n"), "t.obj:2: vertex index 0: OBJ indices start at 1");
    EXPECT_EQ(obj_error("v 0 0 zero\n"), "t.obj:1: 'zero' is not a number (z coordinate)");
    EXPECT_EQ(obj_error("v 0 0 0\nf 1 x 1\n"), "t.obj:2: 'x' is not an integer (vertex index)");
}

TEST(MeshIo, ObjIndicesBeyond32BitsAreRefusedWithTheFilesValue) {
    // 4294967299 = 2^32 + 3 would wrap to vertex 3 in an int; 2147483649 to a negative one;
    // 2147483648 = INT_MAX + 1 is the first index an int cannot hold.
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    EXPECT_EQ(obj_error(tri + "f 1 2 4294967299\n"),
              "t.obj:4: vertex index 4294967299 is out of range: 32-bit indices address at most 2147483647 vertices");
    EXPECT_EQ(obj_error(tri + "f 1 2 2147483649\n"),
              "t.obj:4: vertex index 2147483649 is out of range: 32-bit indices address at most 2147483647 vertices");
    EXPECT_EQ(obj_error(tri + "f 1 2 2147483648\n"),
              "t.obj:4: vertex index 2147483648 is out of range: 32-bit indices address at most 2147483647 vertices");
    // INT_MAX itself fits, and is out of this file's range, reported with its value.
    EXPECT_EQ(obj_error(tri + "f 1 2 2147483647\n"),
              "t.obj:4: vertex index 2147483647 out of range: the file has 3 vertices");
    EXPECT_EQ(obj_error(tri + "f 1 2 99999999999999999999\n"),
              "t.obj:4: '99999999999999999999' is out of the range of a 64-bit integer (vertex index)");
    EXPECT_EQ(obj_error(tri + "f 1 2 3\nt crease 2/1/0 0 4294967298 1\n"),
              "t.obj:5: tag vertex index 4294967298 is out of range: 32-bit indices address 0..2147483647");
    EXPECT_EQ(obj_error(tri + "f 1 2 3\nt corner 1/1/0 -1 1\n"),
              "t.obj:5: tag vertex index -1 is out of range: 32-bit indices address 0..2147483647");
}

TEST(MeshIo, ObjSkipsUnknownStatementsWithANote) {
    // The course files are OBJ saved from a browser, wrapped in HTML.
    const PolyMesh m = obj("<html><pre># OBJ\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n</pre></html>\n");
    EXPECT_EQ(m.num_faces(), 1);
    ASSERT_EQ(m.source.notes.size(), 1u);
    EXPECT_EQ(m.source.notes[0], "skipped 2 line(s) with an unknown statement, the first at t.obj:1 ('<html><pre>')");
}

TEST(MeshIo, ObjInUtf16IsRefusedNotReadAsAnEmptyMesh) {
    // "v 0 0 0" in UTF-16 little-endian, with its byte order mark: read as ASCII, every line
    // would be an unknown statement and the file an empty mesh.
    const std::string utf16("\xff\xfev\0 \0" "0\0 \0" "0\0 \0" "0\0\n\0", 18);
    EXPECT_EQ(obj_error(utf16),
              "t.obj:1: a NUL byte: not a text file in ASCII or UTF-8 (UTF-16 or UTF-32 text, or binary data)");
    // An empty file is an empty mesh (a program's empty result); an input refuses it.
    EXPECT_EQ(obj("").num_vertices(), 0);
}

TEST(MeshIo, ObjReadsOpenSubdivCreaseTags) {
    const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    const PolyMesh m = obj(quad + "t crease 2/1/0 0 1 2.5\nt crease 4/2/0 1 2 2 3 1 10\nt corner 2/1/0 0 3 4\n" +
                           "t creasemethod 0/0/1 chaikin\nt interpolateboundary 1/0/0 2\n");
    ASSERT_EQ(m.creases.edges.size(), 3u);
    EXPECT_EQ(m.creases.edges[0], (SharpEdge{0, 1, 2.5f}));
    EXPECT_EQ(m.creases.edges[1], (SharpEdge{1, 2, 1.0f}));  // one value per pair
    EXPECT_EQ(m.creases.edges[2], (SharpEdge{2, 3, 10.0f}));
    EXPECT_EQ(m.creases.edge_line, (std::vector<int>{6, 7, 7}));
    ASSERT_EQ(m.creases.vertices.size(), 2u);
    EXPECT_EQ(m.creases.vertices[1], (SharpVertex{3, 4.0f}));  // one value for all
    EXPECT_EQ(m.creases.method, CreaseMethod::Chaikin);
    EXPECT_EQ(m.creases.boundary, BoundaryTag::EdgeOnly);  // 2 is edge-only in OpenSubdiv's reader
    EXPECT_TRUE(m.source.notes.empty());

    expect_tags_written_back(m);

    EXPECT_EQ(obj_error(quad + "t crease 2/1/0 0 9 1\n"),
              "t.obj:6: tag vertex index 9 out of range: tags count from 0 and the file has 4 vertices");
    EXPECT_EQ(obj_error(quad + "t crease 2/1/0 0 1 -1\n"), "t.obj:6: tag 'crease': sharpness -1.000000 is negative");
    EXPECT_EQ(obj_error(quad + "t crease 2/1/0 0 1 nan\n"), "t.obj:6: tag float argument is nan; numbers must be finite");
    EXPECT_EQ(obj_error(quad + "t crease 3/1/0 0 1 2 1\n"), "t.obj:6: tag 'crease': needs vertex index pairs, got 3 integer(s)");
    EXPECT_EQ(obj_error(quad + "t crease 2/1/0 0 1\n"), "t.obj:6: missing tag float argument");
    EXPECT_EQ(obj_error(quad + "t crease 2/2/0 0 1 1 2\n"),
              "t.obj:6: tag 'crease': 2 sharpness values for 1 item(s); give 1 or 1");
    EXPECT_EQ(obj_error(quad + "t crease 2-1-0 0 1 1\n"),
              "t.obj:6: tag 'crease': expected counts as nint/nfloat/nstring, got '2-1-0'");
    EXPECT_EQ(obj_error(quad + "t creasemethod 0/0/1 smooth\n"),
              "t.obj:6: tag 'creasemethod': expects one string, 'normal' or 'chaikin'");
}

TEST(MeshIo, ObjReadsHoleBoundaryAndTriangleTagsAndKeepsUnknownOnesForTheCaller) {
    const std::string two_quads = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2 5 6 3\n";
    const PolyMesh m = obj(two_quads + "t hole 2/0/0 1 1\nt hole 1/0/0 0\nt interpolateboundary 1/0/0 0\n" +
                           "t smoothtriangles 0/0/1 smooth\nt facevaryingpropagatecorners 1/0/0 1\n" +
                           "t stitch 1/0/0 3\n");
    EXPECT_EQ(m.creases.holes, (std::vector<int>{0, 1}));  // sorted, each once
    EXPECT_FALSE(m.creases.empty());                       // holes need the tagged refinement
    EXPECT_EQ(m.creases.describe(), "0 crease, 0 corner and 2 hole tag(s)");
    EXPECT_EQ(m.creases.boundary, BoundaryTag::None);
    EXPECT_EQ(m.creases.smooth_triangles, true);
    ASSERT_EQ(m.source.notes.size(), 1u);  // the tag OpenSubdiv 3 dropped: read, said to be ignored
    EXPECT_NE(m.source.notes[0].find("'facevaryingpropagatecorners' at t.obj:13 is ignored: OpenSubdiv 3 has no such option"),
              std::string::npos);
    EXPECT_EQ(m.source.unknown_tags, std::vector<std::string>{"'stitch' at t.obj:14"});

    expect_tags_written_back(m);

    EXPECT_EQ(obj_error(two_quads + "t hole 1/0/0 2\n"),
              "t.obj:9: tag face index 2 out of range: tags count from 0 and the file has 2 faces");
    EXPECT_EQ(obj_error(two_quads + "t hole 0/0/0\n"), "t.obj:9: tag 'hole': needs at least one face index");
    EXPECT_EQ(obj_error(two_quads + "t interpolateboundary 1/0/0 3\n"),
              "t.obj:9: tag 'interpolateboundary': expects one integer, 0 (none), 1 (edge-and-corner) or 2 (edge-only)");
    EXPECT_EQ(obj_error(two_quads + "t smoothtriangles 0/0/1 loop\n"),
              "t.obj:9: tag 'smoothtriangles': expects one string, 'smooth' or 'catmark'");
}

TEST(MeshIo, OffErrorsNameFileAndLine) {
    auto off_error = [](const std::string& text) {
        return test::parse_error([](std::istream& in, const std::string& n) { return read_off(in, n); }, text, "t.off");
    };
    EXPECT_EQ(off_error("PLY\n"), "t.off:1: expected 'OFF' or 'COFF' header, got 'PLY'");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"), "t.off:6: vertex index 7 out of range [0, 3)");
    EXPECT_EQ(off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n"), "t.off:4: unexpected end of file, expecting a vertex");
    // Counts beyond 32-bit indices are refused at the header; a count that fits but is not
    // backed by lines fails at the missing line, without allocating for the claim.
    EXPECT_EQ(off_error("OFF\n4611686018427387904 1 0\n"),
              "t.off:2: vertex count 4611686018427387904 is out of range: 32-bit indices address 0..2147483647");
    EXPECT_EQ(off_error("OFF\n2147483648 1 0\n"),
              "t.off:2: vertex count 2147483648 is out of range: 32-bit indices address 0..2147483647");
    EXPECT_EQ(off_error("OFF\n3 -1 0\n"), "t.off:2: face count -1 is out of range: 32-bit indices address 0..2147483647");
    EXPECT_EQ(off_error("OFF\n2147483647 1 0\n0 0 0\n"), "t.off:3: unexpected end of file, expecting a vertex");
}

TEST(MeshIo, QuadGivenToATriangleSchemeNamesTheLine) {
    const PolyMesh m = obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4 2\n");
    try {
        to_tri_mesh(m, "Loop subdivision");
        FAIL() << "quad accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "face 1 (t.obj:6): has 4 corners; Loop subdivision needs triangles (the mesh is not triangulated "
                  "for you)");
    }
}


/// A binary PLY of one quad and one triangle over five float vertices, in the given byte order.
std::string binary_ply(bool little_endian) {
    std::string s = std::string("ply\nformat ") + (little_endian ? "binary_little_endian" : "binary_big_endian") +
                    " 1.0\ncomment made by hand\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                    "property uchar red\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
    auto put = [&](const void* p, size_t n) {
        std::string b(static_cast<const char*>(p), n);
        if (little_endian != (std::endian::native == std::endian::little)) std::reverse(b.begin(), b.end());
        s += b;
    };
    const float coords[5][3] = {{0.1f, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 2, 1.0f / 3}};
    for (const auto& c : coords) {
        for (float x : c) put(&x, 4);
        const unsigned char red = 7;
        put(&red, 1);
    }
    const int quad[4] = {0, 1, 2, 3}, tri[3] = {3, 2, 4};
    unsigned char n = 4;
    put(&n, 1);
    for (int i : quad) put(&i, 4);
    n = 3;
    put(&n, 1);
    for (int i : tri) put(&i, 4);
    return s;
}

TEST(MeshIo, PlyBinaryBothByteOrdersReadFloatsExactly) {
    for (bool little : {true, false}) {
        std::istringstream in(binary_ply(little));
        const PolyMesh m = read_ply(in, "b.ply");
        ASSERT_EQ(m.num_vertices(), 5);
        ASSERT_EQ(m.num_faces(), 2);
        EXPECT_EQ(m.positions[0].x(), static_cast<double>(0.1f));  // the float, not 0.1
        EXPECT_EQ(m.positions[4].z(), static_cast<double>(1.0f / 3));
        EXPECT_EQ(m.face_size(0), 4);
        EXPECT_EQ(m.face(1)[2], 4);
    }
}

TEST(MeshIo, PlyAsciiRoundTripIsBitExact) {
    PolyMesh m;
    m.positions = {Vec3(0.1, 1.0 / 3, -2e-300), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 1)};
    m.add_face({0, 1, 2});
    m.add_face({1, 3, 2});
    std::ostringstream out;
    write_ply(out, m);
    std::istringstream in(out.str());
    const PolyMesh back = read_ply(in, "rt.ply");
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.face_vertices, m.face_vertices);
    EXPECT_EQ(back.source.vertex_line[0], 11);  // after the 10 header lines
}

TEST(MeshIo, PlyErrorsNameFileAndLine) {
    auto error = [](const std::string& text) {
        return test::parse_error([](std::istream& in, const std::string& n) { return read_ply(in, n); }, text, "bad.ply");
    };
    const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    EXPECT_EQ(error(head + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "bad.ply:13: face 0: vertex index 3 out of range [0, 3)");
    EXPECT_EQ(error(head + "0 0 0\n1 0 nan\n"), "bad.ply:11: z is nan; numbers must be finite");
    EXPECT_EQ(error(head + "0 0 0\n"), "bad.ply:10: unexpected end of file, expecting vertex 1");
    EXPECT_EQ(error("ply\nformat ascii 2.0\n"), "bad.ply:2: only PLY version 1.0 is known");
    EXPECT_EQ(error("ply\nformat ascii 1.0\nproperty float x\n"), "bad.ply:3: a property before any element");
    std::string truncated = binary_ply(true);
    truncated.resize(truncated.size() - 3);
    EXPECT_EQ(error(truncated), "bad.ply:9: unexpected end of the binary data in face 1");
}

}  // namespace
}  // namespace crossdiv
