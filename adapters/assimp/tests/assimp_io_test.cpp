// Reading COLLADA, PLY and STL through Assimp: shared vertices recovered, polygons kept,
// bad files named.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "crossdiv/adapters/assimp.h"
#include "crossdiv/error.h"

namespace crossdiv::adapters::assimp {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("crossdiv_assimp_" + name);
    std::ofstream(path) << text;
    return path.string();
}

// A unit square as one triangle and one quad... as COLLADA writes it: positions shared by
// index, each corner with its own normal index (so Assimp gives each corner its own vertex).
const char* kSquareDae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="g" name="g"><mesh>
      <source id="g-pos"><float_array id="g-pos-a" count="15">0 0 0  1 0 0  1 1 0  0 1 0  2 0.5 0</float_array>
        <technique_common><accessor source="#g-pos-a" count="5" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <source id="g-nrm"><float_array id="g-nrm-a" count="6">0 0 1  0 0 -1</float_array>
        <technique_common><accessor source="#g-nrm-a" count="2" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="g-vtx"><input semantic="POSITION" source="#g-pos"/></vertices>
      <polylist count="2">
        <input semantic="VERTEX" source="#g-vtx" offset="0"/>
        <input semantic="NORMAL" source="#g-nrm" offset="1"/>
        <vcount>4 3</vcount>
        <p>0 0 1 0 2 1 3 0  1 1 4 0 2 0</p>
      </polylist>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="s">
    <node id="n"><instance_geometry url="#g"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";

TEST(Assimp, ColladaCornersAreWeldedIntoSharedVertices) {
    const PolyMesh m = read_mesh(write_temp("square.dae", kSquareDae));
    ASSERT_EQ(m.num_faces(), 2);
    EXPECT_EQ(m.face_size(0), 4);  // the quad stays a quad
    EXPECT_EQ(m.face_size(1), 3);
    ASSERT_EQ(m.num_vertices(), 5);  // 7 corners, 5 positions
    // Numbered by first use: the quad's corners 0 1 2 3, then the triangle's new corner 4.
    EXPECT_EQ(std::vector<int>(m.face(0), m.face(0) + 4), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_EQ(std::vector<int>(m.face(1), m.face(1) + 3), (std::vector<int>{1, 4, 2}));
    EXPECT_EQ(m.positions[4], Vec3(2, 0.5, 0));
    EXPECT_NE(m.source.notes.at(0).find("7 face corners welded into 5 vertices"), std::string::npos) << m.source.notes[0];
}

TEST(Assimp, AsciiStlAndPly) {
    const std::string stl = write_temp("two.stl", R"(solid two
facet normal 0 0 1
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 1 1 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex 0 0 0
  vertex 1 1 0
  vertex 0 1 0
 endloop
endfacet
endsolid two
)");
    const PolyMesh s = read_mesh(stl);
    EXPECT_EQ(s.num_faces(), 2);
    EXPECT_EQ(s.num_vertices(), 4);  // STL repeats every corner; the diagonal is shared again
    const std::string ply = write_temp("tri.ply", R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
1 1 0
0 1 0
3 0 1 2
3 0 2 3
)");
    const PolyMesh p = read_mesh(ply);
    EXPECT_EQ(p.num_faces(), 2);
    EXPECT_EQ(p.num_vertices(), 4);
    EXPECT_EQ(p.positions[2], Vec3(1, 1, 0));
}

// Every format Assimp lists is read through it, but the three core reads itself.
TEST(Assimp, ReadsEveryFormatItListsButCoresOwn) {
    const std::vector<std::string>& ext = extensions();
    for (const char* e : {".dae", ".stl", ".ac", ".lwo", ".fbx", ".gltf", ".glb", ".3ds", ".blend", ".x", ".ase", ".amf"})
        EXPECT_NE(std::find(ext.begin(), ext.end(), e), ext.end()) << e;
    for (const char* e : {".obj", ".off", ".ply"}) EXPECT_EQ(std::find(ext.begin(), ext.end(), e), ext.end()) << e;
    EXPECT_TRUE(std::is_sorted(ext.begin(), ext.end()));
}

// An AC3D file of two objects, a quad and a triangle beside it, each with its own vertex list:
// the scene's objects become one mesh, welded where their positions are bit-identical.
const char* kTwoObjectsAc = R"(AC3Db
MATERIAL "" rgb 1 1 1  amb 0.2 0.2 0.2  emis 0 0 0  spec 0.5 0.5 0.5  shi 10  trans 0
OBJECT world
kids 2
OBJECT poly
name "quad"
numvert 4
0 0 0
1 0 0
1 1 0
0 1 0
numsurf 1
SURF 0x10
mat 0
refs 4
0 0 0
1 0 0
2 0 0
3 0 0
kids 0
OBJECT poly
name "triangle"
numvert 3
1 0 0
2 0.5 0
1 1 0
numsurf 1
SURF 0x10
mat 0
refs 3
0 0 0
1 0 0
2 0 0
kids 0
)";

