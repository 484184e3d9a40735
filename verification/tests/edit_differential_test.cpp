// Randomized differential testing of flip and split against OpenMesh and CGAL, and proof that
// the test can fail: a deliberately broken flip is caught and shrunk to a minimal sequence.
#include <gtest/gtest.h>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/edit_differential.h"

namespace crossdiv::verification {
namespace {

// Ten thousand random flips and splits per mesh; a thousand in a sanitizer build, where each
// operation costs about twenty times as much (the same seed: its first thousand operations).
#ifdef CROSSDIV_SANITIZED
constexpr int kOpsPerMesh = 1000;
#else
constexpr int kOpsPerMesh = 10000;
#endif
constexpr double kFlipShare = 0.75; // flips keep the mesh small enough to check fully after every operation

TriMesh bundled(const std::string& name) { return to_tri_mesh(datasets::bundled_mesh(name)); }

std::string describe(const EditRunResult& r) {
    if (!r.disagreement) return "agrees";
    const EditDisagreement& d = *r.disagreement;
    return "operation " + std::to_string(d.op_index) + " (" + to_string(d.op) + "): " + d.subject + " " + d.kind + ": " + d.detail;
}

class EditDifferential : public ::testing::TestWithParam<std::string> {};

// Closed (icosahedron, cube-asymmetric), boundary (open-patch, fan-7 with its one-ring
// boundary), genus 1 (torus): every operation, interior and boundary, against both references.
TEST_P(EditDifferential, TenThousandOperationsAgreeWithOpenMeshAndCgal) {
    const auto refs = available_edit_references();
    ASSERT_EQ(refs, (std::vector<std::string>{"openmesh", "cgal"}));
    const TriMesh base = bundled(GetParam());
    const EditRunResult r = run_edit_differential(base, random_edit_ops(20261122, kOpsPerMesh, kFlipShare), refs);
    EXPECT_EQ(describe(r), "agrees");
    EXPECT_EQ(r.ops_run, kOpsPerMesh);
    EXPECT_GT(r.flips, kOpsPerMesh / 3);       // flips really happened,
    EXPECT_GT(r.refused_flips, 0);             // refusals were compared with OpenMesh's is_flip_ok,
    EXPECT_GT(r.splits, kOpsPerMesh / 5);      // and splits grew the mesh:
    EXPECT_EQ(r.vertices, base.num_vertices() + r.splits);
}

INSTANTIATE_TEST_SUITE_P(Catalog, EditDifferential,
                         ::testing::Values("icosahedron", "cube-asymmetric", "open-patch", "fan-7", "torus"),
                         [](const auto& info) {
                             std::string n = info.param;
                             std::replace(n.begin(), n.end(), '-', '_');
                             return n;
                         });

// The test double: a flip that, once one endpoint has valence 7 or more, leaves that vertex's
// half-edge pointing at the flipped edge, which no longer leaves it.
OurEdits broken_flip() {
    OurEdits ours;
    ours.flip = [](HalfedgeMesh& m, EdgeId e) {
        const HalfedgeId h = HalfedgeMesh::halfedge(e);
        const VertexId a = m.origin(h);
        const bool trigger = m.valence(a) >= 7;
        const FlipRefusal r = m.flip(e);
        if (r == FlipRefusal::None && trigger) m.set_vertex_halfedge(a, h);
        return r;
    };
    return ours;
}

TEST(EditDifferential, BrokenFlipIsCaughtAndShrunk) {
    const TriMesh base = bundled("icosahedron");
    const auto ops = random_edit_ops(20261122, kOpsPerMesh, kFlipShare);
    const EditRunResult r = run_edit_differential(base, ops, available_edit_references(), broken_flip());
    ASSERT_TRUE(r.disagreement.has_value());
    EXPECT_EQ(r.disagreement->subject, "ours");
    EXPECT_EQ(r.disagreement->kind, "invalid");
    EXPECT_NE(r.disagreement->detail.find("vertex-link"), std::string::npos) << r.disagreement->detail;

    const ShrunkEdits s = shrink_edit_sequence(base, ops, available_edit_references(), broken_flip());
    ASSERT_FALSE(s.ops.empty());
    EXPECT_LT(s.ops.size(), static_cast<size_t>(r.disagreement->op_index + 1));
    // Valence 5 -> 7 needs two operations at one vertex before the faulty flip.
    EXPECT_LE(s.ops.size(), 6u);
    EXPECT_EQ(s.disagreement.kind, "invalid");
    EXPECT_EQ(s.resolved.back().kind, EditKind::Flip);
    std::string printed;
    for (const ResolvedEdit& op : s.resolved) printed += to_string(op) + "; ";
    RecordProperty("shrunk", printed);
    std::cout << "shrunk from " << r.disagreement->op_index + 1 << " to " << s.ops.size() << " operations: " << printed << "\n"
              << s.disagreement.detail << "\n";
    // 1-minimal: without any one of its operations the sequence passes, with the correct flip
    // it passes too.
    for (size_t skip = 0; skip < s.ops.size(); ++skip) {
        std::vector<EditOp> fewer = s.ops;
        fewer.erase(fewer.begin() + static_cast<long>(skip));
        const EditRunResult rr = run_edit_differential(base, fewer, available_edit_references(), broken_flip());
        EXPECT_FALSE(rr.disagreement && rr.disagreement->kind == "invalid" && rr.disagreement->subject == "ours") << "without op " << skip;
    }
    EXPECT_FALSE(run_edit_differential(base, s.ops, available_edit_references()).disagreement.has_value());
}

TEST(EditDifferential, ResolvedOperationsPrintAsCliArguments) {
    EXPECT_EQ(to_string(ResolvedEdit{EditKind::Flip, 3, 7}), "flip 3-7");
    EXPECT_EQ(to_string(ResolvedEdit{EditKind::Split, 12, 0}), "split 12-0");
    const auto ops = random_edit_ops(1, 1000, 0.75);
    const auto flips = std::count_if(ops.begin(), ops.end(), [](const EditOp& o) { return o.kind == EditKind::Flip; });
    EXPECT_GT(flips, 700);
    EXPECT_LT(flips, 800);
    EXPECT_EQ(random_edit_ops(1, 1000, 0.75)[999].selector, ops[999].selector);  // seeded: reproducible
}

TEST(EditDifferential, UnknownReferenceIsAnInputError) {
    EXPECT_THROW(make_edit_references(bundled("icosahedron"), {"meshlab"}), InputError);
}

}  // namespace
}  // namespace crossdiv::verification
