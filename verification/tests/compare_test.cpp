// The comparison's figures on meshes where they are known by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/subdiv/nonmanifold.h"
#include "crossdiv/verification/comparisons/classification.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/registry.h"
#include "library_guard.h"

namespace crossdiv::verification {
namespace {

PolyMesh square_pair() {  // unit square as two triangles: 4 vertices, 5 edges, 1 boundary loop
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(3, 4, 0), Vec3(0, 4, 0)};
    m.add_face({0, 1, 2});
    m.add_face({0, 2, 3});
    return m;
}

/// The one run of `reference` on `mesh`: 2 levels of (scheme, rule).
RefinementRun only_run(const char* reference, const PolyMesh& mesh, Scheme scheme, const SchemeRule& rule,
                       double timeout_seconds = 120) {
    RefinementRequest req;
    req.scheme = scheme;
    req.rule = rule;
    req.levels = 2;
    req.references = {reference};
    req.timeout_seconds = timeout_seconds;
    const RefinementComparison c = compare_refinement(mesh, "mesh", req);
    EXPECT_EQ(c.runs.size(), 1u);
    return c.runs.at(0);
}

// OpenMesh lacks Loop's corner rule and, at an isolated vertex, writes whatever is in memory
// (LoopT::smooth returns before writing it). Both at once are named, never unexplained: the
// corner rule, with the isolated vertex too when it moved; and run again with its heap filled
// otherwise, the isolated vertex changes: ref-nondeterministic, the class kept. (Under the
// sanitizers, whose allocator fills memory itself, the second run may find the same bytes.)
TEST(Compare, ACornerRuleBesideAnIsolatedVertexIsNamedBoth) {
    CROSSDIV_REQUIRE_LIBRARIES("openmesh");
    TriMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0.1), Vec3(0, 1, 0), Vec3(1, 1, 0.3),
                   Vec3(2, 1, 0), Vec3(0, 2, 0.2), Vec3(1, 2, 0), Vec3(2, 2, 0), Vec3(5, 5, 5)};
    m.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}, {4, 5, 8}, {4, 8, 7}};
    RefinementRequest req;
    req.rule.loop = {LoopWeights::Loop, LoopBoundary::EdgeAndCorner};
    req.levels = 2;
    req.references = {"openmesh"};
    const RefinementComparison c = compare_refinement(to_poly_mesh(m), "open grid and an isolated vertex", req);
    ASSERT_EQ(c.runs.size(), 1u);
#ifndef CROSSDIV_SANITIZED
    EXPECT_EQ(c.runs[0].verdict, Verdict::RefNondeterministic) << c.runs[0].explanation;
    EXPECT_NE(c.runs[0].explanation.find("openmesh gives another result when run again on the same input with its heap filled "
                                         "otherwise"),
              std::string::npos) << c.runs[0].explanation;
    EXPECT_NE(c.runs[0].explanation.find(" vertex 9 is ("), std::string::npos) << c.runs[0].explanation;  // the isolated vertex
#endif
    EXPECT_EQ(c.runs[0].divergence_class, DivergenceClass::CornerRule) << c.runs[0].explanation;
}

// VTK's vtkLoopSubdivisionFilter: Loop's weights and the edge-only boundary, its points
// stored in single precision: agrees with core in the float tier, lacks the corner rule, and
// crashes (a stack array overrun, "stack smashing detected") at a vertex of valence 360, which
// the isolated run records. Measured with fans: valence 256 refines, 257 aborts.
TEST(Compare, VtkIsLoopInTheFloatTierWithoutTheCornerRule) {
    CROSSDIV_REQUIRE_LIBRARIES("vtk");
    auto run = [](const PolyMesh& mesh, LoopBoundary boundary) {
        SchemeRule rule;
        rule.loop = {LoopWeights::Loop, boundary};
        return only_run("vtk", mesh, Scheme::Loop, rule);
    };
    for (const char* name : {"icosahedron", "open-patch", "cube-asymmetric", "fan-5"}) {
        const auto r = run(datasets::bundled_mesh(name), LoopBoundary::EdgeOnly);
        EXPECT_EQ(r.verdict, Verdict::Agree) << name << ": " << r.explanation;
        EXPECT_GT(r.comparison.max_rel, 0.0) << name;  // float, not bit for bit
    }
    EXPECT_EQ(run(datasets::bundled_mesh("open-patch"), LoopBoundary::EdgeAndCorner).divergence_class, DivergenceClass::CornerRule);
    EXPECT_EQ(run(datasets::edge_case("pole-360").mesh, LoopBoundary::EdgeOnly).outcome.status, RunStatus::Crashed);
    const auto rejected = run(datasets::edge_case("nonmanifold-edge-3").mesh, LoopBoundary::EdgeOnly);
    EXPECT_EQ(rejected.outcome.status, RunStatus::Rejected);
    EXPECT_NE(rejected.outcome.message.find("Dataset is non-manifold"), std::string::npos) << rejected.outcome.message;
}