TEST(Assimp, TheObjectsOfAnAc3dFileAreWeldedByPosition) {
    const PolyMesh m = read_mesh(write_temp("two.ac", kTwoObjectsAc));
    ASSERT_EQ(m.num_faces(), 2);
    EXPECT_EQ(m.face_size(0) + m.face_size(1), 7);  // a quad and a triangle, as written
    ASSERT_EQ(m.num_vertices(), 5);                  // 7 vertices written, 2 of them twice
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(2, 0.5, 0)})
        EXPECT_NE(std::find(m.positions.begin(), m.positions.end(), p), m.positions.end()) << p.transpose();
}

TEST(Assimp, UnreadableFileNamesTheFile) {
    const std::string bad = write_temp("broken.dae", "<COLLADA><library_geometries><geometry>");
    try {
        read_mesh(bad);
        ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("broken.dae"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_mesh("/nonexistent/file.ply"), InputError);
}

}  // namespace
}  // namespace crossdiv::adapters::assimp

namespace crossdiv::adapters::assimp {
namespace {

TEST(AssimpIo, TextureCoordinatesBecomeAChannelWithItsSeams) {
    // Two quads sharing the edge 2-5 with a seam on it: the left quad has u = 1 there, the
    // right one u = 3. Read by Assimp (which keeps a value per corner), the channel has one
    // value per vertex and side of the seam: 8 values, the seam's two vertices with two each.
    const std::string obj = write_temp("seam.obj",
                                       "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 3 0\nvt 4 0\nvt 4 1\nvt 3 1\n"
                                       "f 1/1 2/2 5/3 4/4\nf 2/5 3/6 6/7 5/8\n");
    const PolyMesh m = read_mesh(obj);
    ASSERT_EQ(m.face_varying.size(), 1u);
    const FaceVaryingChannel& uv = m.face_varying[0];
    EXPECT_EQ(uv.num_values(), 8);
    ASSERT_EQ(uv.corner_values.size(), 8u);
    // Each corner's value is its file's: compare by vertex position within each face.
    for (int f = 0; f < 2; ++f)
        for (int k = 0; k < 4; ++k) {
            const Vec3& p = m.positions[m.face(f)[k]];
            const double* t = uv.value(uv.corner_values[static_cast<size_t>(4 * f + k)]);
            EXPECT_EQ(t[0], f == 0 ? p.x() : p.x() + 2) << "face " << f << " corner " << k;
            EXPECT_EQ(t[1], p.y());
        }
    // The seam: the shared vertices have different values in the two faces.
    int seam_corners = 0;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            if (m.face(0)[k] == m.face(1)[j]) {
                EXPECT_NE(uv.corner_values[static_cast<size_t>(k)], uv.corner_values[static_cast<size_t>(4 + j)]);
                ++seam_corners;
            }
    EXPECT_EQ(seam_corners, 2);
    std::filesystem::remove(obj);
}

}  // namespace
}  // namespace crossdiv::adapters::assimp
