// Invariance testing (comparisons/invariance.h): the transformations by hand on tiny inputs,
// core invariant under every one, and planted subjects -- one wrong only where an
// extraordinary vertex is a particular corner of its first face, one whose output depends on
// vertex order through its summation order alone -- told apart.

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "library_guard.h"

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/disjoint_union.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/bilinear.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/verification/comparisons/input_transformation.h"
#include "crossdiv/verification/comparisons/invariance.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/harness/coincident_vertices.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/harness/tolerances.h"
#include "crossdiv/verification/suite/invariance_case.h"
#include "crossdiv/verification/suite/manifest.h"
#include "crossdiv/verification/suite/operations.h"
#include "crossdiv/verification/suite/runner.h"

#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace crossdiv::verification {
namespace {

/// A quad (0 1 2 3) and a triangle (1 4 2), edge (1, 2) tagged sharp, the quad a hole, a
/// channel with a value per corner.
PolyMesh tagged_pair() {
    PolyMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}};
    m.add_face({0, 1, 2, 3});
    m.add_face({1, 4, 2});
    m.creases.edges = {{1, 2, 2.0f}};
    m.creases.vertices = {{4, 1.0f}};
    m.creases.holes = {0};
    FaceVaryingChannel uv;
    uv.name = "uv";
    uv.dimension = 2;
    for (int c = 0; c < 7; ++c) {
        uv.values.insert(uv.values.end(), {static_cast<double>(c), 0.0});
        uv.corner_values.push_back(c);
    }
    m.face_varying.push_back(uv);
    return m;
}

std::vector<int> face(const PolyMesh& m, int f) { return {m.face(f), m.face(f) + m.face_size(f)}; }

TEST(InputTransformation, EachOneByHand) {
    const PolyMesh m = tagged_pair();
    // Every face starts at its next corner; its channel corners follow.
    const TransformedInput rot = transform_input(m, InputTransformation::RotateCorners, 1);
    EXPECT_EQ(face(rot.mesh, 0), (std::vector<int>{1, 2, 3, 0}));
    EXPECT_EQ(face(rot.mesh, 1), (std::vector<int>{4, 2, 1}));
    EXPECT_EQ(rot.mesh.face_varying[0].corner_values, (std::vector<int>{1, 2, 3, 0, 5, 6, 4}));
    EXPECT_FALSE(rot.exact);
    // The faces reversed: the hole tag follows its face.
    const TransformedInput rev = transform_input(m, InputTransformation::ReverseFaces, 1);
    EXPECT_EQ(face(rev.mesh, 0), (std::vector<int>{1, 4, 2}));
    EXPECT_EQ(rev.mesh.creases.holes, (std::vector<int>{1}));
    EXPECT_EQ(rev.mesh.face_varying[0].corner_values, (std::vector<int>{4, 5, 6, 0, 1, 2, 3}));
    // Rotated by half: of two faces, the second first (as reversed, here).
    EXPECT_EQ(face(transform_input(m, InputTransformation::RotateFaces, 1).mesh, 0), (std::vector<int>{1, 4, 2}));
    // Orientation: the first corner stays, the rest in the other order.
    const TransformedInput ori = transform_input(m, InputTransformation::ReverseOrientation, 1);
    EXPECT_EQ(face(ori.mesh, 0), (std::vector<int>{0, 3, 2, 1}));
    EXPECT_EQ(face(ori.mesh, 1), (std::vector<int>{1, 2, 4}));
    EXPECT_TRUE(ori.reversed);
    // Relabelled: a permutation, with the positions and the crease and corner tags moved alike.
    const TransformedInput rel = transform_input(m, InputTransformation::RelabelVertices, 7);
    std::vector<int> image(5, -1);
    for (int v = 0; v < 5; ++v)
        for (int w = 0; w < 5; ++w)
            if (rel.mesh.positions[static_cast<size_t>(w)] == m.positions[static_cast<size_t>(v)]) image[static_cast<size_t>(v)] = w;
    for (int x : image) EXPECT_GE(x, 0);
    EXPECT_EQ(face(rel.mesh, 1), (std::vector<int>{image[1], image[4], image[2]}));
    EXPECT_EQ(rel.mesh.creases.edges[0].a, image[1]);
    EXPECT_EQ(rel.mesh.creases.edges[0].b, image[2]);
    EXPECT_EQ(rel.mesh.creases.vertices[0].v, image[4]);
    // The same seed, the same permutation; another seed, (here) another.
    EXPECT_EQ(transform_input(m, InputTransformation::RelabelVertices, 7).mesh.face_vertices, rel.mesh.face_vertices);
    // Translate: the box's largest side (2) is a power of two already: every coordinate + 2.
    const TransformedInput tr = transform_input(m, InputTransformation::Translate, 1);
    EXPECT_EQ(tr.mesh.positions[4], Vec3(4, 2.5, 2));
    EXPECT_FALSE(tr.exact);
    // Scale, swap and mirror are exact in floating point.
    EXPECT_EQ(transform_input(m, InputTransformation::Scale, 1).mesh.positions[4], Vec3(4, 1, 0));
    EXPECT_EQ(transform_input(m, InputTransformation::SwapAxes, 1).mesh.positions[4], Vec3(0.5, 2, 0));
    EXPECT_EQ(transform_input(m, InputTransformation::Mirror, 1).mesh.positions[4], Vec3(-2, 0.5, 0));
    EXPECT_TRUE(transform_input(m, InputTransformation::Mirror, 1).exact);
    // Names.
    for (InputTransformation t : kInputTransformations) EXPECT_EQ(input_transformation_from_string(to_string(t)), t);
    EXPECT_THROW(input_transformation_from_string("spin-faces"), InputError);
}

