// The 3D viewer's side file: the arrays byte for byte (hand-encoded base64), and a real
// divergence's view holding every level and each reference's offsets from ours.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/implementations/inputs.h"
#include "crossdiv/verification/pages/divergence_view_file.h"
#include "library_guard.h"

namespace crossdiv::verification {
namespace {

PolyMesh triangle() {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    m.add_face({0, 1, 2});
    return m;
}

TEST(DivergenceView, ArraysAreLittleEndianBase64ByHand) {
    DivergenceView view;
    view.levels = {triangle()};
    // The reference: vertex 1 lifted by 0.5 in z, vertex 2 unmatched.
    view.references["ref"] = {{Vec3(0, 0, 0), Vec3(1, 0, 0.5), Vec3::Constant(NAN)}};
    const std::string script = divergence_view_script(view, 7, "core");
    ASSERT_EQ(script.rfind("crossdivView(", 0), 0u);
    EXPECT_EQ(script.substr(script.size() - 3), ");\n");
    // Triangle (0, 1, 2) as int32: 00000000 01000000 02000000.
    EXPECT_NE(script.find("\"triangles\":\"AAAAAAEAAAACAAAA\""), std::string::npos) << script;
    // Positions as float64: 0 0 0, then 1.0 = 00..00 F0 3F, 0, 0, then 0, 1.0, 0.
    EXPECT_NE(script.find("\"positions\":\"AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA8D8AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAADwPwAAAAAAAAAA\""),
              std::string::npos) << script;
    // Offsets as float32: 0 0 0 | 0 0 0.5 (00 00 00 3F) | NaN NaN NaN (00 00 C0 7F, the quiet NaN).
    EXPECT_NE(script.find("\"ref\":[\"AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA/AADAfwAAwH8AAMB/\"]"), std::string::npos) << script;
    EXPECT_NE(script.find("\"job\":7"), std::string::npos);
    EXPECT_EQ(script.find("origins"), std::string::npos);  // level 0 has none
}

TEST(DivergenceView, AReferenceWithoutAMapAtALevelIsNull) {
    DivergenceView view;
    view.levels = {triangle(), triangle()};
    using Kind = VertexBirth::Kind;
    view.births = {{{Kind::Vertex, 0, -1}, {Kind::Edge, 0, 1}, {Kind::Face, 0, -1}}};
    view.references["ref"] = {{}, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}};
    const std::string script = divergence_view_script(view, 0, "core");
    EXPECT_NE(script.find("\"ref\":[null,\""), std::string::npos) << script;
    // Origins (0, -1) (0, 1) (0, -2): 00000000 FFFFFFFF 00000000 01000000 00000000 FEFFFFFF.
    EXPECT_NE(script.find("\"origins\":\"AAAAAP////8AAAAAAQAAAAAAAAD+////\""), std::string::npos) << script;
}

TEST(DivergenceView, APolygonLevelNamesItsFaceSizes) {
    PolyMesh quad;
    quad.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    quad.add_face({0, 1, 2, 3});
    DivergenceView view;
    view.levels = {quad};
    const std::string script = divergence_view_script(view, 0, "core");
    // The quad fanned into (0, 1, 2) (0, 2, 3), and its one size, 4: 04000000.
    EXPECT_NE(script.find("\"triangles\":\"AAAAAAEAAAACAAAAAAAAAAIAAAADAAAA\""), std::string::npos) << script;
    EXPECT_NE(script.find("\"sizes\":\"BAAAAA==\""), std::string::npos) << script;
    EXPECT_EQ(divergence_view_script(DivergenceView{{triangle()}, {}, {}, {}}, 0, "core").find("sizes"), std::string::npos);
}

TEST(DivergenceView, ACatmullClarkBoundaryRuleDivergenceKeepsEveryLevelOfCoreAndOfEachReference) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv", "openmesh");
    RefinementRequest req;
    req.scheme = Scheme::CatmullClark;
    req.levels = 2;
    req.references = {"opensubdiv", "openmesh"};
    req.view_max_faces = 1000;
    const PolyMesh input = load_input("bundled:quad-grid");
    const RefinementComparison c = compare_refinement(input, "bundled:quad-grid", req);
    ASSERT_TRUE(c.view.has_value());
    const DivergenceView& v = *c.view;
    ASSERT_EQ(v.levels.size(), 3u);  // Catmull-Clark is primal: every level, in core's numbering
    EXPECT_EQ(v.levels[2].num_faces(), 16 * input.num_faces());
    // Provenance at every level, read off core's faces: vertex points, then a face point per
    // face, then an edge point per edge (Catmull-Clark's order).
    ASSERT_EQ(v.births.size(), 2u);
    for (size_t l = 1; l <= 2; ++l) ASSERT_EQ(v.births[l - 1].size(), v.levels[l].positions.size());
    const int nv = input.num_vertices(), nf = input.num_faces();
    EXPECT_EQ(v.births[0][0], (VertexBirth{VertexBirth::Kind::Vertex, 0, -1}));
    EXPECT_EQ(v.births[0][static_cast<size_t>(nv)], (VertexBirth{VertexBirth::Kind::Face, 0, -1}));
    const VertexBirth e = v.births[0][static_cast<size_t>(nv + nf)];
    EXPECT_EQ(e.kind, VertexBirth::Kind::Edge);
    bool a_side = false;  // (e.a, e.b) is a side of some input face
    for (int f = 0; f < nf; ++f)
        for (int k = 0; k < input.face_size(f); ++k) {
            const int p = input.face(f)[k], q = input.face(f)[(k + 1) % input.face_size(f)];
            a_side = a_side || (p == e.a && q == e.b) || (p == e.b && q == e.a);
        }
    EXPECT_TRUE(a_side) << e.a << " " << e.b;
    for (const char* ref : {"opensubdiv", "openmesh"}) {
        const auto& at = v.references.at(ref);
        ASSERT_EQ(at.size(), 3u);
        for (size_t l = 0; l < 3; ++l)  // matched level by level through provenance
            ASSERT_EQ(at[l].size(), v.levels[l].positions.size()) << ref << " level " << l;
    }
    // OpenSubdiv sits on core; OpenMesh's midpoint-average corners do not (a corner of the
    // grid is vertex 0, kept first).
    EXPECT_LE((v.references.at("opensubdiv")[2][0] - v.levels[2].positions[0]).norm(), 1e-15);
    EXPECT_GT((v.references.at("openmesh")[2][0] - v.levels[2].positions[0]).norm(), 1e-3);
    // A scheme that is not primal shows every level too (sqrt3: a face point per face).
    RefinementRequest sqrt3;
    sqrt3.scheme = Scheme::Sqrt3;
    sqrt3.levels = 2;
    sqrt3.references = {"openmesh"};  // per level: it never refines the boundary (parity)
    sqrt3.view_max_faces = 1000;
    const RefinementComparison s = compare_refinement(load_input("bundled:open-patch"), "bundled:open-patch", sqrt3);
    ASSERT_TRUE(s.view.has_value());
    ASSERT_EQ(s.view->levels.size(), 3u);
    EXPECT_EQ(s.view->levels[1].num_vertices(), s.view->levels[0].num_vertices() + s.view->levels[0].num_faces());
    EXPECT_TRUE(s.view->births.empty());  // sqrt3 rotates its edges: no provenance drawn
    // No view when every reference agrees, or past the size limit.
    req.references = {"opensubdiv"};
    EXPECT_FALSE(compare_refinement(input, "bundled:quad-grid", req).view.has_value());
    req.references = {"opensubdiv", "openmesh"};
    req.view_max_faces = 10;
    EXPECT_FALSE(compare_refinement(input, "bundled:quad-grid", req).view.has_value());
}