// VTK's vtkButterflySubdivisionFilter: the modified Butterfly with VTK's boundary choices
// (core's other-face-wings), in the float tier. Asked for OpenMesh's choices it differs by the
// wing rule; on a boundary loop of three edges it takes another outer point for the four-point
// rule than the loop's third vertex, and only those edge points differ (short-boundary-loop).
TEST(Compare, VtksButterflyIsTheModifiedButterflyWithItsOwnBoundaryChoices) {
    CROSSDIV_REQUIRE_LIBRARIES("vtk");
    auto run = [](const PolyMesh& mesh, ButterflyWings wings) {
        SchemeRule rule;
        rule.butterfly_wings = wings;
        return only_run("vtk", mesh, Scheme::ModifiedButterfly, rule);
    };
    for (const char* name : {"icosahedron", "open-patch", "fan-5", "torus"}) {
        const auto r = run(datasets::bundled_mesh(name), ButterflyWings::OtherFaceVertex);
        EXPECT_EQ(r.verdict, Verdict::Agree) << name << ": " << r.explanation;
    }
    EXPECT_EQ(run(datasets::bundled_mesh("open-patch"), ButterflyWings::Reflected).divergence_class, DivergenceClass::WingRule);
    for (const char* name : {"single-triangle", "holes"}) {
        const auto r = run(datasets::edge_case(name).mesh, ButterflyWings::OtherFaceVertex);
        EXPECT_EQ(r.divergence_class, DivergenceClass::ShortBoundaryLoop) << name << ": " << r.explanation;
        EXPECT_NE(r.explanation.find("boundary edges on boundary loops of three edges differ"), std::string::npos) << r.explanation;
    }
}

// VTK's vtkLinearSubdivisionFilter is the midpoint scheme: each edge point the midpoint of its
// edge, stored in float (the float tier), the old vertices where they were; it refuses a
// non-manifold edge as its other filters do.
TEST(Compare, VtksLinearFilterIsTheMidpointScheme) {
    CROSSDIV_REQUIRE_LIBRARIES("vtk");
    for (const char* name : {"icosahedron", "open-patch", "fan-5", "torus"}) {
        const auto r = only_run("vtk", datasets::bundled_mesh(name), Scheme::Midpoint, {});
        EXPECT_EQ(r.verdict, Verdict::Agree) << name << ": " << r.explanation;
    }
    const auto rejected = only_run("vtk", datasets::edge_case("nonmanifold-edge-3").mesh, Scheme::Midpoint, {});
    EXPECT_EQ(rejected.outcome.status, RunStatus::Rejected) << rejected.outcome.message;
}