TEST(InputTransformation, ComponentsByHand) {
    // Faces 0 and 2 share vertex 2 (a bowtie: one component), face 1 stands apart, vertex 8 no
    // face uses; the tags and the texture coordinates go with their parts.
    PolyMesh m;
    for (int v = 0; v < 9; ++v) m.positions.push_back(Vec3(v, v * v, 0));
    m.add_face({0, 1, 2});
    m.add_face({3, 4, 5});
    m.add_face({2, 6, 7});
    m.creases.edges = {{4, 5, 1.5f}};
    m.creases.vertices = {{6, 2.0f}};
    m.creases.holes = {2};
    FaceVaryingChannel uv;
    uv.dimension = 1;
    for (int c = 0; c < 9; ++c) {
        uv.values.push_back(10 + c);
        uv.corner_values.push_back(c);
    }
    m.face_varying.push_back(uv);
    const std::vector<PolyMesh> parts = connected_components(m);
    ASSERT_EQ(parts.size(), 2u);
    // The first: faces 0 and 2 over vertices 0 1 2 6 7 and the unused 8, in input order.
    EXPECT_EQ(parts[0].positions, (std::vector<Vec3>{m.positions[0], m.positions[1], m.positions[2], m.positions[6],
                                                     m.positions[7], m.positions[8]}));
    EXPECT_EQ(parts[0].face_vertices, (std::vector<int>{0, 1, 2, 2, 3, 4}));
    EXPECT_EQ(parts[0].creases.holes, (std::vector<int>{1}));
    ASSERT_EQ(parts[0].creases.vertices.size(), 1u);
    EXPECT_EQ(parts[0].creases.vertices[0].v, 3);
    EXPECT_TRUE(parts[0].creases.edges.empty());
    // The texture coordinates its corners use, renumbered in order.
    EXPECT_EQ(parts[0].face_varying[0].corner_values, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(parts[0].face_varying[0].values, (std::vector<double>{10, 11, 12, 16, 17, 18}));
    // The second: face 1 alone, its crease renumbered.
    EXPECT_EQ(parts[1].face_vertices, (std::vector<int>{0, 1, 2}));
    ASSERT_EQ(parts[1].creases.edges.size(), 1u);
    EXPECT_EQ(parts[1].creases.edges[0].a, 1);
    EXPECT_EQ(parts[1].creases.edges[0].b, 2);
    EXPECT_EQ(parts[1].face_varying[0].corner_values, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(parts[1].face_varying[0].values, (std::vector<double>{13, 14, 15}));
    // A connected mesh is its own only part; components and level-by-level leave the input as it is.
    EXPECT_EQ(connected_components(datasets::bundled_mesh("icosahedron")).size(), 1u);
    for (InputTransformation t : {InputTransformation::SplitComponents, InputTransformation::LevelByLevel}) {
        EXPECT_TRUE(runs_otherwise(t));
        EXPECT_EQ(transform_input(m, t, 1).mesh.face_vertices, m.face_vertices);
        EXPECT_FALSE(transform_input(m, t, 1).exact);
    }
}

/// `a` and `b` side by side, `b` moved along x past `a`'s box: a mesh of two components.
PolyMesh beside(const PolyMesh& a, PolyMesh b) {
    double right = -INFINITY;
    for (const Vec3& p : a.positions) right = std::max(right, p.x());
    for (Vec3& p : b.positions) p += Vec3(right + 4, 0, 0);
    return disjoint_union({a, b});
}

/// Each transformation's check of `impl` on `mesh`.
InvarianceReport checked(const Implementation& impl, const PolyMesh& mesh, Scheme scheme, int levels) {
    RefineRequest r{scheme, {}, levels};
    if (scheme == Scheme::Loop) r.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    return check_invariance(impl, mesh, r, {kInputTransformations.begin(), kInputTransformations.end()}, 1, 1e-12, 60, false);
}

const InvarianceCheck& check_of(const InvarianceReport& r, InputTransformation t) {
    return *std::find_if(r.checks.begin(), r.checks.end(), [&](const InvarianceCheck& c) { return c.transformation == t; });
}

// Which vertices positions cannot tell apart, counted by hand: the bound is included, a pair
// across a cell border or a cell corner is found, and far from the origin (where the cell
// numbers pass 2^53) only the distance decides.
TEST(CoincidentVertices, WithinTheDistanceIncludedAcrossCellsAndFarFromTheOrigin) {
    EXPECT_FALSE(has_vertices_within(std::vector<Vec3>{}, 0.1));
    EXPECT_FALSE(has_vertices_within(std::vector<Vec3>{{0, 0, 0}}, 0.1));
    EXPECT_FALSE(has_vertices_within(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}, 0.0));
    EXPECT_TRUE(has_vertices_within(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}, 0.0));  // one position
    EXPECT_TRUE(has_vertices_within(std::vector<Vec3>{{0, 0, 0}, {0.25, 0, 0}}, 0.25));        // the bound itself
    EXPECT_FALSE(has_vertices_within(std::vector<Vec3>{{0, 0, 0}, {0.25, 0, 1e-3}}, 0.25));    // just beyond it
    EXPECT_TRUE(has_vertices_within(std::vector<Vec3>{{0.099, 0, 0}, {0.101, 0, 0}}, 0.01));   // two cells in x
    // Neighbours through a cell corner: 2e-4 apart in each axis, sqrt(3) 2e-4 = 3.5e-4 <= 1e-3.
    EXPECT_TRUE(has_vertices_within(std::vector<Vec3>{{0.0999, 0.0999, 0.0999}, {0.1001, 0.1001, 0.1001}}, 1e-3));
    EXPECT_FALSE(has_vertices_within(std::vector<Vec3>{{0, 0, 0}, {0, 2, 0}, {0, 0, 3}}, 1.5));
    // At 1e17 neighbouring doubles are 16 apart and the cell numbers (near 1e23) are not exact:
    // only the distance decides, 16 > 1e-6 is not near and 16 <= 16 is.
    EXPECT_FALSE(has_vertices_within(std::vector<Vec3>{{1e17, 0, 0}, {1e17 + 16, 0, 0}}, 1e-6));
    EXPECT_TRUE(has_vertices_within(std::vector<Vec3>{{1e17, 0, 0}, {1e17 + 16, 0, 0}}, 16.0));
    // Rounded to float: at 1e8 a float's step is 8, so 1e8 and 1e8 + 1 are one float; at 1 they differ.
    EXPECT_EQ(vertices_float_cannot_tell_apart(std::vector<Vec3>{{1e8, 0, 0}, {1e8 + 1, 0, 0}, {1e8 + 16, 0, 0}}), 2u);
    EXPECT_EQ(vertices_float_cannot_tell_apart(std::vector<Vec3>{{1, 0, 0}, {1 + 1e-6, 0, 0}}), 0u);
}

TEST(Invariance, CoreIsInvariantUnderEveryTransformation) {
    const PolyMesh two = beside(datasets::bundled_mesh("icosahedron"), datasets::bundled_mesh("open-patch"));
    for (const auto& [name, mesh] : {std::pair{"icosahedron", datasets::bundled_mesh("icosahedron")},
                                     std::pair{"open-patch", datasets::bundled_mesh("open-patch")},
                                     std::pair{"octahedron", datasets::bundled_mesh("octahedron")},
                                     std::pair{"icosahedron beside open-patch", two}}) {
        const InvarianceReport r = checked(core_implementation(), mesh, Scheme::Loop, 2);
        ASSERT_EQ(r.checks.size(), kInputTransformations.size());
        for (const InvarianceCheck& c : r.checks) {
            // A connected mesh has no parts to refine apart.
            const bool one_part = c.transformation == InputTransformation::SplitComponents && mesh.num_vertices() != two.num_vertices();
            EXPECT_EQ(c.result, one_part ? InvarianceResult::NotCompared : InvarianceResult::Invariant)
                << name << " " << to_string(c.transformation) << ": " << c.explanation;
        }
        // Exact transformations are bit for bit.
        EXPECT_TRUE(check_of(r, InputTransformation::Scale).bit_identical) << name;
        EXPECT_TRUE(check_of(r, InputTransformation::Repeat).bit_identical) << name;
    }
    const InvarianceReport cc = checked(core_implementation(), beside(datasets::bundled_mesh("quad-cube"), datasets::bundled_mesh("quad-cube")),
                                        Scheme::CatmullClark, 2);
    for (const InvarianceCheck& c : cc.checks)
        EXPECT_EQ(c.result, InvarianceResult::Invariant) << "two quad-cubes " << to_string(c.transformation) << ": " << c.explanation;
}

