// Recovering which reference vertex is which of ours, when the reference renumbers.
#include <gtest/gtest.h>

#include "library_guard.h"

#include <algorithm>
#include <numeric>
#include <random>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

/// Core's levels 0..levels of `scheme` (default rule) on `mesh`.
adapters::LevelTrace refine(Scheme scheme, const PolyMesh& mesh, int levels) {
    return core_implementation().refine(mesh, {scheme, SchemeRule{}, levels});
}

/// Renumbers the new vertices of every level (old ones stay first, as the libraries do) and
/// reverses each level's face order; `last_perm[our index]` is the reference's index.
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
        PolyMesh m;
        m.positions.resize(t[l].positions.size());
        for (int v = 0; v < n; ++v) m.positions[perm[v]] = t[l].positions[v];
        for (int f = t[l].num_faces() - 1; f >= 0; --f) {
            const int* c = t[l].face(f);
            std::vector<int> face;
            for (int k = 0; k < t[l].face_size(f); ++k) face.push_back(perm[c[k]]);
            std::rotate(face.begin(), face.begin() + f % face.size(), face.end());  // any first corner
            m.add_face(face);
        }
        t[l] = m;
        prev_perm = perm;
    }
    last_perm = prev_perm;
    return t;
}

void expect_recovered(const adapters::LevelTrace& ours, unsigned seed) {
    std::vector<int> perm;
    const adapters::LevelTrace ref = shuffle_new_vertices(ours, seed, perm);
    const Correspondence c = match_by_provenance(level_view(ours), ref);
    ASSERT_EQ(c.method, MatchMethod::Topology) << c.note;
    for (size_t v = 0; v < perm.size(); ++v) EXPECT_EQ(c.ref_to_ours[perm[v]], static_cast<int>(v)) << "our vertex " << v;
}

TEST(Correspondence, OurOwnNumberingIsOrder) {
    const Correspondence c =
        match_refinement(level_view(refine(Scheme::Loop, datasets::bundled_mesh("open-patch"), 2)),
                         refine(Scheme::Loop, datasets::bundled_mesh("open-patch"), 2));
    EXPECT_EQ(c.method, MatchMethod::Order) << c.note;
}

TEST(Correspondence, ShuffledNewVerticesAreRecoveredFromProvenance) {
    expect_recovered(refine(Scheme::Loop, datasets::bundled_mesh("cube-asymmetric"), 3), 7);
    expect_recovered(refine(Scheme::CatmullClark, datasets::bundled_mesh("cube-asymmetric"), 2), 8);
    expect_recovered(refine(Scheme::Butterfly, datasets::bundled_mesh("open-patch"), 2), 9);
}

// The pillow (two triangles back to back): from level 1 on, pairs of distinct edges share
// both ends, so their edge points have the same two old neighbours; only the parent face
// tells them apart. At level 2: 18 vertices, 6 of them edge points of such pairs.
TEST(Correspondence, PillowEdgesWithTheSameEndsAreToldApartByTheirFaces) {
    const adapters::LevelTrace ours = refine(Scheme::Loop, datasets::edge_case("valence-2").mesh, 3);
    ASSERT_EQ(ours[2].num_vertices(), 18);
    for (unsigned seed : {1u, 2u, 3u}) expect_recovered(ours, seed);
}

// Two quads back to back: their face points coincide (both at the centroid), so positions
// cannot tell them apart; the orientation of the parent face does.
TEST(Correspondence, BackToBackQuadsAreMatchedByOrientation) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    m.add_face({0, 1, 2, 3});
    m.add_face({3, 2, 1, 0});
    const adapters::LevelTrace ours = refine(Scheme::CatmullClark, m, 3);
    ASSERT_EQ(ours[1].num_vertices(), 10);
    ASSERT_EQ(ours[1].positions[4], ours[1].positions[5]);  // the two face points coincide
    EXPECT_EQ(match_nearest(ours.back().positions, ours.back().positions).method, MatchMethod::None);
    for (unsigned seed : {4u, 5u}) expect_recovered(ours, seed);
}

