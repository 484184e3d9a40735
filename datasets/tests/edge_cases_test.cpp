// The edge-case catalog holds what each case's one-line description promises: checked on the
// topology, not on counts alone.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "crossdiv/datasets/analytic_surfaces.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/datasets/implicit_surfaces.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/mesh_checks.h"
#include "crossdiv/mesh/tri_connectivity.h"
#include "crossdiv/mesh/tri_mesh.h"

namespace crossdiv::datasets {
namespace {

std::map<int, int> valences(const PolyMesh& m) {  // vertex -> number of distinct neighbours
    std::map<int, std::set<int>> n;
    for (int f = 0; f < m.num_faces(); ++f)
        for (int k = 0; k < m.face_size(f); ++k) {
            const int a = m.face(f)[k], b = m.face(f)[(k + 1) % m.face_size(f)];
            n[a].insert(b);
            n[b].insert(a);
        }
    std::map<int, int> v;
    for (const auto& [k, s] : n) v[k] = static_cast<int>(s.size());
    return v;
}

int euler(const PolyMesh& m) {
    std::set<std::pair<int, int>> edges;
    for (int f = 0; f < m.num_faces(); ++f)
        for (int k = 0; k < m.face_size(f); ++k) {
            const int a = m.face(f)[k], b = m.face(f)[(k + 1) % m.face_size(f)];
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    return m.num_vertices() - static_cast<int>(edges.size()) + m.num_faces();
}

int max_valence(const PolyMesh& m) {
    int best = 0;
    for (const auto& [v, n] : valences(m)) best = std::max(best, n);
    return best;
}

TEST(EdgeCases, NamesAreUniqueAndEveryCaseIsDescribed) {
    std::set<std::string> names;
    for (const EdgeCase& c : edge_cases()) {
        EXPECT_TRUE(names.insert(c.name).second) << c.name;
        EXPECT_FALSE(c.description.empty()) << c.name;
        EXPECT_EQ(c.mesh.source.file, "edgecase:" + c.name);
    }
    EXPECT_THROW(edge_case("no-such-case"), InputError);
}

TEST(EdgeCases, ValidCasesBuildAndInvalidOnesAreRefusedNamingTheElement) {
    for (const EdgeCase& c : edge_cases()) {
        const TriMesh m = to_tri_mesh(c.mesh, "test");
        if (c.valid_loop_input) {
            EXPECT_NO_THROW(build_tri_connectivity(m)) << c.name;
        } else {
            try {
                build_tri_connectivity(m);
                ADD_FAILURE() << c.name << " was accepted";
            } catch (const InputError& e) {
                const std::string what = e.what();
                EXPECT_TRUE(what.find("edge (") != std::string::npos || what.find("vertex ") != std::string::npos ||
                            what.find("face ") != std::string::npos)
                    << c.name << ": " << what;
            }
        }
    }
}

TEST(EdgeCases, FansPolesAndBoundaryFansHaveTheirValence) {
    for (int n = 3; n <= 16; ++n) EXPECT_EQ(valences(edge_case("interior-fan-" + std::to_string(n)).mesh).at(0), n);
    for (int n : {8, 64, 360}) {
        const PolyMesh m = edge_case("pole-" + std::to_string(n)).mesh;
        EXPECT_EQ(valences(m).at(0), n);
        EXPECT_EQ(euler(m), 2);  // a sphere
    }
    for (int k = 1; k <= 8; ++k) {
        const PolyMesh m = edge_case("boundary-fan-" + std::to_string(k)).mesh;
        EXPECT_EQ(m.num_faces(), k);
        EXPECT_EQ(valences(m).at(0), k + 1);  // k faces on a boundary vertex: k + 1 neighbours
    }
}

TEST(EdgeCases, GlobalTopology) {
    EXPECT_EQ(euler(edge_case("genus-3").mesh), 2 - 2 * 3);
    EXPECT_EQ(euler(edge_case("several-components").mesh), 3 * 2);
    EXPECT_EQ(euler(edge_case("valence-2").mesh), 2);
    EXPECT_EQ(max_valence(edge_case("valence-2").mesh), 2);
    // Three faces removed from a sphere: three boundary loops, Euler characteristic 2 - 3.
    EXPECT_EQ(euler(edge_case("holes").mesh), -1);
}

TEST(EdgeCases, NonManifoldEdgesCarryTheirFaceCount) {
    for (int pages : {3, 100}) {
        const PolyMesh m = edge_case("nonmanifold-edge-" + std::to_string(pages)).mesh;
        int on_edge = 0;
        for (int f = 0; f < m.num_faces(); ++f) {
            const std::set<int> vs(m.face(f), m.face(f) + 3);
            on_edge += vs.count(0) && vs.count(1);
        }
        EXPECT_EQ(on_edge, pages);
    }
}

TEST(EdgeCases, NumericTrapsAreWhereTheySayTheyAre) {
    const PolyMesh far = edge_case("far-from-origin").mesh;
    for (const Vec3& p : far.positions) EXPECT_NEAR(p.x(), 1e8, 2.0);
    const PolyMesh near = edge_case("near-coincident").mesh;
    double closest = INFINITY;
    for (int a = 0; a < near.num_vertices(); ++a)
        for (int b = a + 1; b < near.num_vertices(); ++b)
            closest = std::min(closest, (near.positions[a] - near.positions[b]).norm());
    EXPECT_NEAR(closest, 1e-12, 1e-13);
    bool zero_area = false;
    for (const MeshIssue& i : check_mesh(edge_case("zero-area-triangle").mesh))
        zero_area |= i.kind == MeshIssueKind::ZeroAreaFace;
    EXPECT_TRUE(zero_area);
}

TEST(BenchmarkMesh, IsClosedWithTheRequestedSizeAndMixedValences) {
    const PolyMesh m = benchmark_mesh(20000);
    EXPECT_EQ(m.num_faces(), 2 * 100 * 100);
    EXPECT_EQ(euler(m), 0);  // a torus
    const auto v = valences(m);
    int lo = 100, hi = 0;
    for (const auto& [k, n] : v) lo = std::min(lo, n), hi = std::max(hi, n);
    EXPECT_LE(lo, 5);
    EXPECT_GE(hi, 7);
    EXPECT_NO_THROW(build_tri_connectivity(to_tri_mesh(m, "test")));
}

}  // namespace
}  // namespace crossdiv::datasets

namespace crossdiv::datasets {
namespace {

// The icosphere: 10 4^l + 2 vertices on the unit sphere, 20 4^l faces, closed (no boundary
// vertex), valence 5 at the icosahedron's 12 vertices and 6 at every midpoint, and outward:
// its signed volume approaches 4 pi / 3 from below.
TEST(AnalyticSurfaces, IcosphereIsAClosedOutwardSphere) {
    for (int level = 0; level < 4; ++level) {
        const TriMesh m = icosphere(level);
        const int scale = 1 << (2 * level);
        ASSERT_EQ(m.num_vertices(), 10 * scale + 2);
        ASSERT_EQ(m.num_faces(), 20 * scale);
        for (const Vec3& p : m.positions) EXPECT_NEAR(p.norm(), 1.0, 4e-16);
        const TriConnectivity conn = build_tri_connectivity(m);
        std::vector<int> valence(m.num_vertices(), 0);
        for (const auto& [a, b] : conn.edge_vertices) ++valence[a], ++valence[b];
        for (int v = 0; v < m.num_vertices(); ++v) {
            EXPECT_FALSE(conn.is_boundary_vertex(v));
            EXPECT_EQ(valence[v], v < 12 ? 5 : 6) << v;
        }
        double volume = 0;
        for (const Triangle& t : m.triangles)
            volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6;
        EXPECT_GT(volume, 0.0);
        EXPECT_LT(volume, 4 * M_PI / 3);
    }
    EXPECT_THROW(icosphere(9), InputError);
}

TEST(AnalyticSurfaces, TorusVerticesLieOnTheTorus) {
    const TriMesh m = regular_torus(16, 8, 1.0, 0.25);
    ASSERT_EQ(m.num_vertices(), 128);
    for (const Vec3& p : m.positions) EXPECT_NEAR(std::hypot(std::hypot(p.x(), p.y()) - 1.0, p.z()), 0.25, 1e-15);
    EXPECT_THROW(regular_torus(16, 8, 1.0, 1.5), InputError);
}

}  // namespace
}  // namespace crossdiv::datasets

// The implicit surfaces: hand values of each function, the genus-2 tube's holes open, the
// Newton distance on the gyroid, and grids of cubic cells.
TEST(ImplicitSurfaces, HandValuesAndDistances) {
    using crossdiv::datasets::implicit_surface;
    const auto& g2 = implicit_surface("genus2");
    // At a lobe's centre (1/sqrt 2, 0, 0), L = -1/4: L^2 - 0.04 > 0, outside (a hole).
    EXPECT_NEAR(g2.f(crossdiv::Vec3(std::sqrt(0.5), 0, 0)), 0.0625 - 0.04, 1e-15);
    EXPECT_LT(g2.f(crossdiv::Vec3(0, 0, 0)), 0);  // the crossing of the figure eight is inside
    const auto& gy = implicit_surface("gyroid");
    EXPECT_EQ(gy.f(crossdiv::Vec3(0, 0, 0)), 0);
    // Near the origin the gyroid is the plane x + y + z = 0: (0, 0, d) is d / sqrt 3 from it.
    EXPECT_NEAR(crossdiv::datasets::distance_to(gy, crossdiv::Vec3(0, 0, 1e-4)), 1e-4 / std::sqrt(3.0), 1e-11);
    const auto& torus = implicit_surface("torus");
    EXPECT_DOUBLE_EQ(crossdiv::datasets::distance_to(torus, crossdiv::Vec3(1.5, 0, 0)), 0.1);
    EXPECT_THROW(implicit_surface("klein"), crossdiv::InputError);
    const crossdiv::ScalarGrid grid = crossdiv::datasets::sample(torus, 32);
    EXPECT_EQ(grid.size, (std::array<int, 3>{32, 32, 12}));  // 3.1 x 3.1 x 1.1 in cells of 0.1
    EXPECT_DOUBLE_EQ(grid.spacing.x(), grid.spacing.z());
    EXPECT_THROW(crossdiv::datasets::sample(torus, 2), crossdiv::InputError);
    const crossdiv::ScalarGrid field = crossdiv::datasets::ambiguous_field(5);
    EXPECT_EQ(field.at(0, 2, 2), 1.0);  // the shell is outside
    EXPECT_LT(std::abs(field.at(2, 2, 2)), 1.0);
}