TEST(Invariance, LevelByLevelIsComparedWhereTheRuleComposes) {
    const auto level_by_level = [](const PolyMesh& mesh, RefineRequest request) {
        return check_invariance(core_implementation(), mesh, request, {InputTransformation::LevelByLevel}, 1, 1e-12, 60, false).checks.at(0);
    };
    const PolyMesh icosahedron = datasets::bundled_mesh("icosahedron");
    const PolyMesh patch = datasets::bundled_mesh("open-patch");
    // One level has nothing to run level by level; a tagged mesh's levels lose their tags.
    const InvarianceCheck one = level_by_level(icosahedron, {Scheme::Loop, {}, 1});
    EXPECT_EQ(one.result, InvarianceResult::NotCompared);
    EXPECT_EQ(one.explanation, "one level: nothing to run level by level");
    PolyMesh tagged = icosahedron;
    tagged.creases.edges = {{icosahedron.face(0)[0], icosahedron.face(0)[1], 2.0f}};
    const InvarianceCheck tags = level_by_level(tagged, {Scheme::Loop, {}, 2});
    EXPECT_EQ(tags.result, InvarianceResult::NotCompared);
    EXPECT_NE(tags.explanation.find("1 crease and 0 corner tag(s)"), std::string::npos) << tags.explanation;
    // Two triangles back to back: level 1 holds each face's interior edges twice over on the
    // same vertex pairs, which a face list read back makes one edge; a face naming a vertex twice
    // has the two halves of its degenerate edge. Neither can be written out as faces.
    const InvarianceCheck pillow = level_by_level(datasets::edge_case("valence-2").mesh, {Scheme::Loop, {}, 2});
    EXPECT_EQ(pillow.result, InvarianceResult::NotCompared);
    EXPECT_NE(pillow.explanation.find("level 1's result has 3 edges that more than two faces share"), std::string::npos)
        << pillow.explanation;
    const InvarianceCheck repeated = level_by_level(datasets::edge_case("repeated-vertex-triangle").mesh, {Scheme::Loop, {}, 2});
    EXPECT_EQ(repeated.result, InvarianceResult::NotCompared);
    EXPECT_NE(repeated.explanation.find("repeated vertex 0"), std::string::npos) << repeated.explanation;
    // A bowtie's children are bowties again: compared, and core composes.
    EXPECT_EQ(level_by_level(datasets::edge_case("bowtie").mesh, {Scheme::Loop, {}, 2}).result, InvarianceResult::Invariant);
    // Shrunk from a Sweet Home 3D cupboard: an edge of four faces, two faces traversing an edge
    // the same way, a bowtie. OpenSubdiv's rules pass the non-manifold tags of level 0 to level
    // 1's children, which its faces, read afresh, tag otherwise (PolyMesh::derived keeps them).
    // Core's level 1, returned from an isolated run, keeps them too, and level 2 run on it is
    // level 2 of one run; as faces alone it would be another surface (measured below), which is
    // what the isolated run returned before the tags crossed the process boundary.
    PolyMesh cupboard;
    cupboard.positions = {
        Vec3(38.611637, -41.148674, -18.515646), Vec3(54.601063, -41.148674, -18.515648), Vec3(56.983940, -41.148674, -18.515646),
        Vec3(54.601063, -38.771088, -18.515648), Vec3(54.601063, -12.346336, -18.515650), Vec3(38.611637, -41.148674, -29.831118),
        Vec3(54.601063, -41.148674, -29.831120), Vec3(56.983940, -41.148674, -29.831118), Vec3(38.611641, 16.138680, -29.831121),
        Vec3(54.599277, 16.138680, -29.831121), Vec3(38.611641, 14.553028, -29.831121), Vec3(54.601196, 14.553028, -29.831121),
        Vec3(56.983940, -12.346336, -29.831116), Vec3(54.601063, -10.286072, -29.831121), Vec3(38.611637, -12.346336, -29.831116),
        Vec3(38.611641, -10.286072, -29.831121), Vec3(54.601063, -12.346336, -29.831121), Vec3(38.611637, -38.771088, -29.831118),
        Vec3(54.601063, -38.771088, -29.831121)};
    cupboard.add_face({4, 16, 6, 1});
    cupboard.add_face({0, 5, 6, 1});
    cupboard.add_face({12, 7, 6, 16});
    cupboard.add_face({1, 6, 7, 2});
    cupboard.add_face({1, 3, 18, 6});
    cupboard.add_face({9, 11, 13, 16, 18, 6, 5, 17, 14, 15, 10, 8});
    for (const bool isolate : {false, true}) {
        const InvarianceCheck inherited = check_invariance(core_implementation(), cupboard, {Scheme::CatmullClark, {}, 2},
                                                           {InputTransformation::LevelByLevel}, 1, 1e-12, 60, isolate)
                                              .checks.at(0);
        EXPECT_EQ(inherited.result, InvarianceResult::Invariant) << isolate << ": " << inherited.explanation;
    }
    {
        // The reason measured: level 2 from level 1 with its tags, and from its faces alone.
        const CatmullClarkOptions cc{CatmullClarkBoundary::EdgeOnly};
        const PolyMesh two = catmull_clark_subdivide_nonmanifold(cupboard, cc, 2);
        PolyMesh faces_only = catmull_clark_subdivide_nonmanifold(cupboard, cc, 1);
        faces_only.derived = {};
        const PolyMesh afresh = catmull_clark_subdivide_nonmanifold(faces_only, cc, 1);
        ASSERT_EQ(two.num_vertices(), afresh.num_vertices());
        EXPECT_GT((two.positions[39] - afresh.positions[39]).norm(), 1e-3 * bounding_box_diagonal(two.positions));
    }
    // sqrt3 counted from the input trisects its boundary every second level: compared on a
    // closed mesh, not on one with a boundary; restarted each level, compared on both.
    RefineRequest sqrt3{Scheme::Sqrt3, {}, 2};
    sqrt3.rule.sqrt3.parity = Sqrt3Parity::CountFromInput;
    EXPECT_EQ(level_by_level(icosahedron, sqrt3).result, InvarianceResult::Invariant);
    const InvarianceCheck bounded = level_by_level(patch, sqrt3);
    EXPECT_EQ(bounded.result, InvarianceResult::NotCompared);
    EXPECT_NE(bounded.explanation.find("every second level"), std::string::npos) << bounded.explanation;
    sqrt3.rule.sqrt3.parity = Sqrt3Parity::RestartEachLevel;
    EXPECT_EQ(level_by_level(patch, sqrt3).result, InvarianceResult::Invariant);
    // Every scheme composes, on a mesh with a boundary: core's levels one at a time are its
    // levels in one run, within the strict tier (its multi-level Loop sums the last level in
    // another order: 4e-17 of the diagonal apart).
    for (Scheme scheme : all_schemes()) {
        RefineRequest request{scheme, {}, 3};
        request.rule.sqrt3.parity = Sqrt3Parity::RestartEachLevel;
        const InvarianceCheck c = level_by_level(traits(scheme).triangles ? patch : datasets::bundled_mesh("quad-cube"), request);
        EXPECT_EQ(c.result, InvarianceResult::Invariant) << to_string(scheme) << ": " << c.explanation;
        EXPECT_LE(c.max_rel, 1e-15) << to_string(scheme) << ": " << c.explanation;
    }
}

TEST(Invariance, ASubjectThatSmoothsOnceAfterSplittingIsNotInvariantLevelByLevel) {
    // Catmull-Clark done as n - 1 bilinear splits and one smoothing step: right for one level
    // (and so run one level at a time), wrong for two.
    const std::unique_ptr<Implementation> once =
        make_callback_implementation("smooth-once", {Scheme::CatmullClark}, [](const PolyMesh& m, const RefineRequest& r) {
            RefineRequest last = r;
            last.levels = 1;
            return core_implementation().refine(bilinear_subdivide(m, r.levels - 1), last).back();
        });
    const PolyMesh cube = datasets::bundled_mesh("quad-cube");
    const InvarianceCheck c =
        check_invariance(*once, cube, {Scheme::CatmullClark, {}, 2}, {InputTransformation::LevelByLevel}, 1, 1e-12, 60, false).checks.at(0);
    EXPECT_EQ(c.result, InvarianceResult::NotInvariant) << c.explanation;
    EXPECT_TRUE(c.faces_equal);  // the same faces, other positions
    EXPECT_GT(c.max_rel, 1e-3);
    EXPECT_EQ(c.worst_valence, 3);  // a cube corner
    // The same subject passes every transformation that writes the input otherwise.
    const InvarianceCheck rot =
        check_invariance(*once, cube, {Scheme::CatmullClark, {}, 2}, {InputTransformation::RotateCorners}, 1, 1e-12, 60, false).checks.at(0);
    EXPECT_EQ(rot.result, InvarianceResult::Invariant) << rot.explanation;
}