// OpenSubdiv's Hbr, the second implementation OpenSubdiv ships: float weights, so the float
// tier. It agrees with core under each rule it has; it splits a bowtie's centre into one vertex
// per fan (non-manifold-handling, measured against core on the split mesh); it refuses what its
// half-edges cannot hold, by face; and two triangles back to back (every vertex of valence 2),
// where its Loop loops forever in HbrVertex::AddIncidentEdge making level 2, are refused by name.
TEST(Compare, HbrIsOpenSubdivsSecondImplementationInTheFloatTier) {
    CROSSDIV_REQUIRE_LIBRARIES("hbr");
    auto run = [](const PolyMesh& mesh, Scheme scheme, const SchemeRule& rule, double timeout = 60) {
        return only_run("hbr", mesh, scheme, rule, timeout);
    };
    SchemeRule loop, loop_corners, catmark, catmark_corners;
    loop.loop = {LoopWeights::Loop, LoopBoundary::EdgeOnly};
    loop_corners.loop = {LoopWeights::Loop, LoopBoundary::EdgeAndCorner};
    catmark.catmull_clark.boundary = CatmullClarkBoundary::EdgeOnly;
    catmark_corners.catmull_clark.boundary = CatmullClarkBoundary::EdgeAndCorner;
    for (const char* name : {"icosahedron", "open-patch", "fan-5"})
        for (const SchemeRule& rule : {loop, loop_corners}) {
            const auto r = run(datasets::bundled_mesh(name), Scheme::Loop, rule);
            EXPECT_EQ(r.verdict, Verdict::Agree) << name << ": " << r.explanation;
        }
    for (const char* name : {"quad-grid", "prism-5", "quad-fan-5"})
        for (const SchemeRule& rule : {catmark, catmark_corners}) {
            const auto r = run(datasets::bundled_mesh(name), Scheme::CatmullClark, rule);
            EXPECT_EQ(r.verdict, Verdict::Agree) << name << ": " << r.explanation;
            EXPECT_GT(r.comparison.max_rel, 0.0) << name;  // float weights (1/n^2), not bit for bit
        }
    EXPECT_EQ(run(datasets::bundled_mesh("quad-grid"), Scheme::Bilinear, {}).verdict, Verdict::Agree);

    const auto bowtie = run(datasets::edge_case("bowtie").mesh, Scheme::CatmullClark, catmark);
    EXPECT_EQ(bowtie.divergence_class, DivergenceClass::NonManifoldHandling) << bowtie.explanation;
    EXPECT_NE(bowtie.explanation.find("one vertex per fan (1 vertex into 2)"), std::string::npos) << bowtie.explanation;

    const auto fin = run(datasets::edge_case("nonmanifold-edge-3").mesh, Scheme::Loop, loop);
    EXPECT_EQ(fin.outcome.status, RunStatus::Rejected);
    EXPECT_NE(fin.outcome.message.find("Hbr cannot hold face 2"), std::string::npos) << fin.outcome.message;

    // Its hang on two triangles back to back is refused before it runs, the reason naming it.
    const auto pillow = run(datasets::edge_case("valence-2").mesh, Scheme::Loop, loop, 3.0);
    EXPECT_EQ(pillow.outcome.status, RunStatus::Rejected) << pillow.outcome.message;
    EXPECT_NE(pillow.outcome.message.find("loops without end"), std::string::npos) << pillow.outcome.message;
}

TEST(Compare, IdenticalMeshesUnderAPermutationAgree) {
    const PolyMesh ours = square_pair();
    PolyMesh ref;  // reference numbers vertices 3,2,1,0 and stores faces rotated
    ref.positions = {ours.positions[3], ours.positions[2], ours.positions[1], ours.positions[0]};
    ref.add_face({1, 3, 2});  // (2, 0, 1) in our numbering: a rotation of (0, 1, 2)
    ref.add_face({0, 3, 1});  // (3, 0, 2)
    const MeshComparison c = compare_meshes(ours, ref, {3, 2, 1, 0});
    EXPECT_TRUE(c.face_sets_equal);
    EXPECT_EQ(c.ours, (TopologyCounts{4, 5, 2, 1, 1}));
    EXPECT_EQ(c.max_abs, 0.0);
    EXPECT_TRUE(c.agree());
}

TEST(Compare, DistancesAreAbsoluteAndRelativeToTheDiagonal) {
    const PolyMesh ours = square_pair();
    PolyMesh ref = ours;
    ref.positions[2].z() += 0.5;  // diagonal of our box: 5
    const MeshComparison c = compare_meshes(ours, ref, {0, 1, 2, 3}, 2);
    EXPECT_EQ(c.diagonal, 5.0);
    EXPECT_EQ(c.max_abs, 0.5);
    EXPECT_EQ(c.max_rel, 0.1);
    EXPECT_EQ(c.rms_abs, 0.25);  // sqrt(0.25 / 4)
    ASSERT_EQ(c.worst.size(), 2u);
    EXPECT_EQ(c.worst[0].ours_index, 2);
    EXPECT_EQ(c.worst[0].valence, 3);  // neighbours 0, 1, 3
    EXPECT_TRUE(c.worst[0].boundary);
    EXPECT_FALSE(c.agree());
}

TEST(Compare, FlippedDiagonalIsATopologyDifference) {
    const PolyMesh ours = square_pair();
    PolyMesh ref = ours;
    ref.face_vertices = {0, 1, 3, 1, 2, 3};
    const MeshComparison c = compare_meshes(ours, ref, {0, 1, 2, 3});
    EXPECT_FALSE(c.face_sets_equal);
    EXPECT_EQ(c.faces_only_in_ours, 2);
    EXPECT_EQ(c.faces_only_in_ref, 2);
    EXPECT_FALSE(c.agree());
}

