// Recovering which reference vertex is which of ours, when the reference renumbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/correspondence.h"

namespace crossdiv::verification {
namespace {

constexpr LoopOptions kLoop{LoopWeights::Loop, LoopBoundary::EdgeOnly};

struct Ours {
    LoopRefiner refiner;
    std::vector<std::vector<VertexOrigin>> origins;
    adapters::LevelTrace as_trace;  // our own levels, as a reference would return them
};

Ours refine(const std::string& name, int levels) {
    Ours o{LoopRefiner(to_tri_mesh(datasets::bundled_mesh(name)), kLoop), {}, {}};
    o.refiner.refine(levels);
    for (int l = 0; l <= levels; ++l) {
        if (l > 0) o.origins.push_back(o.refiner.origins(l));
        o.as_trace.push_back(to_poly_mesh(o.refiner.mesh(l)));
    }
    return o;
}

/// Renumbers the new vertices of every level (old ones stay first, as the libraries do).
adapters::LevelTrace shuffle_new_vertices(adapters::LevelTrace t, unsigned seed, std::vector<int>& last_perm) {
    std::mt19937 rng(seed);
    std::vector<int> prev_perm(t[0].positions.size());
    std::iota(prev_perm.begin(), prev_perm.end(), 0);
    for (size_t l = 1; l < t.size(); ++l) {
        const int n_old = t[l - 1].num_vertices(), n = t[l].num_vertices();
        std::vector<int> perm(n);  // perm[our index] = reference index
        for (int v = 0; v < n_old; ++v) perm[v] = prev_perm[v];
        std::vector<int> fresh(n - n_old);
        std::iota(fresh.begin(), fresh.end(), n_old);
        std::shuffle(fresh.begin(), fresh.end(), rng);
        for (int v = n_old; v < n; ++v) perm[v] = fresh[v - n_old];
        PolyMesh m = t[l];
        for (int v = 0; v < n; ++v) m.positions[perm[v]] = t[l].positions[v];
        for (int& v : m.face_vertices) v = perm[v];
        t[l] = m;
        prev_perm = perm;
    }
    last_perm = prev_perm;
    return t;
}

TEST(Correspondence, OurOwnNumberingIsOrder) {
    const Ours o = refine("open-patch", 2);
    const Correspondence c =
        match_loop_refinement(o.origins, o.refiner.mesh(0).positions, o.as_trace, o.refiner.mesh(2).positions);
    EXPECT_EQ(c.method, MatchMethod::Order) << c.note;
}

TEST(Correspondence, ShuffledNewVerticesAreRecoveredFromTopology) {
    const Ours o = refine("cube-asymmetric", 3);
    std::vector<int> perm;
    const adapters::LevelTrace ref = shuffle_new_vertices(o.as_trace, 7, perm);
    const Correspondence c =
        match_loop_refinement(o.origins, o.refiner.mesh(0).positions, ref, o.refiner.mesh(3).positions);
    ASSERT_EQ(c.method, MatchMethod::Topology) << c.note;
    for (size_t ours = 0; ours < perm.size(); ++ours) EXPECT_EQ(c.ref_to_ours[perm[ours]], static_cast<int>(ours));
}

TEST(Correspondence, FallsBackToNearestWhenOldVerticesAreMoved) {
    const Ours o = refine("icosahedron", 1);
    adapters::LevelTrace ref = o.as_trace;
    // Swap two old vertices at level 1: old-vertices-first no longer holds topologically.
    std::swap(ref[1].positions[0], ref[1].positions[12]);
    for (int& v : ref[1].face_vertices) v = v == 0 ? 12 : v == 12 ? 0 : v;
    const Correspondence c =
        match_loop_refinement(o.origins, o.refiner.mesh(0).positions, ref, o.refiner.mesh(1).positions);
    EXPECT_EQ(c.method, MatchMethod::Nearest);
    EXPECT_NE(c.note.find("topological matching failed (level 1"), std::string::npos) << c.note;
    EXPECT_EQ(c.ref_to_ours[0], 12);
    EXPECT_EQ(c.ref_to_ours[12], 0);
}

TEST(Correspondence, NearestRefusesANonBijection) {
    const std::vector<Vec3> ours = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
    const std::vector<Vec3> ref = {Vec3(0.1, 0, 0), Vec3(0.2, 0, 0)};
    EXPECT_EQ(match_nearest(ours, ref).method, MatchMethod::None);
}

}  // namespace
}  // namespace crossdiv::verification