TEST(Invariance, ASubjectThatKeepsTheWholesSizeIsNotInvariantOverComponents) {
    // Loop, then the result scaled about its centroid back to the input's bounding-box
    // diagonal (a "keep the size" option): a property of the whole mesh, so the parts refined
    // apart are scaled otherwise. Every map and order leaves it alone.
    const std::unique_ptr<Implementation> sized =
        make_callback_implementation("keep-size", {Scheme::Loop}, [](const PolyMesh& m, const RefineRequest& r) {
            PolyMesh out = core_implementation().refine(m, r).back();
            Vec3 centroid = Vec3::Zero();
            for (const Vec3& p : out.positions) centroid += p / out.num_vertices();
            const double ratio = bounding_box_diagonal(m.positions) / bounding_box_diagonal(out.positions);
            for (Vec3& p : out.positions) p = centroid + ratio * (p - centroid);
            return out;
        });
    const PolyMesh two = beside(datasets::bundled_mesh("icosahedron"), datasets::bundled_mesh("open-patch"));
    const std::vector<InvarianceCheck> checks =
        check_invariance(*sized, two, {Scheme::Loop, {}, 1},
                         {InputTransformation::SplitComponents, InputTransformation::RotateCorners, InputTransformation::Scale},
                         1, 1e-12, 60, false).checks;
    EXPECT_EQ(checks.at(0).result, InvarianceResult::NotInvariant) << checks[0].explanation;
    EXPECT_GT(checks[0].max_rel, 1e-3) << checks[0].explanation;  // too far to match: the point sets' distance
    EXPECT_EQ(checks.at(1).result, InvarianceResult::Invariant) << checks[1].explanation;
    EXPECT_EQ(checks.at(2).result, InvarianceResult::Invariant) << checks[2].explanation;
    // Its finding shrinks to a face of each component: the fewest that still make two parts.
    const InvarianceShrink s =
        shrink_not_invariant(*sized, two, {Scheme::Loop, {}, 1}, InputTransformation::SplitComponents, 1, 1e-12, 60, false);
    EXPECT_EQ(s.minimal.num_faces(), 2);
    EXPECT_EQ(connected_components(s.minimal).size(), 2u);
}

TEST(Invariance, TextureCoordinatesAreCheckedToo) {
    // Core refines the UV junction's channel as invariantly as its positions; a subject whose
    // texture coordinates depend on the first face's first corner is caught by them alone.
    RefineRequest request{Scheme::CatmullClark, {}, 2, FaceVaryingRule::None};
    const PolyMesh mesh = datasets::edge_case("uv-junction").mesh;
    const InvarianceReport core = check_invariance(core_implementation(), mesh, request,
                                                   {kInputTransformations.begin(), kInputTransformations.end()}, 1, 1e-12, 60, false);
    for (const InvarianceCheck& c : core.checks) {
        if (c.transformation == InputTransformation::SplitComponents) continue;  // one component: below
        EXPECT_EQ(c.result, InvarianceResult::Invariant) << to_string(c.transformation) << ": " << c.explanation;
        EXPECT_LE(c.uv_max_rel, 1e-12) << to_string(c.transformation);
    }
    // Two copies refined apart: their channels, concatenated, are the channel of the whole.
    const InvarianceCheck apart = check_invariance(core_implementation(), beside(mesh, mesh), request,
                                                   {InputTransformation::SplitComponents}, 1, 1e-12, 60, false).checks.at(0);
    EXPECT_EQ(apart.result, InvarianceResult::Invariant) << apart.explanation;
    EXPECT_LE(apart.uv_max_rel, 1e-12) << apart.explanation;
    const std::unique_ptr<Implementation> shifty =
        make_callback_implementation("uv-shift", {Scheme::CatmullClark}, [](const PolyMesh& m, const RefineRequest& r) {
            PolyMesh out = core_implementation().refine(m, r).back();
            const double shift = 1e-3 * m.face_vertices[0];  // read off how the input is written
            for (double& x : out.face_varying[0].values) x += shift;
            return out;
        });
    const InvarianceReport r = check_invariance(*shifty, mesh, request, {InputTransformation::RotateCorners}, 1, 1e-12, 60, false);
    ASSERT_EQ(r.checks.size(), 1u);
    EXPECT_EQ(r.checks[0].result, InvarianceResult::NotInvariant) << r.checks[0].explanation;
    EXPECT_LE(r.checks[0].max_rel, 1e-12);  // the positions agree: the texture coordinates alone show it
    EXPECT_NE(r.checks[0].explanation.find("texture coordinates"), std::string::npos) << r.checks[0].explanation;
}

TEST(Invariance, FarsUvBowtieDependsOnTheFaceListRotatedByHalf) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv");
    // The comparison's face-order-dependence, found with no reference: under `none`, Far splits
    // one of the bowtie's two values, which one depending on the face that comes first.
    RefineRequest request{Scheme::CatmullClark, {}, 2, FaceVaryingRule::None};
    const InvarianceReport r = check_invariance(find_implementation("opensubdiv"), datasets::edge_case("uv-bowtie").mesh, request,
                                                {InputTransformation::RotateFaces, InputTransformation::ReverseFaces}, 1, 1e-12, 60, false);
    ASSERT_EQ(r.checks.size(), 2u);
    EXPECT_EQ(r.checks[0].result, InvarianceResult::NotInvariant) << r.checks[0].explanation;
    EXPECT_GT(r.checks[0].uv_max_rel, 0.01) << r.checks[0].explanation;
    EXPECT_LE(r.checks[0].max_rel, 1e-12);  // its positions do not move
    EXPECT_EQ(r.checks[1].result, InvarianceResult::Invariant) << r.checks[1].explanation;  // reversed: the same values
}

/// Core's refinement, with the vertex point of every interior extraordinary vertex (valence
/// other than `regular`) that is corner 2 of the first face listing it moved 1e-3 of its way
/// from the input's centroid (a move every affine map carries alike): right unless such a
/// vertex sits at that corner.
std::unique_ptr<Implementation> corner_position_subject(Scheme scheme, int regular) {
    return make_callback_implementation("corner-bug", {scheme}, [regular](const PolyMesh& m, const RefineRequest& r) {
        PolyMesh out = core_implementation().refine(m, r).back();
        const PolyConnectivity conn = build_poly_connectivity(m);
        std::vector<char> seen(static_cast<size_t>(m.num_vertices()), 0);
        Vec3 centroid = Vec3::Zero();
        for (const Vec3& p : m.positions) centroid += p / m.num_vertices();
        for (int f = 0; f < m.num_faces(); ++f)
            for (int k = 0; k < m.face_size(f); ++k) {
                const int v = m.face(f)[k];
                if (seen[static_cast<size_t>(v)]) continue;
                seen[static_cast<size_t>(v)] = 1;
                if (k == 2 && !conn.is_boundary_vertex(v) && conn.fan(v).faces != regular) {
                    Vec3& p = out.positions[static_cast<size_t>(v)];
                    p += 1e-3 * (p - centroid);
                }
            }
        return out;
    });
}

TEST(Invariance, ASubjectWrongAtOneCornerPositionIsNotInvariantUnderFaceRotation) {
    // Loop on the icosahedron (every vertex valence 5) and Catmull-Clark on the cube (valence 3).
    for (const auto& [scheme, regular, name] : {std::tuple{Scheme::Loop, 6, "icosahedron"}, std::tuple{Scheme::CatmullClark, 4, "quad-cube"}}) {
        const std::unique_ptr<Implementation> subject = corner_position_subject(scheme, regular);
        const InvarianceReport r = checked(*subject, datasets::bundled_mesh(name), scheme, 1);
        const InvarianceCheck& rot = check_of(r, InputTransformation::RotateCorners);
        EXPECT_EQ(rot.result, InvarianceResult::NotInvariant) << name << ": " << rot.explanation;
        EXPECT_GT(rot.max_rel, 1e-4) << name;
        EXPECT_NE(rot.worst_valence, regular) << name;  // the worst vertex is an extraordinary one
        EXPECT_NE(rot.explanation.find("valence"), std::string::npos) << rot.explanation;
        // What keeps every face's corners where they were keeps its answer.
        for (InputTransformation t : {InputTransformation::Scale, InputTransformation::Mirror, InputTransformation::Repeat})
            EXPECT_EQ(check_of(r, t).result, InvarianceResult::Invariant) << name << " " << to_string(t);
        EXPECT_FALSE(r.invariant());
        // Shrunk by delta debugging: the fan of one extraordinary vertex still shows it.
        RefineRequest request{scheme, {}, 1};
        if (scheme == Scheme::Loop) request.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
        const InvarianceShrink s = shrink_not_invariant(*subject, datasets::bundled_mesh(name), request,
                                                        InputTransformation::RotateCorners, 1, 1e-12, 60, false);
        EXPECT_EQ(s.minimal.num_faces(), scheme == Scheme::Loop ? 5 : 3) << name << " after " << s.tests << " checks";
        EXPECT_EQ(s.check.result, InvarianceResult::NotInvariant);
        EXPECT_NE(s.check.worst_valence, regular);
    }
    // Nothing to shrink where it is invariant.
    EXPECT_THROW(shrink_not_invariant(core_implementation(), datasets::bundled_mesh("icosahedron"), {Scheme::Loop, {}, 1},
                                      InputTransformation::RotateCorners, 1, 1e-12, 60, false),
                 InputError);
}

