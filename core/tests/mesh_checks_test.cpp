// Each diagnostic on the smallest mesh that shows it, with the element named.
#include <gtest/gtest.h>

#include <cmath>

#include "crossdiv/mesh/disjoint_union.h"
#include "crossdiv/mesh/mesh_checks.h"

namespace crossdiv {
namespace {

PolyMesh mesh_of(std::vector<Vec3> p, std::vector<std::vector<int>> faces) {
    PolyMesh m;
    m.positions = std::move(p);
    for (const auto& f : faces) m.add_face(f);
    return m;
}

std::vector<Vec3> pyramid_points() { return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, 1)}; }

/// The one issue of `kind`, failing the test unless there is exactly one.
std::string only(const std::vector<MeshIssue>& issues, MeshIssueKind kind) {
    std::string found;
    int n = 0;
    for (const MeshIssue& i : issues)
        if (i.kind == kind) { found = i.message; ++n; }
    EXPECT_EQ(n, 1) << "issues of kind " << to_string(kind);
    return found;
}

TEST(MeshChecks, CleanMeshHasNoIssues) {
    EXPECT_TRUE(check_mesh(mesh_of(pyramid_points(), {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}})).empty());
}

TEST(MeshChecks, ARepeatedVertexInALargePolygonIsReportedOncePerValue) {
    // A 50,000-gon on a circle whose corners 7 and 49,999 are both vertex 3, and 11, 12, 13
    // all vertex 20: two repeated values, each reported once.
    PolyMesh m;
    const int n = 50'000;
    for (int i = 0; i < n; ++i) m.positions.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0);
    std::vector<int> corners(n);
    for (int i = 0; i < n; ++i) corners[i] = i;
    corners[49'999] = 3;
    corners[7] = 3;
    corners[11] = corners[12] = corners[13] = 20;
    m.add_face(corners);
    std::vector<std::string> repeated;
    for (const MeshIssue& i : check_mesh(m))
        if (i.kind == MeshIssueKind::RepeatedVertex) repeated.push_back(i.message);
    EXPECT_EQ(repeated, (std::vector<std::string>{"face 0: repeated vertex 3", "face 0: repeated vertex 20"}));
}

TEST(MeshChecks, EachIssueNamesItsElement) {
    EXPECT_EQ(only(check_mesh(mesh_of(pyramid_points(), {{0, 1, 9}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}})),
                   MeshIssueKind::IndexOutOfRange),
              "face 0: vertex index 9 out of range [0, 5)");
    EXPECT_EQ(only(check_mesh(mesh_of(pyramid_points(), {{0, 1, 1}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}})),
                   MeshIssueKind::RepeatedVertex),
              "face 0: repeated vertex 1");
    EXPECT_NE(only(check_mesh(mesh_of(pyramid_points(), {{0, 1, 4}, {1, 0, 2}, {0, 1, 3}})), MeshIssueKind::NonManifoldEdge)
                  .find("edge (0, 1) is shared by 3 faces"),
              std::string::npos);
    EXPECT_NE(only(check_mesh(mesh_of(pyramid_points(), {{0, 1, 4}, {0, 1, 2}})), MeshIssueKind::InconsistentOrientation)
                  .find("edge (0, 1): face 0 and face 1"),
              std::string::npos);
    std::vector<Vec3> bow = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)};
    EXPECT_NE(only(check_mesh(mesh_of(bow, {{0, 1, 2}, {0, 3, 4}})), MeshIssueKind::NonManifoldVertex)
                  .find("vertex 0 is non-manifold"),
              std::string::npos);
    EXPECT_EQ(only(check_mesh(mesh_of(pyramid_points(), {{0, 1, 2}, {0, 2, 3}})), MeshIssueKind::IsolatedVertex),
              "vertex 4 is used by no face");
    std::vector<Vec3> line = {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(3, 3, 3)};
    EXPECT_NE(only(check_mesh(mesh_of(line, {{0, 1, 2}})), MeshIssueKind::ZeroAreaFace).find("face 0: zero area"),
              std::string::npos);
    std::vector<Vec3> bad = pyramid_points();
    bad[3].z() = std::nan("");
    EXPECT_EQ(only(check_mesh(mesh_of(bad, {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}})),
                   MeshIssueKind::NonFiniteCoordinate),
              "vertex 3: coordinate is NaN or infinite");
}

TEST(MeshChecks, SeverityErrorsVersusWarnings) {
    for (const MeshIssue& i : check_mesh(mesh_of(pyramid_points(), {{0, 1, 2}, {0, 2, 3}})))
        EXPECT_EQ(i.severity, Severity::Warning) << i.message;
}

TEST(MeshChecks, MessagesCarryFileLinesWhenKnown) {
    PolyMesh m = mesh_of(pyramid_points(), {{0, 1, 1}});
    m.source = {"a.obj", {1, 2, 3, 4, 5}, {7}, {}, {}};
    const auto issues = check_mesh(m);
    EXPECT_EQ(only(issues, MeshIssueKind::RepeatedVertex), "face 0 (a.obj:7): repeated vertex 1");
}

TEST(MeshChecks, ThinSliverIsNotZeroArea) {
    std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1e-9, 0)};
    for (const MeshIssue& i : check_mesh(mesh_of(p, {{0, 1, 2}})))
        EXPECT_NE(i.kind, MeshIssueKind::ZeroAreaFace) << i.message;
}

TEST(DisjointUnion, RenumbersFacesAndValuesPastTheEarlierParts) {
    // A triangle with a UV per corner, then a quad with two UVs shared by its corners.
    PolyMesh a, b;
    a.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    a.add_face({0, 1, 2});
    a.face_varying.push_back({"uv", 2, {0, 0, 1, 0, 0, 1}, {0, 1, 2}});
    b.positions = {{5, 0, 0}, {6, 0, 0}, {6, 1, 0}, {5, 1, 0}};
    b.add_face({3, 2, 1, 0});
    b.face_varying.push_back({"uv", 2, {7, 7, 8, 8}, {0, 1, 0, 1}});
    const PolyMesh u = disjoint_union({a, b});
    EXPECT_EQ(u.num_vertices(), 7);
    EXPECT_EQ(u.face_start, (std::vector<int>{0, 3, 7}));
    EXPECT_EQ(u.face_vertices, (std::vector<int>{0, 1, 2, 6, 5, 4, 3}));
    EXPECT_EQ(u.positions[3], Vec3(5, 0, 0));
    ASSERT_EQ(u.face_varying.size(), 1u);
    EXPECT_EQ(u.face_varying[0].corner_values, (std::vector<int>{0, 1, 2, 3, 4, 3, 4}));
    EXPECT_EQ(u.face_varying[0].values, (std::vector<double>{0, 0, 1, 0, 0, 1, 7, 7, 8, 8}));
    // Channels that differ between the parts are dropped rather than misnumbered; colours too.
    b.face_varying[0].dimension = 1;
    b.colors.assign(4, Vec3(1, 0, 0));
    const PolyMesh v = disjoint_union({a, b});
    EXPECT_TRUE(v.face_varying.empty());
    EXPECT_TRUE(v.colors.empty());
    EXPECT_EQ(disjoint_union({}).num_faces(), 0);
}

}  // namespace
}  // namespace crossdiv