TEST(Compare, NanPositionNeverAgrees) {
    const PolyMesh ours = square_pair();
    PolyMesh ref = ours;
    ref.positions[1].x() = std::nan("");
    EXPECT_FALSE(compare_meshes(ours, ref, {0, 1, 2, 3}).agree());
}

}  // namespace
}  // namespace crossdiv::verification

namespace crossdiv::verification {
namespace {

// The reach of non-manifold vertices bounds where OpenSubdiv's non-manifold rules can move a
// vertex: a 4x4 grid with one triangle reversed, refined by those rules, keeps every old
// vertex outside the reach exactly where Loop puts it on the grid as it should be (Loop's
// positions do not depend on orientation); inside, some move.
TEST(Compare, NonManifoldRulesMoveOnlyVerticesTheirReachMarks) {
    const PolyMesh reversed = datasets::edge_case("inconsistent-orientation").mesh;
    PolyMesh fixed = reversed;
    std::swap(fixed.face_vertices[static_cast<size_t>(fixed.face_start[10]) + 1],
              fixed.face_vertices[static_cast<size_t>(fixed.face_start[10]) + 2]);
    const adapters::LevelTrace levels = core_implementation().refine(reversed, {Scheme::Loop, SchemeRule{}, 2});
    const PolyMesh manifold = core_implementation().refine_last(fixed, {Scheme::Loop, SchemeRule{}, 2});
    const std::vector<char> reach = nonmanifold_reach(level_view(levels));
    ASSERT_EQ(reach.size(), levels.back().positions.size());
    int outside = 0, moved_inside = 0;
    for (int v = 0; v < reversed.num_vertices(); ++v) {  // old vertices keep their index in both
        if (!reach[static_cast<size_t>(v)]) {
            ++outside;
            EXPECT_EQ(levels.back().positions[v], manifold.positions[v]) << "vertex " << v;
        } else {
            moved_inside += levels.back().positions[v] != manifold.positions[v];
        }
    }
    EXPECT_GT(outside, 0);
    EXPECT_GT(moved_inside, 0);
    EXPECT_TRUE(nonmanifold_reach(level_view(core_implementation().refine(fixed, {Scheme::Loop, SchemeRule{}, 2}))).empty());
}

/// Vertex 0 (X) in three faces: a = (1 2 0 3) and c = (2 7 4 0) on either side of (3 0 4 5 0 6),
/// which names X twice, not in a row. Across X's edges 0-2, 0-3 and 0-4 the three faces close a
/// fan; the corner (5 0 6) of the middle face is a second fan with two boundary edges. Shrunk
/// from a Sweet Home 3D model (pedestrianRailing1.obj); `far_quad` adds a quad far away.
PolyMesh fan_walk_mesh(bool far_quad) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0),  Vec3(-2, 2, 0), Vec3(0, 2, 0),  Vec3(2, 0, 0),
                   Vec3(0, -2, 1), Vec3(1, -1, -1), Vec3(-1, -1, -1), Vec3(-2, 0, 0.5)};
    m.add_face({1, 2, 0, 3});
    m.add_face({3, 0, 4, 5, 0, 6});
    m.add_face({2, 7, 4, 0});
    if (far_quad) {
        for (const Vec3& p : {Vec3(20, 0, 0), Vec3(22, 0, 0), Vec3(22, 2, 1), Vec3(20, 2, 0)}) m.positions.push_back(p);
        m.add_face({8, 9, 10, 11});
    }
    return m;
}

SchemeRule edge_only() {
    SchemeRule r;
    r.catmull_clark.boundary = CatmullClarkBoundary::EdgeOnly;
    return r;
}

TEST(FanWalk, FarsWalkTakesTheTwoFansOfAVertexAFaceNamesTwiceForOne) {
    // Far's walk (orderVertexFacesAndEdges) starts at X's last boundary edge, 0-6, in the
    // middle face, but enters that face at X's first corner; it counts five edges by taking
    // 0-3 twice and never 5-0, so X is manifold to Far. Core finds two fans: a corner.
    EXPECT_EQ(opensubdiv_walk_accepted_vertices(fan_walk_mesh(false)), (std::vector<int>{0}));
    EXPECT_EQ(nonmanifold_vertices(fan_walk_mesh(false)), (std::vector<int>{0}));
    // A bowtie: Far's walk fails (4 edges, 2 faces), as core's fans say; and a vertex ending a
    // non-manifold edge is Far's by the edge, never by the walk.
    PolyMesh bowtie;
    bowtie.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)};
    bowtie.add_face({0, 1, 2});
    bowtie.add_face({0, 3, 4});
    EXPECT_EQ(nonmanifold_vertices(bowtie), (std::vector<int>{0}));
    EXPECT_TRUE(opensubdiv_walk_accepted_vertices(bowtie).empty());
    PolyMesh repeated;
    repeated.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    repeated.add_face({1, 2, 1});
    EXPECT_TRUE(opensubdiv_walk_accepted_vertices(repeated).empty());
    EXPECT_TRUE(opensubdiv_walk_accepted_vertices(datasets::bundled_mesh("quad-cube")).empty());
}

