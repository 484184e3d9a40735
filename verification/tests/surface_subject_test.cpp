// A program's tessellated surface in core's place: the counts the verdict rests on (faces that
// turn against their normals, boundary edges once welded) on meshes small enough to count by
// hand, and the convention a subject follows when core offers several.
#include <gtest/gtest.h>

#include "crossdiv/verification/comparisons/surface_subject.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

PolyMesh poly(std::vector<Vec3> positions, const std::vector<std::vector<int>>& faces) {
    PolyMesh m;
    m.positions = std::move(positions);
    for (const auto& f : faces) {
        m.face_vertices.insert(m.face_vertices.end(), f.begin(), f.end());
        m.face_start.push_back(static_cast<int>(m.face_vertices.size()));
    }
    return m;
}

/// A tetrahedron, faces counterclockwise seen from outside.
PolyMesh tetrahedron() {
    return poly({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}, {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}});
}

TEST(SurfaceSubjectCounts, BoundaryEdgesAfterWelding) {
    EXPECT_EQ(welded_boundary_edges(tetrahedron(), 1e-9), 0);
    PolyMesh open = tetrahedron();
    open.face_vertices.resize(9);
    open.face_start.pop_back();
    EXPECT_EQ(welded_boundary_edges(open, 1e-9), 3);  // the dropped face's three edges
    // A unit square as two triangles written unwelded (six vertices): its four sides, once the
    // diagonal's two copies are welded; unwelded, all six edges are boundary.
    const PolyMesh square = poly({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(welded_boundary_edges(square, 1e-9), 4);
    EXPECT_EQ(welded_boundary_edges(square, 0), 6);  // no tolerance, no welding
    // A triangle welding collapses (two corners at a pole) has no edges: the fan around the
    // pole closes, as it does in core's welded surface.
    const PolyMesh pole = poly({{0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(welded_boundary_edges(pole, 1e-9), 3);
}

TEST(SurfaceSubjectCounts, FacesAgainstTheirNormals) {
    const PolyMesh t = poly({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    const std::vector<Vec3> up(3, Vec3::UnitZ()), down(3, -Vec3::UnitZ());
    EXPECT_EQ(faces_against_normals(t, up, 1e-12), 0);
    EXPECT_EQ(faces_against_normals(t, down, 1e-12), 1);
    // No area, no side: a collapsed triangle is not counted either way.
    const PolyMesh flat = poly({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}});
    EXPECT_EQ(faces_against_normals(flat, down, 1e-12), 0);
}

/// Any file will do as the input: the programs below write what they are told.
const std::string kAnyInput = test::kSource + "/README.md";

/// A program writing `obj` (its \n escapes decoded) whatever its input.
std::string writes(const std::string& obj) {
    return "python3 -c 'import sys; open(sys.argv[2], \"w\").write(sys.argv[3].encode().decode(\"unicode_escape\"))' {in} {out} '" +
           obj + "'";
}

/// Core's unit square in the xy-plane (normals +z), welded as two triangles, under `name`.
SurfaceSamples square_samples(const std::string& name, double z) {
    SurfaceSamples s;
    s.convention = name;
    s.positions = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {0, 1, z}};
    s.normals.assign(4, Vec3::UnitZ());
    s.welded_vertices = 4;
    s.boundary_edges = 4;
    return s;
}

TEST(SurfaceSubjectConventions, TheOneItFollowsIsNamedAndOnlyCoresPasses) {
    const std::vector<SurfaceSamples> conventions{square_samples("flat", 0), square_samples("raised", 1)};
    const std::string square = "v 0 0 Z\\nv 1 0 Z\\nv 1 1 Z\\nv 0 1 Z\\nvn 0 0 1\\nvn 0 0 1\\nvn 0 0 1\\nvn 0 0 1\\nf 1 2 3\\nf 1 3 4\\n";
    auto at = [&](const char* z) {
        std::string s = square;
        for (size_t p; (p = s.find('Z')) != std::string::npos;) s.replace(p, 1, z);
        return s;
    };
    const SurfaceSubjectComparison own = compare_surface_subject(kAnyInput, conventions, "s", writes(at("0")), 30);
    ASSERT_EQ(own.outcome.status, RunStatus::Ok) << own.outcome.summary();
    EXPECT_EQ(own.convention, "flat");
    EXPECT_EQ(own.boundary_edges, 4);
    EXPECT_TRUE(own.passed()) << own.summary();

    const SurfaceSubjectComparison raised = compare_surface_subject(kAnyInput, conventions, "s", writes(at("1")), 30);
    EXPECT_EQ(raised.convention, "raised");
    EXPECT_FALSE(raised.positions_fit);
    EXPECT_FALSE(raised.passed());
    EXPECT_NE(raised.summary().find("positions follow raised (to 0), not core's flat (0.707 off); normals as under it"),
              std::string::npos)
        << raised.summary();

    const SurfaceSubjectComparison neither = compare_surface_subject(kAnyInput, conventions, "s", writes(at("2")), 30);
    EXPECT_EQ(neither.convention, "");
    EXPECT_FALSE(neither.passed());
}

TEST(SurfaceSubjectConventions, ACrackWhereCoresSurfaceIsClosedFails) {
    // Core's tetrahedron is closed; a subject that leaves a face out is not watertight.
    SurfaceSamples closed;
    const PolyMesh t = tetrahedron();
    closed.positions = t.positions;
    for (const Vec3& p : t.positions) closed.normals.push_back(p.normalized());
    closed.welded_vertices = 4;
    std::string obj = "v 1 1 1\\nv 1 -1 -1\\nv -1 1 -1\\nv -1 -1 1\\n";
    for (const Vec3& p : t.positions) obj += "vn " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\\n";
    const std::string faces = "f 1 2 3\\nf 1 4 2\\nf 2 4 3\\n";
    const SurfaceSubjectComparison whole =
        compare_surface_subject(kAnyInput, {&closed, 1}, "s", writes(obj + faces + "f 3 4 1\\n"), 30);
    EXPECT_EQ(whole.boundary_edges, 0);
    EXPECT_TRUE(whole.passed()) << whole.summary();
    const SurfaceSubjectComparison cracked = compare_surface_subject(kAnyInput, {&closed, 1}, "s", writes(obj + faces), 30);
    EXPECT_EQ(cracked.boundary_edges, 3);
    EXPECT_FALSE(cracked.passed());
    EXPECT_NE(cracked.summary().find("NOT watertight: 3 boundary edges where core's surface has 0"), std::string::npos)
        << cracked.summary();
}

}  // namespace
}  // namespace crossdiv::verification