/// Core's refinement with each old vertex's position summed from three parts in an order set
/// by its label's parity: the same values up to rounding, whatever the labels.
std::unique_ptr<Implementation> summation_order_subject() {
    return make_callback_implementation("summation-order", {Scheme::Loop}, [](const PolyMesh& m, const RefineRequest& r) {
        PolyMesh out = core_implementation().refine(m, r).back();
        for (int v = 0; v < m.num_vertices(); ++v) {
            Vec3& p = out.positions[static_cast<size_t>(v)];
            const Vec3 a = p * 0.1, b = p * 0.2, c = p - a - b;
            p = v % 2 ? Vec3((a + b) + c) : Vec3(a + (b + c));
        }
        return out;
    });
}

TEST(Invariance, ASubjectThatDependsOnOrderOnlyThroughSummationIsInvariantInTheWeakTierOnly) {
    const std::unique_ptr<Implementation> subject = summation_order_subject();
    const InvarianceReport r = checked(*subject, datasets::bundled_mesh("torus"), Scheme::Loop, 1);
    const InvarianceCheck& relabel = check_of(r, InputTransformation::RelabelVertices);
    EXPECT_EQ(relabel.result, InvarianceResult::Invariant) << relabel.explanation;
    EXPECT_FALSE(relabel.bit_identical);
    EXPECT_GT(relabel.max_rel, 0.0);
    EXPECT_LE(relabel.max_rel, 1e-15);
    EXPECT_NE(relabel.explanation.find("not bit for bit (strict tier: not invariant)"), std::string::npos) << relabel.explanation;
    EXPECT_TRUE(r.invariant());
}

TEST(Invariance, ANondeterministicSubjectIsNamedSo) {
    int calls = 0;
    const std::unique_ptr<Implementation> subject =
        make_callback_implementation("drifting", {Scheme::Loop}, [&calls](const PolyMesh& m, const RefineRequest& r) {
            PolyMesh out = core_implementation().refine(m, r).back();
            out.positions[0].x() += 1e-6 * ++calls;  // another answer each run
            return out;
        });
    RefineRequest request{Scheme::Loop, {}, 1};
    const InvarianceReport r = check_invariance(*subject, datasets::bundled_mesh("octahedron"), request,
                                                {InputTransformation::Repeat}, 1, 1e-12, 60, false);
    ASSERT_EQ(r.checks.size(), 1u);
    EXPECT_EQ(r.checks[0].result, InvarianceResult::Nondeterministic) << r.checks[0].explanation;
    EXPECT_NE(r.checks[0].explanation.find("vertex 0"), std::string::npos) << r.checks[0].explanation;
}

TEST(Invariance, AFloatImplementationIsHeldToTwiceTheFloatTier) {
    // Two runs in float part by up to twice one run's rounding: a vertex moved by one float ulp
    // of the largest coordinate is within that bar, and outside the double one.
    const PolyMesh refined = core_implementation().refine(datasets::bundled_mesh("icosahedron"), {Scheme::Loop, {}, 1}).back();
    PolyMesh moved = refined;
    float largest = 0;
    for (const Vec3& p : refined.positions) largest = std::max(largest, static_cast<float>(p.cwiseAbs().maxCoeff()));
    moved.positions[3].x() += static_cast<double>(std::nextafter(largest, INFINITY) - largest);
    const TransformedInput same = transform_input(datasets::bundled_mesh("icosahedron"), InputTransformation::RotateCorners, 1);
    EXPECT_EQ(measure_invariance(refined, moved, same, 1e-12).result, InvarianceResult::NotInvariant);
    const double b = tolerances::kFloatAgreementUlps + 0.5 * (5 + 2) * 1;
    const InvarianceCheck in_float = measure_invariance(refined, moved, same, 1e-12, b);
    EXPECT_EQ(in_float.result, InvarianceResult::Invariant) << in_float.explanation;
    EXPECT_FALSE(in_float.bit_identical);
}

/// A finding of `impl` on `mesh` under `t`, and what explains it.
InvarianceCause cause_of(const Implementation& impl, const PolyMesh& mesh, const RefineRequest& request, InputTransformation t) {
    const InvarianceReport r = check_invariance(impl, mesh, request, {t}, 1, 1e-12, 60, true);
    EXPECT_EQ(r.checks.size(), 1u);
    if (r.checks.empty()) return {};
    EXPECT_NE(r.checks[0].result, InvarianceResult::Invariant) << impl.name() << " " << to_string(t);
    return explain_not_invariant(impl, mesh, request, r.checks[0], 1, 1e-12, 60, true);
}

TEST(InvarianceCause, AReferencesFindingIsClassedByWhatRemovesIt) {
    CROSSDIV_REQUIRE_LIBRARIES("openmesh", "cgal", "opensubdiv");
    RefineRequest loop{Scheme::Loop, {}, 2};
    loop.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    struct Expected {
        const char* impl;
        const char* mesh;
        RefineRequest request;
        InputTransformation t;
        DivergenceClass cls;
        const char* why;
    };
    const std::vector<Expected> cases = {
        // OpenMesh leaves an isolated vertex where memory had it: removed, the rest moves right.
        {"openmesh", "isolated-vertex", loop, InputTransformation::Translate, DivergenceClass::IsolatedVertexHandling,
         "invariant once its 1 vertices no face uses are removed"},
        // Three fans at one vertex: which keep it is read off the face order. Split into its
        // fans (not into single faces, which would make new bowties at the rims), invariant.
        {"cgal", "bowtie-3", loop, InputTransformation::ReverseFaces, DivergenceClass::NonManifoldHandling,
         "split into their fans"},
        {"openmesh", "bowtie", loop, InputTransformation::ShuffleFaces, DivergenceClass::NonManifoldHandling, "fans"},
        // Past Sqrt3T's 50 weights at a valence-64 pole.
        {"openmesh", "pole-64", {Scheme::Sqrt3, {}, 2}, InputTransformation::Translate, DivergenceClass::ValenceLimit,
         "valence 64"},
        // CGAL's Doo-Sabin makes a 2-gon at a valence-2 vertex, whose orientation no rule fixes.
        {"cgal", "valence-2", {Scheme::DooSabin, {}, 2}, InputTransformation::ReverseOrientation,
         DivergenceClass::DegenerateFaceHandling, "degenerate face at level 1"},
        // Far's UV bowtie under `none`: split into one value per fan, its values stay put.
        {"opensubdiv", "uv-bowtie", {Scheme::CatmullClark, {}, 2, FaceVaryingRule::None}, InputTransformation::RotateFaces,
         DivergenceClass::FaceOrderDependence, "bowtie values are split"},
    };
    for (const Expected& e : cases) {
        const InvarianceCause c = cause_of(find_implementation(e.impl), datasets::edge_case(e.mesh).mesh, e.request, e.t);
        EXPECT_EQ(c.cls, e.cls) << e.impl << " on " << e.mesh << ": " << c.why;
        EXPECT_NE(c.why.find(e.why), std::string::npos) << c.why;
    }
}