TEST(FanWalk, OpenSubdivRefinesTheVertexByTheRingItsWalkMade) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv");
    // Far's ring at X: edges 0-6, 0-3, 0-2, 0-4, 0-3 and faces middle, a, c, middle. Its one
    // sharp edge (0-6; 5-0 is not in the ring) makes X a dart, the smooth mask of valence 4
    // (its faces): 1/2 X, 1/16 of each of the first four edges' other ends and of each face
    // point, the middle face's twice.
    const PolyMesh m = fan_walk_mesh(false);
    const PolyMesh far = find_implementation("opensubdiv").refine_last(m, {Scheme::CatmullClark, edge_only(), 1});
    auto face_point = [&](int f) {
        Vec3 sum = Vec3::Zero();
        for (int k = 0; k < m.face_size(f); ++k) sum += m.positions[static_cast<size_t>(m.face(f)[k])];
        return Vec3(sum / m.face_size(f));
    };
    const std::vector<Vec3>& p = m.positions;
    const Vec3 ring = 0.5 * p[0] + (p[6] + p[3] + p[2] + p[4]) / 16 + (2 * face_point(1) + face_point(0) + face_point(2)) / 16;
    EXPECT_LT((far.positions[0] - ring).norm(), 1e-15);
    // Core keeps it (a corner); the comparison names Far's walk.
    RefinementRequest req;
    req.scheme = Scheme::CatmullClark;
    req.rule.catmull_clark.boundary = CatmullClarkBoundary::EdgeOnly;
    req.levels = 2;
    req.references = {"opensubdiv"};
    const RefinementComparison c = compare_refinement(fan_walk_mesh(true), "fan-walk", req);
    ASSERT_EQ(c.runs.size(), 1u);
    EXPECT_EQ(c.runs[0].verdict, Verdict::Diverge);
    EXPECT_EQ(c.runs[0].divergence_class, DivergenceClass::FanWalk) << c.runs[0].explanation;
    EXPECT_NE(c.runs[0].explanation.find("input vertex 0 "), std::string::npos) << c.runs[0].explanation;
}

TEST(FanWalk, ADifferenceOutsideTheWalksReachIsNotNamedByIt) {
    // The quad far away is outside what X reaches in two levels; a vertex moved there leaves
    // the difference unexplained even though X's reach differs too.
    const PolyMesh m = fan_walk_mesh(true);
    const adapters::LevelTrace levels = core_implementation().refine(m, {Scheme::CatmullClark, edge_only(), 2});
    const std::vector<int> accepted = opensubdiv_walk_accepted_vertices(m);
    const std::vector<char> reach = reach_of(level_view(levels), accepted);
    ASSERT_EQ(reach.size(), levels.back().positions.size());
    EXPECT_FALSE(reach[8]);  // the far quad's first corner
    EXPECT_TRUE(reach[0]);
    PolyMesh moved = levels.back();
    std::vector<int> identity(static_cast<size_t>(moved.num_vertices()));
    for (int v = 0; v < moved.num_vertices(); ++v) identity[static_cast<size_t>(v)] = v;
    moved.positions[0] += Vec3(0.1, 0, 0);
    EXPECT_TRUE(fan_walk_handling(reach, accepted, levels.back(), moved, identity, 1e-12, "opensubdiv", 0.1));
    moved.positions[8] += Vec3(0.1, 0, 0);
    EXPECT_FALSE(fan_walk_handling(reach, accepted, levels.back(), moved, identity, 1e-12, "opensubdiv", 0.1));
    EXPECT_FALSE(fan_walk_handling(reach, {}, levels.back(), levels.back(), identity, 1e-12, "opensubdiv", 0));
}

}  // namespace
}  // namespace crossdiv::verification

