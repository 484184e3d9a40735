// Invariance testing (comparisons/invariance.h): the transformations by hand on tiny inputs,
// core invariant under every one, and planted subjects -- one wrong only where an
// extraordinary vertex is a particular corner of its first face, one whose output depends on
// vertex order through its summation order alone -- told apart.

#include <gtest/gtest.h>

#include <algorithm>

#include "library_guard.h"

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/verification/comparisons/input_transformation.h"
#include "crossdiv/verification/comparisons/invariance.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/registry.h"

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

/// Each transformation's check of `impl` on `mesh`.
InvarianceReport checked(const Implementation& impl, const PolyMesh& mesh, Scheme scheme, int levels) {
    RefineRequest r{scheme, {}, levels};
    if (scheme == Scheme::Loop) r.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    return check_invariance(impl, mesh, r, {kInputTransformations.begin(), kInputTransformations.end()}, 1, 1e-12, 60, false);
}

const InvarianceCheck& check_of(const InvarianceReport& r, InputTransformation t) {
    return *std::find_if(r.checks.begin(), r.checks.end(), [&](const InvarianceCheck& c) { return c.transformation == t; });
}

TEST(Invariance, CoreIsInvariantUnderEveryTransformation) {
    for (const char* name : {"icosahedron", "open-patch", "octahedron"}) {
        const InvarianceReport r = checked(core_implementation(), datasets::bundled_mesh(name), Scheme::Loop, 2);
        ASSERT_EQ(r.checks.size(), kInputTransformations.size());
        for (const InvarianceCheck& c : r.checks)
            EXPECT_EQ(c.result, InvarianceResult::Invariant) << name << " " << to_string(c.transformation) << ": " << c.explanation;
        // Exact transformations are bit for bit.
        EXPECT_TRUE(check_of(r, InputTransformation::Scale).bit_identical) << name;
        EXPECT_TRUE(check_of(r, InputTransformation::Repeat).bit_identical) << name;
    }
    const InvarianceReport cc = checked(core_implementation(), datasets::bundled_mesh("quad-cube"), Scheme::CatmullClark, 2);
    for (const InvarianceCheck& c : cc.checks)
        EXPECT_EQ(c.result, InvarianceResult::Invariant) << "quad-cube " << to_string(c.transformation) << ": " << c.explanation;
}

TEST(Invariance, TextureCoordinatesAreCheckedToo) {
    // Core refines the UV junction's channel as invariantly as its positions; a subject whose
    // texture coordinates depend on the first face's first corner is caught by them alone.
    RefineRequest request{Scheme::CatmullClark, {}, 2, FaceVaryingRule::None};
    const PolyMesh mesh = datasets::edge_case("uv-junction").mesh;
    const InvarianceReport core = check_invariance(core_implementation(), mesh, request,
                                                   {kInputTransformations.begin(), kInputTransformations.end()}, 1, 1e-12, 60, false);
    for (const InvarianceCheck& c : core.checks) {
        EXPECT_EQ(c.result, InvarianceResult::Invariant) << to_string(c.transformation) << ": " << c.explanation;
        EXPECT_LE(c.uv_max_rel, 1e-12) << to_string(c.transformation);
    }
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

}  // namespace
}  // namespace crossdiv::verification