/// Expects `impl`'s finding on `mesh` under `t` to be explained as `cls`, in exactly `why`.
void expect_cause(const char* impl, const PolyMesh& mesh, const RefineRequest& request, InputTransformation t,
                  DivergenceClass cls, const std::string& why) {
    const InvarianceCause c = cause_of(find_implementation(impl), mesh, request, t);
    EXPECT_EQ(c.cls, cls) << impl << ": " << c.why;
    EXPECT_EQ(c.why, why) << impl;
}

// OpenMesh's Catmull-Clark moves a vertex no face uses to a third of its place, and a bowtie
// vertex, with its four boundary edges, to (v + four midpoints) / 3, weights that sum to 5/3:
// under a translation neither moves with the mesh. Neither removal alone makes it invariant, both
// in turn do (a Sweet Home 3D flower box has both); the bowtie named by its input number.
TEST(InvarianceCause, RemovalsAreKeptOneAfterAnother) {
    CROSSDIV_REQUIRE_LIBRARIES("openmesh");
    PolyMesh m;
    m.positions = {Vec3(5, 5, 5),                                                      // no face uses it
                   Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),         // a quad
                   Vec3(2, 1, 0), Vec3(2, 2, 0), Vec3(1, 2, 0)};                        // another at vertex 3
    m.add_face({1, 2, 3, 4});
    m.add_face({3, 5, 6, 7});
    expect_cause("openmesh", m, {Scheme::CatmullClark, {}, 1}, InputTransformation::Translate,
                 DivergenceClass::NonManifoldHandling,
                 "invariant once its 1 vertices no face uses are removed, its 1 non-manifold vertices are split into "
                 "their fans (vertex 3)");
}

// CGAL's Catmull-Clark links the boundaries of a bowtie in the order its faces come, so its
// points move when they are reversed; beside it two quads on the same corners put face points
// at one position, so the check compares point sets. The finding is gone when the points come
// out the same, as it was made (a Sweet Home 3D bamboo has both).
TEST(InvarianceCause, AFindingOnPointSetsIsGoneWhenTheSamePointsRemain) {
    CROSSDIV_REQUIRE_LIBRARIES("cgal");
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(2, 1, 0), Vec3(2, 2, 0),
                   Vec3(1, 2, 0), Vec3(4, 0, 0), Vec3(5, 0, 0), Vec3(5, 1, 0), Vec3(4, 1, 0)};
    m.add_face({0, 1, 2, 3});
    m.add_face({2, 4, 5, 6});  // a bowtie at vertex 2
    m.add_face({7, 8, 9, 10});
    m.add_face({10, 9, 8, 7});  // back to back
    const RefineRequest cc{Scheme::CatmullClark, {}, 1};
    const InvarianceReport r = check_invariance(find_implementation("cgal"), m, cc, {InputTransformation::ReverseFaces}, 1, 1e-12, 60, true);
    ASSERT_EQ(r.checks.size(), 1u);
    EXPECT_TRUE(r.checks[0].point_sets) << r.checks[0].explanation;
    expect_cause("cgal", m, cc, InputTransformation::ReverseFaces, DivergenceClass::NonManifoldHandling,
                 "the same points (its faces not compared: vertices at one position) once its 1 non-manifold "
                 "vertices are split into their fans (vertex 2)");
}

// Hbr takes a face-varying edge for a seam only where the values of its two faces differ by
// more than 0.001 (HbrHalfedge::IsFVarInfiniteSharpAnywhere): closer, they are one value, the
// first face's. Two triangles whose shared corners' values are 0.0005 apart (a Sweet Home 3D
// sofa's seams are so) move with the order of the faces; cut along the seam, they do not.
// 0.002 apart, Hbr sees the seam and keeps both.
TEST(InvarianceCause, HbrsValuesAlongASeamWithinItsToleranceAreReadOffTheFaceOrder) {
    CROSSDIV_REQUIRE_LIBRARIES("hbr");
    const auto seam = [](double apart) {
        PolyMesh m;
        m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
        m.add_face({2, 1, 3});
        m.add_face({0, 1, 2});
        FaceVaryingChannel& uv = m.face_varying.emplace_back();
        uv.values = {0.5, 0.5, 0.6, 0.5, 0.6, 0.6, 0.4, 0.4, 0.6 + apart, 0.5, 0.5, 0.5 + apart};
        uv.corner_values = {0, 1, 2, 3, 4, 5};
        return m;
    };
    const RefineRequest cc{Scheme::CatmullClark, {}, 2, FaceVaryingRule::All};
    const Implementation& hbr = find_implementation("hbr");
    const InvarianceReport r = check_invariance(hbr, seam(0.0005), cc, {InputTransformation::ReverseFaces}, 1, 1e-12, 60, true);
    ASSERT_EQ(r.checks.size(), 1u);
    EXPECT_TRUE(r.checks[0].uv_only) << r.checks[0].explanation;
    expect_cause("hbr", seam(0.0005), cc, InputTransformation::ReverseFaces, DivergenceClass::FaceOrderDependence,
                 "its texture coordinates depend on the order of the faces along a UV seam: invariant once it is cut "
                 "along its seams (2 vertex copies, one per value)");
    const InvarianceReport apart = check_invariance(hbr, seam(0.002), cc, {InputTransformation::ReverseFaces}, 1, 1e-12, 60, true);
    ASSERT_EQ(apart.checks.size(), 1u);
    EXPECT_EQ(apart.checks[0].result, InvarianceResult::Invariant) << apart.checks[0].explanation;
}

// A file of points and no face (Assimp's testpoints.obj): whatever an implementation makes of its
// vertices differs only at vertices no face uses, and nothing is left once they are removed.
TEST(InvarianceCause, AMeshWithoutFacesIsIsolatedVertexHandlingWithoutARun) {
    PolyMesh points;
    points.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    InvarianceCheck finding;
    finding.transformation = InputTransformation::Translate;
    finding.result = InvarianceResult::NotInvariant;
    const InvarianceCause c = explain_not_invariant(find_implementation("core"), points, {Scheme::CatmullClark, {}, 2},
                                                    finding, 1, 1e-12, 60, true);
    EXPECT_EQ(c.cls, DivergenceClass::IsolatedVertexHandling) << c.why;
    EXPECT_EQ(c.why, "the input has no faces: all 3 of its vertices are ones no face uses");
}

// VTK's Butterfly: on a lone triangle and on the bowtie of two, a loop of three boundary edges
// whose four-point rule it gives an outer point that does not move with the mesh.
TEST(InvarianceCause, VtksButterflyOnABoundaryLoopOfThreeEdgesIsAShortBoundaryLoop) {
    CROSSDIV_REQUIRE_LIBRARIES("vtk");
    RefineRequest vtk{Scheme::ModifiedButterfly, {}, 2};
    vtk.rule.butterfly_wings = ButterflyWings::OtherFaceVertex;
    for (const char* mesh : {"single-triangle", "bowtie", "holes"}) {
        const InvarianceCause c = cause_of(find_implementation("vtk"), datasets::edge_case(mesh).mesh, vtk, InputTransformation::Translate);
        EXPECT_EQ(c.cls, DivergenceClass::ShortBoundaryLoop) << mesh << ": " << c.why;
        EXPECT_NE(c.why.find("boundary loop(s) of three edges are capped"), std::string::npos) << c.why;
    }
}

