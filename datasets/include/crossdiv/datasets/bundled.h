#pragma once
/// @file
/// Small meshes generated in code, each a named topology case for the conformance tests and
/// for `crossdiv compare bundled:NAME`. Deterministic: the same vertices and faces, in the
/// same order, on every machine.

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::datasets {

struct BundledMesh {
    std::string name;
    std::string description;  ///< one line: what topology case it is
    PolyMesh mesh;
};

/// Every bundled mesh: tetrahedron, octahedron, icosahedron, cube-symmetric,
/// cube-asymmetric, open-patch, torus, fan-3 .. fan-12, pole-64.
std::vector<BundledMesh> bundled_meshes();

/// The polygon meshes for the schemes that take any polygon (Catmull-Clark): quad-cube,
/// quad-grid, quad-torus, prism-5, quad-fan-3, quad-fan-5, quad-fan-7. Collection
/// "polygons:all". Not in bundled_meshes(), whose every member is a Loop input.
std::vector<BundledMesh> polygon_meshes();

/// The polygon meshes, then the bundled (triangle) meshes: the catalog the scheme and limit
/// studies run over.
std::vector<BundledMesh> catalog_meshes();

/// The crease-tagged meshes (crease and corner tags as OpenSubdiv's shape files give them):
/// quad meshes for Catmull-Clark, then triangle meshes for Loop and Catmull-Clark alike.
/// Infinitely sharp, semi-sharp and fractional sharpness, varying sharpness along a crease
/// (Chaikin decay), darts, crease lines meeting a border, corner tags. Names start "crease-".
std::vector<BundledMesh> crease_meshes();

/// The cube of the seed's question "what happens to sharp features?".
enum class CreaseCubeVariant {
    Smooth,     ///< no tags
    SharpTop,   ///< the four edges of the top face infinitely sharp
    SemiSharp,  ///< all edges of sharpness 2
    Sharp,      ///< all edges infinitely sharp
};
/// The quad cube [-1, 1]^3 with the variant's tags.
PolyMesh crease_cube(CreaseCubeVariant variant);

/// One bundled or polygon mesh by name. @throws InputError naming the unknown name and listing the known ones.
PolyMesh bundled_mesh(const std::string& name);

/// The CGAL demo meshes unpacked by datasets/install_cgal_meshes.sh (paths to .off files,
/// sorted), or empty when they are not installed.
std::vector<std::string> cgal_mesh_files();

/// OpenSubdiv's regression shapes with hierarchical edits (catmark_square_hedit0..4), written
/// out of Debian's opensubdiv-tools by datasets/install_opensubdiv_shapes.py (paths to .obj
/// files, sorted), or empty when they are not installed.
std::vector<std::string> opensubdiv_shape_files();

/// The course meshes in ../shared/data/c3100/objs when that folder exists, else empty.
std::vector<std::string> course_mesh_files();

/// The meshedit COLLADA meshes in ../shared/data/meshedit/dae (the top level: bean, beetle,
/// cow, cube, peter, quadball, teapot, weird) when that folder exists, else empty. They are read
/// through the Assimp adapter.
std::vector<std::string> meshedit_mesh_files();

}  // namespace crossdiv::datasets