namespace crossdiv::verification {
namespace {

// A face listed from any corner has one canonical start, also when it names its least
// vertex twice: (0 0 1) from each corner, and (0 2 0 1) whose two 0s start different lists.
TEST(Compare, TheFloatTierCountsAFacePointsSumOfCorners) {
    // A face point sums every corner of its face: a 184-gon's sums 184 terms, more than any
    // vertex's stencil around its valence 2, and the float tier's n is 183.
    PolyMesh gon;
    std::vector<int> corners;
    for (int i = 0; i < 184; ++i) {
        const double a = 2 * std::numbers::pi * i / 184;
        gon.positions.push_back(Vec3(std::cos(a), std::sin(a), 0));
        corners.push_back(i);
    }
    gon.add_face(corners);
    EXPECT_EQ(max_valence(gon), 2);
    EXPECT_EQ(longest_float_sum(gon), 183);
    // A quad cube's vertices have valence 3, its faces 4 corners: 3 either way. An octahedron's
    // valence 4 exceeds its triangles' 2.
    EXPECT_EQ(longest_float_sum(datasets::bundled_mesh("quad-cube")), 3);
    EXPECT_EQ(longest_float_sum(datasets::bundled_mesh("octahedron")), 4);
    // The tier at n = 183, 2 levels: 64 + 92.5 * 2 = 249 float ulps of the largest coordinate.
    const double ulp = std::nextafter(1.0f, 2.0f) - 1.0f;
    EXPECT_DOUBLE_EQ(agreement_tolerance(gon, true, 0, longest_float_sum(gon), 2), 249 * ulp / bounding_box_diagonal(gon.positions));
}

TEST(Compare, FacesJoinedToTheOtherOfTwoVerticesCloserThanTheRoundingAreRounding) {
    // Two quads; core's vertex 4 lies 1e-7 from vertex 1 (a degenerate sliver's corners). The
    // reference (within 1e-8 of each place) joins each quad to the other of the two: by
    // position nobody can tell them apart at a rounding of 1e-6 of the diagonal (2.2e-6).
    PolyMesh ours;
    ours.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(1 + 1e-7, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0)};
    ours.add_face({0, 1, 2, 3});
    ours.add_face({4, 5, 6, 2});
    PolyMesh ref = ours;
    for (Vec3& p : ref.positions) p.y() += 1e-8;
    ref.face_vertices = {0, 4, 2, 3, 1, 5, 6, 2};
    const std::optional<Classification> c = rounding_among_near_vertices(ours, ref, 1e-6);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->cls, DivergenceClass::Rounding);
    EXPECT_NE(c->explanation.find("; 2 of core's vertices have another within that distance"), std::string::npos) << c->explanation;
    // Nothing to confuse at a rounding of 1e-9: no class.
    EXPECT_FALSE(rounding_among_near_vertices(ours, ref, 1e-9).has_value());
    // Another face (a quad's corners in another cycle) is not rounding.
    PolyMesh other = ref;
    other.face_vertices = {0, 4, 3, 2, 1, 5, 6, 2};
    EXPECT_FALSE(rounding_among_near_vertices(ours, other, 1e-6).has_value());
    // Nor a vertex farther than the rounding from every one of core's.
    PolyMesh moved = ref;
    moved.positions[5].x() += 1e-3;
    EXPECT_FALSE(rounding_among_near_vertices(ours, moved, 1e-6).has_value());
    // Nor a face joined to a vertex farther than the rounding from the corner it stands for,
    // though every vertex is near one of core's (vertex 0 moved onto the two).
    PolyMesh merged = ref;
    merged.positions[0] = Vec3(1 + 5e-8, 0, 0);
    EXPECT_FALSE(rounding_among_near_vertices(ours, merged, 1e-6).has_value());
}

TEST(Compare, AFaceHasOneLeastRotationFromEveryCorner) {
    for (const std::vector<int>& face : {std::vector<int>{0, 0, 1}, std::vector<int>{0, 2, 0, 1}, std::vector<int>{5, 3, 9}})
        for (size_t r = 0; r < face.size(); ++r) {
            std::vector<int> listed = face;
            std::rotate(listed.begin(), listed.begin() + static_cast<std::ptrdiff_t>(r), listed.end());
            std::rotate(listed.begin(), listed.begin() + static_cast<std::ptrdiff_t>(least_rotation(listed)), listed.end());
            std::vector<int> least = face;
            std::rotate(least.begin(), least.begin() + static_cast<std::ptrdiff_t>(least_rotation(least)), least.end());
            EXPECT_EQ(listed, least);
        }
    EXPECT_EQ(least_rotation(std::vector<int>{0, 2, 0, 1}), 2u);  // (0 1 0 2) < (0 2 0 1)
}

}  // namespace
}  // namespace crossdiv::verification