// Hierarchical edits name faces, corners and positions of the input as written: a
// transformation would carry them elsewhere, so only the same input run again is compared; a
// submesh (shrinking, the cause tests) keeps the edits of its faces, renumbered.
TEST(Invariance, AMeshWithHierarchicalEditsIsComparedWithItselfOnly) {
    PolyMesh m = datasets::bundled_mesh("quad-grid");
    m.creases.edits = {HierarchicalEdit{EditTarget::Position, EditOperation::Add, 1, {2}, 0, {0, 0, 1}, 0},
                       HierarchicalEdit{EditTarget::Hole, EditOperation::Set, 0, {1}, -1, {}, 0}};
    const InvarianceReport r = check_invariance(core_implementation(), m, {Scheme::CatmullClark, {}, 2},
                                                {InputTransformation::ShuffleFaces, InputTransformation::Repeat}, 1, 1e-12, 60, false);
    ASSERT_EQ(r.checks.size(), 2u);
    EXPECT_EQ(r.checks[0].result, InvarianceResult::NotCompared);
    EXPECT_NE(r.checks[0].explanation.find("2 hierarchical edit(s)"), std::string::npos) << r.checks[0].explanation;
    EXPECT_EQ(r.checks[1].result, InvarianceResult::Invariant) << r.checks[1].explanation;
    const PolyMesh part = submesh(m, {1, 2});
    ASSERT_EQ(part.creases.edits.size(), 1u);  // face 0's hole goes with face 0
    EXPECT_EQ(part.creases.edits[0].face, 0);  // face 1 is the part's face 0
    EXPECT_EQ(part.creases.edits[0].children, std::vector<int>{2});
}

TEST(InvarianceCause, NothingNamedExplainsAPlantedCornerBug) {
    const std::unique_ptr<Implementation> subject = corner_position_subject(Scheme::Loop, 6);
    RefineRequest request{Scheme::Loop, {}, 1};
    const InvarianceCause c = cause_of(*subject, datasets::bundled_mesh("icosahedron"), request, InputTransformation::RotateCorners);
    EXPECT_EQ(c.cls, DivergenceClass::Unexplained) << c.why;
}