// A face listed twice: the copies share their edges, so at level 1 every vertex has its own
// provenance; from level 2 on the edges inside each copy are apart (as OpenSubdiv keeps
// them) and their points are told apart only by the symmetry that swaps the copies, which
// also makes them coincide: paired in order, and the positions agree exactly.
TEST(Correspondence, TheCopiesOfADuplicateFaceArePairedBySymmetry) {
    for (auto [scheme, name] : {std::pair{Scheme::CatmullClark, "cube-asymmetric"}, std::pair{Scheme::Loop, "icosahedron"}}) {
        PolyMesh m = datasets::bundled_mesh(name);
        m.add_face(std::vector<int>(m.face(0), m.face(0) + m.face_size(0)));
        const adapters::LevelTrace ours = refine(scheme, m, 3);
        std::vector<int> perm;
        const adapters::LevelTrace ref = shuffle_new_vertices(ours, 11, perm);
        const Correspondence c = match_by_provenance(level_view(ours), ref);
        ASSERT_EQ(c.method, MatchMethod::Topology) << c.note;
        EXPECT_NE(c.note.find("paired in order"), std::string::npos) << c.note;
        for (size_t v = 0; v < c.ref_to_ours.size(); ++v)
            EXPECT_EQ(ref.back().positions[v], ours.back().positions[c.ref_to_ours[v]]) << "reference vertex " << v;
    }
}

TEST(Correspondence, FallsBackToPositionsWhenOldVerticesAreMoved) {
    const adapters::LevelTrace ours = refine(Scheme::Loop, datasets::bundled_mesh("icosahedron"), 1);
    adapters::LevelTrace ref = ours;
    // Swap two old vertices at level 1: old-vertices-first no longer holds topologically.
    std::swap(ref[1].positions[0], ref[1].positions[12]);
    for (int& v : ref[1].face_vertices) v = v == 0 ? 12 : v == 12 ? 0 : v;
    const Correspondence c = match_refinement(level_view(ours), ref);
    EXPECT_EQ(c.method, MatchMethod::Nearest);
    EXPECT_NE(c.note.find("matching by provenance failed (level 1"), std::string::npos) << c.note;
    EXPECT_EQ(c.ref_to_ours[0], 12);
    EXPECT_EQ(c.ref_to_ours[12], 0);
}

TEST(Correspondence, CopiesOfAVertexAtOnePlaceAreToldApartByTheirFaces) {
    // Two quads cut open along their shared edge: vertices 1 and 4, 2 and 7 are copies at one
    // place. The reference numbers the copies the other way round; only its faces tell which
    // copy is which (by position either would do, and the wrong one breaks both faces).
    PolyMesh ours;
    ours.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
                      Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0)};
    ours.add_face({0, 1, 2, 3});
    ours.add_face({4, 5, 6, 7});
    PolyMesh ref;
    ref.positions = ours.positions;  // the copies coincide: the swapped numbering moves nothing
    ref.add_face({0, 4, 7, 3});
    ref.add_face({1, 5, 6, 2});
    const Correspondence c = match_nearest_and_faces(ours, ref);
    ASSERT_EQ(c.method, MatchMethod::NearestAndFaces) << c.note;
    EXPECT_EQ(c.ref_to_ours, (std::vector<int>{0, 4, 7, 3, 1, 5, 6, 2}));
    // Copies no face uses are paired by position, each with one of ours.
    ours.positions.push_back(Vec3(5, 5, 5));
    ours.positions.push_back(Vec3(5, 5, 5));
    ref.positions = ours.positions;
    const Correspondence isolated = match_nearest_and_faces(ours, ref);
    ASSERT_EQ(isolated.method, MatchMethod::NearestAndFaces) << isolated.note;
    EXPECT_EQ(isolated.ref_to_ours[8] + isolated.ref_to_ours[9], 17);
}