TEST(DivergenceView, ACornerRuleDivergenceKeepsEveryLevelAndEachReference) {
    RefinementRequest req;
    req.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeAndCorner};
    req.levels = 2;
    req.references = {"opensubdiv", "openmesh"};
    req.view_max_faces = 1000;
    const PolyMesh input = load_input("bundled:open-patch");
    const RefinementComparison c = compare_refinement(input, "bundled:open-patch", req);
    ASSERT_TRUE(c.view.has_value());
    const DivergenceView& v = *c.view;
    ASSERT_EQ(v.levels.size(), 3u);
    ASSERT_EQ(v.births.size(), 2u);
    EXPECT_EQ(v.levels[0].positions, input.positions);
    for (int l = 1; l <= 2; ++l) EXPECT_EQ(v.births[l - 1].size(), v.levels[l].positions.size());
    // OpenSubdiv has the corner rule and agrees; OpenMesh lacks it: its offsets are largest at
    // the case's worst vertex, and equal to the worst vertex's recorded values.
    ASSERT_EQ(v.references.size(), 2u);
    for (const auto& [name, levels] : v.references) {
        ASSERT_EQ(levels.size(), 3u) << name;
        for (int l = 0; l <= 2; ++l) ASSERT_EQ(levels[l].size(), v.levels[l].positions.size()) << name << " level " << l;
    }
    const int w = c.worst_vertex->ours_index;
    EXPECT_EQ(v.references.at("openmesh")[2][w], c.worst_vertex->reference_positions.at("openmesh"));
    EXPECT_GT((v.references.at("openmesh")[2][w] - v.levels[2].positions[w]).norm(), 1e-3);
    for (size_t i = 0; i < v.levels[2].positions.size(); ++i)
        EXPECT_LT((v.references.at("opensubdiv")[2][i] - v.levels[2].positions[i]).norm(), 1e-12) << i;

    req.view_max_faces = 0;  // not asked for
    EXPECT_FALSE(compare_refinement(input, "bundled:open-patch", req).view.has_value());
    req.view_max_faces = 1000;
    req.rule.loop.boundary = LoopBoundary::EdgeOnly;  // every reference agrees: nothing to view
    EXPECT_FALSE(compare_refinement(input, "bundled:open-patch", req).view.has_value());
}

}  // namespace
}  // namespace crossdiv::verification