std::filesystem::path fresh_folder(const std::string& name) {
    const std::filesystem::path d = std::filesystem::temp_directory_path() / ("crossdiv_invariance_" + name + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    return d;
}

Manifest manifest_of(const std::string& text) {
    std::istringstream in(text);
    return read_manifest(in, "t.suite", ".", ProgramStatements::CheckOnly);
}

TEST(InvarianceView, TheOtherRunIsMappedBackIntoTheFirstsNumbering) {
    // Core under scale: the other run, mapped back (halved), lands on the first bit
    // for bit, vertex for vertex; every level is there, the earlier ones without a map.
    const PolyMesh mesh = datasets::bundled_mesh("open-patch");
    RefineRequest request{Scheme::Loop, {}, 2};
    request.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    const std::optional<DivergenceView> view =
        invariance_view(core_implementation(), mesh, request, InputTransformation::Scale, 1, 60, false);
    ASSERT_TRUE(view);
    ASSERT_EQ(view->levels.size(), 3u);
    const auto& other = view->references.at("core under scale");
    ASSERT_EQ(other.size(), 3u);
    EXPECT_TRUE(other[0].empty());
    ASSERT_EQ(other[2].size(), view->levels[2].positions.size());
    for (size_t v = 0; v < other[2].size(); ++v) EXPECT_EQ(other[2][v], view->levels[2].positions[v]) << v;
}

TEST(InvarianceCase, TheManifestTakesTheSchemesKeysAndRefusesWhatHasNoMeaningHere) {
    const Manifest m = manifest_of("suite t\ncase bundled:icosahedron,edgecase:bowtie invariance scheme=loop levels=2 "
                                   "boundary=edge-and-corner impls=core transform=rotate-corners,repeat seed=7\n"
                                   "case bundled:quad-cube invariance scheme=catmull-clark triangles=smooth fvar=none\n");
    ASSERT_EQ(m.entries.size(), 2u);
    const ManifestEntry& e = m.entries[0];
    EXPECT_EQ(e.operation->kind, OperationKind::Invariance);
    EXPECT_EQ(e.request.scheme, Scheme::Loop);
    EXPECT_EQ(e.request.levels, 2);
    EXPECT_EQ(e.request.rule.loop.boundary, LoopBoundary::EdgeAndCorner);
    EXPECT_EQ(e.invariance.implementations, std::vector<std::string>{"core"});
    EXPECT_EQ(e.invariance.transformations,
              (std::vector<InputTransformation>{InputTransformation::RotateCorners, InputTransformation::Repeat}));
    EXPECT_EQ(e.invariance.seed, 7u);
    // Without impls=: core and every reference of the scheme.
    EXPECT_EQ(m.entries[1].invariance.implementations.front(), "core");
    EXPECT_EQ(m.entries[1].invariance.implementations.size(), 1 + references_for(Scheme::CatmullClark).size());
    EXPECT_EQ(m.entries[1].rule_flags.triangles, "smooth");
    const std::vector<SuiteJob> jobs = expand_jobs(m);
    ASSERT_EQ(jobs.size(), 3u);
    EXPECT_EQ(jobs[0].id, "bundled:icosahedron | invariance loop weights=loop boundary=edge-and-corner L2 tol=1e-12 impls=core "
                          "transform=rotate-corners,repeat seed=7");
    for (const char* bad : {"case bundled:all invariance levels=2",                       // no scheme
                            "case bundled:all invariance scheme=loop against=cgal",        // a comparison's key
                            "case bundled:all invariance scheme=loop tier=strict",
                            "case bundled:all invariance scheme=loop transform=spin",      // no such transformation
                            "case bundled:all invariance scheme=loop impls=nosuch",        // no such implementation
                            "case bundled:all invariance scheme=doo-sabin impls=opensubdiv",  // not its scheme
                            "case bundled:all invariance scheme=loop seed=-1",
                            "case bundled:all invariance scheme=loop crease-method=chaikin"})  // not Loop's key
        EXPECT_THROW(manifest_of(std::string("suite t\n") + bad + "\n"), ParseError) << bad;
    EXPECT_THROW(manifest_of("suite t\nsubject s result=out/{input}.obj\ncase bundled:all invariance scheme=loop\n"),
                 ParseError);
}

TEST(InvarianceCase, APlantedSubjectFailsWithItsMinimalInputAndCoreIsInvariant) {
    const std::filesystem::path d = fresh_folder("case");
    Manifest m = manifest_of("suite t\ncase bundled:icosahedron invariance scheme=loop levels=1 impls=core\n");
    ASSERT_EQ(m.entries.size(), 1u);
    const std::vector<SuiteJob> jobs = expand_jobs(m);
    const CaseRecord core = run_invariance_case(jobs[0], d.string());
    ASSERT_EQ(core.runs.size(), kInputTransformations.size());
    for (const RunRecord& r : core.runs) {
        EXPECT_EQ(r.subject, "core");
        // One component and one level: nothing to refine apart or level by level.
        const bool nothing_to_run = r.check == "components" || r.check == "level-by-level";
        EXPECT_EQ(outcome_label(core, r), nothing_to_run ? "not-compared" : "agree") << r.check << ": " << r.explanation;
    }
    EXPECT_FALSE(core.detail["implementations"][0].contains("minimal"));

    // The same case with a subject wrong only where an extraordinary vertex is corner 2.
    auto subject = std::make_shared<ManifestSubject>();
    subject->name = "corner-bug";
    subject->program = corner_position_subject(Scheme::Loop, 6);
    m.entries[0].subject = subject;
    const CaseRecord planted = run_invariance_case(jobs[0], d.string());
    const auto rot = std::find_if(planted.runs.begin(), planted.runs.end(), [](const RunRecord& r) { return r.check == "rotate-corners"; });
    ASSERT_NE(rot, planted.runs.end());
    EXPECT_EQ(rot->subject, "corner-bug");
    EXPECT_EQ(outcome_label(planted, *rot), "diverge (unexplained)") << rot->explanation;
    EXPECT_TRUE(is_failure(planted, *rot));
    EXPECT_NE(rot->worst_valence, 6);
    const nlohmann::json& minimal = planted.detail["implementations"][0]["minimal"];
    EXPECT_EQ(minimal["faces"], 5);  // one valence-5 fan
    EXPECT_EQ(minimal["transformation"], "rotate-corners");
    EXPECT_TRUE(std::filesystem::exists(d / minimal["mesh"].get<std::string>()));
    EXPECT_NE(minimal["reproduce"].get<std::string>().find("--transform rotate-corners --seed 1"), std::string::npos);
    std::filesystem::remove_all(d);
}

TEST(InvarianceCase, AFindingOnALargeInputIsShrunkWithinTheTimeLimit) {
    // The corner bug on the icosahedron refined three times: 1,280 faces, its twelve valence-5
    // vertices kept, as large as a real model's part: shrunk however many faces the input has,
    // to a 1-minimal input (rotate-corners draws each face's rotation from one stream, so which
    // fan shows the bug depends on the faces before it, and the minimum is not one fan here).
    const std::unique_ptr<Implementation> subject = corner_position_subject(Scheme::Loop, 6);
    RefineRequest request{Scheme::Loop, {}, 1};
    request.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    RefineRequest three = request;
    three.levels = 3;
    const PolyMesh large = core_implementation().refine_last(datasets::bundled_mesh("icosahedron"), three);
    ASSERT_EQ(large.num_faces(), 1280);
    const InvarianceReport report = check_invariance(*subject, large, request, {InputTransformation::RotateCorners}, 1, 1e-12, 60, false);
    ASSERT_EQ(report.checks.size(), 1u);
    ASSERT_EQ(report.checks[0].result, InvarianceResult::NotInvariant) << report.checks[0].explanation;
    const std::filesystem::path d = fresh_folder("large");
    const std::optional<InvarianceMinimal> m =
        shrink_first_finding(*subject, true, true, large, request, report, {}, 1, 1e-12, 60, false, d.string(), "large");
    ASSERT_TRUE(m.has_value());
    EXPECT_FALSE(m->cut_short);
    EXPECT_LT(m->faces, 1280 / 10);
    const PolyMesh minimal = read_mesh(m->mesh);
    ASSERT_EQ(minimal.num_faces(), m->faces);
    const auto shows = [&](const PolyMesh& mesh) {
        const InvarianceReport r = check_invariance(*subject, mesh, request, {InputTransformation::RotateCorners}, 1, 1e-12, 60, false);
        return r.checks.size() == 1 && r.checks[0].finding();
    };
    EXPECT_TRUE(shows(minimal));
    for (int f = 0; f < minimal.num_faces(); ++f) {  // 1-minimal: no face can go
        std::vector<int> others(static_cast<size_t>(minimal.num_faces()) - 1);
        std::iota(others.begin(), others.begin() + f, 0);
        std::iota(others.begin() + f, others.end(), f + 1);
        EXPECT_FALSE(shows(submesh(minimal, others))) << "without face " << f;
    }
    EXPECT_TRUE(std::filesystem::exists(m->mesh));
    EXPECT_EQ(to_json(*m)["cut_short"], false);

    // Out of time before the first candidate: the input itself, marked cut short, after the one
    // check that found the finding again.
    const InvarianceShrink none = shrink_not_invariant(*subject, large, request, InputTransformation::RotateCorners, 1, 1e-12, 60,
                                                       false, ShrinkLimits{0});
    EXPECT_TRUE(none.cut_short);
    EXPECT_EQ(none.tests, 1);
    EXPECT_EQ(none.minimal.num_faces(), 1280);
    EXPECT_EQ(none.check.result, InvarianceResult::NotInvariant);
    std::filesystem::remove_all(d);
}

TEST(InvarianceCase, AReferencesUnexplainedFindingIsShrunkBeforeOneAClassNames) {
    // Two findings of the corner bug (corners rotated in turn, and at random). As a reference's,
    // with the first one's cause named by a class, the second (unexplained) is shrunk: the one
    // that fails the case. As the implementation under test's, every finding fails: the first.
    const std::unique_ptr<Implementation> bug = corner_position_subject(Scheme::Loop, 6);
    RefineRequest request{Scheme::Loop, {}, 1};
    request.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    const PolyMesh ico = datasets::bundled_mesh("icosahedron");
    const std::vector<InputTransformation> both = {InputTransformation::RotateCorners, InputTransformation::RotateCornersRandom};
    const InvarianceReport report = check_invariance(*bug, ico, request, both, 1, 1e-12, 60, false);
    ASSERT_EQ(report.checks.size(), 2u);
    ASSERT_TRUE(report.checks[0].finding() && report.checks[1].finding());
    const std::vector<std::optional<InvarianceCause>> causes = {InvarianceCause{DivergenceClass::FaceOrderDependence, "named"},
                                                                std::nullopt};
    const std::filesystem::path d = fresh_folder("unexplained-first");
    const auto shrunk = [&](bool under_test) {
        const std::optional<InvarianceMinimal> m =
            shrink_first_finding(*bug, false, under_test, ico, request, report, causes, 1, 1e-12, 60, false, d.string(), "ico");
        return m ? m->transformation : InputTransformation::Repeat;
    };
    EXPECT_EQ(shrunk(false), InputTransformation::RotateCornersRandom);
    EXPECT_EQ(shrunk(true), InputTransformation::RotateCorners);
    std::filesystem::remove_all(d);
}

TEST(InvarianceCase, AnInputTheSchemeRefusesBeforeAnyRunStillNamesTheScheme) {
    // Loop's invariance over quads: refused by name before any implementation runs (as over the
    // corpus's quad models), counted under Loop's invariance, not under an unknown scheme.
    const std::filesystem::path d = fresh_folder("refused-input");
    const Manifest m = manifest_of("suite t\ncase bundled:quad-cube invariance scheme=loop levels=2 impls=core "
                                   "refuses=invalid-input-handling\n");
    const std::vector<SuiteJob> jobs = expand_jobs(m);
    ASSERT_EQ(jobs.size(), 1u);
    const nlohmann::json j = to_json(run_job(jobs[0], d.string()));
    EXPECT_EQ(j.value("scheme", ""), "loop") << j.dump();
    EXPECT_EQ(j.value("levels", 0), 2);
    EXPECT_NE(j.value("core_error", "").find("needs triangles"), std::string::npos) << j.dump();
    std::filesystem::remove_all(d);
}

TEST(InvarianceCase, CoresRefusalFailsUnlessDeclaredAndAReferencesFindingPassesClassed) {
    CROSSDIV_REQUIRE_LIBRARIES("cgal");
    const std::filesystem::path d = fresh_folder("refusal");
    const Manifest m = manifest_of("suite t\ncase edgecase:bowtie-3 invariance scheme=sqrt3 levels=2 impls=core,cgal-one-call "
                                   "transform=reverse-faces\n"
                                   "case edgecase:bowtie-3 invariance scheme=sqrt3 levels=2 impls=core,cgal-one-call "
                                   "transform=reverse-faces refuses=non-manifold-handling\n");
    const std::vector<SuiteJob> jobs = expand_jobs(m);
    ASSERT_EQ(jobs.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
        const CaseRecord c = run_invariance_case(jobs[k], d.string());
        ASSERT_EQ(c.runs.size(), 2u);
        EXPECT_EQ(c.runs[0].check, "input");
        EXPECT_EQ(outcome_label(c, c.runs[0]), k == 0 ? "ours-rejected (unexplained)" : "ours-rejected (non-manifold-handling)");
        EXPECT_EQ(is_failure(c, c.runs[0]), k == 0);
        EXPECT_EQ(c.runs[1].subject, "cgal-one-call");
        EXPECT_EQ(outcome_label(c, c.runs[1]), "diverge (non-manifold-handling)") << c.runs[1].explanation;
        EXPECT_FALSE(is_failure(c, c.runs[1]));
        // The finding drawn for the viewer: CGAL's levels, and its run on the faces reversed.
        ASSERT_TRUE(c.detail.contains("view"));
        EXPECT_TRUE(std::filesystem::exists(d / c.detail["view"].get<std::string>()));
        EXPECT_EQ(c.detail["view_reference"], "cgal-one-call under reverse-faces");
    }
    std::filesystem::remove_all(d);
}

}  // namespace
}  // namespace crossdiv::verification
