// Multiresolution editing of Loop surfaces: a subdivision surface decomposes into its base and
// zero details; decompose then recompose gives the input back; a rigid motion commutes with
// both; an edit of a base vertex moves only what edit_reach predicts, and with zero details
// exactly the subdivision support.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "crossdiv/error.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/subdiv/multiresolution.h"
#include "loop_test_meshes.h"
#include "test_meshes.h"
#include "test_points.h"

namespace crossdiv {
namespace {

using test::largest_difference;

using test::kLoopEdge;

/// The octahedron refined once (valences 4 and 6), and an open patch of it (a boundary).
TriMesh closed_base() { return loop_subdivide(to_tri_mesh(test::octahedron()), kLoopEdge, 1); }

std::vector<Vec3> with_detail(const LoopMultiresolution& m, const TriMesh& base, double amount, unsigned seed) {
    return test::perturbed(m.subdivide(base.positions), amount, seed);
}

TEST(Multiresolution, ASubdivisionSurfaceHasItsBaseAndNoDetail) {
    TriMesh base = closed_base();
    base.positions[3] += Vec3(0.2, -0.1, 0.3);
    const LoopMultiresolution m(base, kLoopEdge, 3);
    const MultiresolutionDecomposition d = m.decompose(m.subdivide(base.positions));
    EXPECT_LT(largest_difference(d.base, base.positions), 1e-13);
    for (const std::vector<Vec3>& level : d.details)
        for (const Vec3& x : level) EXPECT_LT(x.norm(), 1e-13);
}

TEST(Multiresolution, RecomposingTheDecompositionGivesTheInputBack) {
    for (const TriMesh& base : {closed_base(), to_tri_mesh(test::octahedron())}) {
        const LoopMultiresolution m(base, kLoopEdge, 3);
        const std::vector<Vec3> fine = with_detail(m, base, 0.05, 1);
        EXPECT_LT(largest_difference(m.recompose(m.decompose(fine)), fine), 1e-14 * 2);  // the diagonal is 2
    }
}

TEST(Multiresolution, ARigidMotionCommutes) {
    const TriMesh base = closed_base();
    const LoopMultiresolution m(base, kLoopEdge, 3);
    const std::vector<Vec3> fine = with_detail(m, base, 0.05, 2);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
    const Vec3 shift(3, -1, 2);
    std::vector<Vec3> moved = fine;
    for (Vec3& x : moved) x = r * x + shift;
    const MultiresolutionDecomposition d = m.decompose(fine), dm = m.decompose(moved);
    // The same detail coordinates (frames turn with the mesh), the base moved by the motion.
    for (size_t l = 0; l < d.details.size(); ++l) EXPECT_LT(largest_difference(d.details[l], dm.details[l]), 1e-13) << l;
    std::vector<Vec3> base_moved = d.base;
    for (Vec3& x : base_moved) x = r * x + shift;
    EXPECT_LT(largest_difference(base_moved, dm.base), 1e-13);
    EXPECT_LT(largest_difference(m.recompose(dm), moved), 1e-13);
}

TEST(Multiresolution, AnEditMovesOnlyItsReach) {
    const TriMesh base = closed_base();
    const LoopMultiresolution m(base, kLoopEdge, 3);
    for (double amount : {0.0, 0.05}) {
        const std::vector<Vec3> fine = amount > 0 ? with_detail(m, base, amount, 3) : m.subdivide(base.positions);
        MultiresolutionDecomposition d = m.decompose(fine);
        // A subdivision surface's details are rounding (1e-16); make them the zeros they stand for.
        if (amount == 0)
            for (std::vector<Vec3>& level : d.details) std::fill(level.begin(), level.end(), Vec3::Zero());
        const std::vector<Vec3> before = m.recompose(d);
        d.base[5] += Vec3(0.1, 0.2, -0.15);
        const std::vector<Vec3> after = m.recompose(d);
        const std::vector<char> support = m.edit_reach({5}, false), reach = m.edit_reach({5}, true);
        int moved = 0, outside_reach = 0, outside_support = 0, support_size = 0;
        for (size_t v = 0; v < after.size(); ++v) {
            const bool changed = after[v] != before[v];
            moved += changed;
            outside_reach += changed && !reach[v];
            outside_support += changed && !support[v];
            support_size += support[v];
        }
        EXPECT_EQ(outside_reach, 0) << amount;
        if (amount == 0) {
            // With zero details the frames do not matter: exactly the subdivision support moves.
            EXPECT_EQ(outside_support, 0);
            EXPECT_EQ(moved, support_size);
        } else {
            EXPECT_GT(outside_support, 0);  // the frames around the support turned
        }
    }
}

TEST(Multiresolution, RefusesWrongCountsAndLevels) {
    const TriMesh base = closed_base();
    EXPECT_THROW(LoopMultiresolution(base, kLoopEdge, 0), InputError);
    const LoopMultiresolution m(base, kLoopEdge, 2);
    EXPECT_THROW(m.decompose(base.positions), InputError);
    MultiresolutionDecomposition d = m.decompose(m.subdivide(base.positions));
    d.details.pop_back();
    EXPECT_THROW(m.recompose(d), InputError);
    std::vector<Vec3> nan = m.subdivide(base.positions);
    nan[7].x() = std::nan("");
    EXPECT_THROW(m.decompose(nan), InputError);
}

}  // namespace
}  // namespace crossdiv