TEST(Correspondence, ATriangleAndItsReversedCopyAtOnePlaceAreToldApartByTheirCornersOrder) {
    // A double-sided triangle as real models have them: vertices 0 1 2 and their copies 3 4 5,
    // the copy's face reversed. Every corner has two of ours at its place and no edge is matched
    // to start from: only the corners' cyclic order tells the face from its reversed copy.
    PolyMesh ours;
    ours.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    ours.add_face({0, 1, 2});
    ours.add_face({3, 5, 4});
    // The reference numbers the copies otherwise (its vertex i is our vertex perm[i]) and lists
    // its faces from another corner.
    const std::vector<int> perm = {4, 3, 0, 2, 5, 1};
    PolyMesh ref;
    ref.positions.resize(6);
    for (int i = 0; i < 6; ++i) ref.positions[i] = ours.positions[perm[i]];
    const auto ref_of = [&](int ours_vertex) { return static_cast<int>(std::find(perm.begin(), perm.end(), ours_vertex) - perm.begin()); };
    ref.add_face({ref_of(5), ref_of(4), ref_of(3)});
    ref.add_face({ref_of(1), ref_of(2), ref_of(0)});
    const Correspondence c = match_nearest_and_faces(ours, ref);
    ASSERT_EQ(c.method, MatchMethod::NearestAndFaces) << c.note;
    EXPECT_EQ(c.ref_to_ours, perm);
    // A float reference, and our copies 1e-7 apart (a model's two overlapping surfaces), which
    // a float cannot tell apart: its rounding (here 0.8e-7 towards the other copy) puts each of
    // its vertices nearer our other copy. At the default copy distance that one-to-one match by
    // position is taken, every copy swapped; at the float tolerance the faces decide.
    for (int i = 3; i < 6; ++i) ours.positions[i] += Vec3(1e-7, 0, 0);
    for (int i = 0; i < 6; ++i) ref.positions[i] = ours.positions[perm[i]] + Vec3(perm[i] < 3 ? 0.8e-7 : -0.8e-7, 0, 0);
    const Correspondence in_float = match_nearest_and_faces(ours, ref, 1e-6);
    ASSERT_EQ(in_float.method, MatchMethod::NearestAndFaces) << in_float.note;
    EXPECT_EQ(in_float.ref_to_ours, perm);
    EXPECT_NE(match_nearest_and_faces(ours, ref).ref_to_ours, perm);
}

/// A birth in terms that do not depend on how the level numbers its edges and its copies of
/// a face: a vertex, an edge's two ends in order, a face's corner cycle from its least rotation.
std::vector<int> normal_form(const VertexBirth& b, const PolyMesh& coarse) {
    switch (b.kind) {
        case VertexBirth::Kind::Vertex: return {0, b.a};
        case VertexBirth::Kind::Edge: return {1, std::min(b.a, b.b), std::max(b.a, b.b)};
        case VertexBirth::Kind::Face: {
            std::vector<int> cycle(coarse.face(b.a), coarse.face(b.a) + coarse.face_size(b.a));
            std::rotate(cycle.begin(), cycle.begin() + static_cast<long>(least_rotation(cycle)), cycle.end());
            cycle.insert(cycle.begin(), 2);
            return cycle;
        }
    }
    return {};
}

// The provenance this testbed reads off a refined level's faces (primal_births, the reading
// match_by_provenance makes of every reference) is the provenance Far itself records: its
// child queries, on every level of Loop, Catmull-Clark and bilinear over the catalog and every
// edge case, manifold or not (bowties, fins, duplicate faces, a vertex named twice).
TEST(Correspondence, BirthsReadOffTheFacesAreFarsOwn) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv");
    const Implementation& osd = find_implementation("opensubdiv");
    std::vector<std::pair<std::string, PolyMesh>> inputs;
    for (const auto& b : datasets::catalog_meshes()) inputs.emplace_back(b.name, b.mesh);
    for (const auto& e : datasets::edge_cases()) inputs.emplace_back(e.name, e.mesh);
    for (const auto& e : datasets::polygon_edge_cases()) inputs.emplace_back(e.name, e.mesh);
    int levels_read = 0;
    for (const Scheme scheme : {Scheme::Loop, Scheme::CatmullClark, Scheme::Bilinear})
        for (const auto& [name, mesh] : inputs) {
            if (!mesh.creases.empty() || (traits(scheme).triangles && !mesh.all_triangles())) continue;
            SCOPED_TRACE(std::string(to_string(scheme)) + " " + name);
            const Refinement far = osd.refine_with_provenance(mesh, {scheme, SchemeRule{}, 2});
            ASSERT_EQ(far.births.size(), 2u);
            for (size_t l = 1; l <= 2; ++l) {
                const PolyMesh& coarse = far.levels[l - 1];
                const std::vector<VertexBirth> read = primal_births(coarse, far.levels[l]);
                ASSERT_EQ(read.size(), far.births[l - 1].size()) << "level " << l;
                for (size_t v = 0; v < read.size(); ++v)
                    ASSERT_EQ(normal_form(read[v], coarse), normal_form(far.births[l - 1][v], coarse)) << "level " << l << " vertex " << v;
                ++levels_read;
            }
        }
    EXPECT_GT(levels_read, 150);
}

TEST(Correspondence, NearestRefusesANonBijection) {
    const std::vector<Vec3> ours = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
    const std::vector<Vec3> ref = {Vec3(0.1, 0, 0), Vec3(0.2, 0, 0)};
    EXPECT_EQ(match_nearest(ours, ref).method, MatchMethod::None);
}

}  // namespace
}  // namespace crossdiv::verification
