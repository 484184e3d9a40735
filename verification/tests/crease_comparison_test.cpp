// Creases against OpenSubdiv on the crease catalog: Loop and Catmull-Clark, uniform and
// Chaikin decay, three levels -- every run agrees to rounding, and the tags move the surface
// far more than that (so the agreement tests the sharp rules, not the smooth ones). OpenMesh
// and CGAL, which have no crease rules, refuse a tagged mesh.
#include <gtest/gtest.h>

#include "library_guard.h"

#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/datasets/bundled.h"
#include "crossdiv/verification/comparisons/crease_comparison.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/harness/correspondence.h"
#include "crossdiv/verification/harness/mesh_comparison.h"
#include "crossdiv/verification/implementations/tag_rules.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/hole_faces.h"
#ifdef CROSSDIV_HAS_OPENSUBDIV
#include "crossdiv/adapters/opensubdiv.h"
#endif

#include <sstream>

namespace crossdiv::verification {
namespace {

TEST(CreaseComparison, OpenSubdivAgreesOnEveryCreaseMesh) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv");
    // Measured: at most 1.7e-16 of the diagonal; the tags move the surface by 6.7e-3 to 0.25.
    constexpr double kTagsMatter = 1e-3;
    int runs = 0;
    for (const CreaseComparison& c : compare_crease_catalog()) {
        SCOPED_TRACE(c.input + " " + to_string(c.scheme) + " " + c.method);
        EXPECT_EQ(c.verdict, Verdict::Agree) << c.explanation << c.core_error;
        EXPECT_TRUE(c.faces_equal);
        ASSERT_EQ(c.max_rel_per_level.size(), 3u);
        for (double d : c.max_rel_per_level) EXPECT_LE(d, tolerances::kAgreementRelative);
        EXPECT_GT(c.effect_of_tags, kTagsMatter);
        ++runs;
    }
    EXPECT_EQ(runs, 36);
}

TEST(CreaseComparison, ChaikinAndUniformDecayDifferWhereSharpnessVaries) {
    // Along a crease loop of sharpness 1, 2, 3, 4 the two decays give different surfaces, and
    // OpenSubdiv agrees with each (above): the creasing method really reaches Far.
    const PolyMesh m = datasets::bundled_mesh("crease-cube-varying");
    CreaseRequest uniform, chaikin;
    chaikin.method = CreaseMethod::Chaikin;
    const CreaseComparison a = compare_creases(m, "varying", uniform), b = compare_creases(m, "varying", chaikin);
    EXPECT_NE(a.effect_of_tags, b.effect_of_tags);
}

TEST(CreaseComparison, ReferencesWithoutCreaseRulesRefuseTaggedMeshes) {
    RefinementRequest req;
    req.scheme = Scheme::CatmullClark;
    req.levels = 1;
    const RefinementComparison c = compare_refinement(datasets::bundled_mesh("crease-cube-top"), "crease-cube-top", req);
    ASSERT_TRUE(c.core_error.empty()) << c.core_error;
    for (const RefinementRun& r : c.runs) {
        SCOPED_TRACE(r.reference);
        if (r.reference == "opensubdiv" || r.reference == "hbr") {  // OpenSubdiv's two implementations
            EXPECT_EQ(r.verdict, Verdict::Agree) << r.explanation;
        } else {
            EXPECT_EQ(r.verdict, Verdict::RefRejected);
            EXPECT_NE(r.explanation.find("has no crease or hole rules"), std::string::npos) << r.explanation;
        }
    }
}

/// An n x n grid (triangulated along the diagonals when asked) as OBJ text, then `tags`.
std::string grid_obj(int n, bool triangles, const std::string& tags) {
    std::ostringstream s;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) s << "v " << i << ' ' << j << ' ' << 0.1 * ((3 * i + 5 * j) % 4) << '\n';
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1;  // OBJ counts from 1
            if (triangles)
                s << "f " << a << ' ' << a + 1 << ' ' << a + n + 2 << "\nf " << a << ' ' << a + n + 2 << ' ' << a + n + 1 << '\n';
            else
                s << "f " << a << ' ' << a + 1 << ' ' << a + n + 2 << ' ' << a + n + 1 << '\n';
        }
    return s.str() + tags;
}

PolyMesh read_text(const std::string& text) {
    std::istringstream in(text);
    return read_obj(in, "tagged.obj");
}

TEST(ShapeTags, BoundaryNoneMakesTheHolesFarMakes) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv");
#ifdef CROSSDIV_HAS_OPENSUBDIV
    // Outer ring only; a triangulation; one side sharpened by tags (its inner vertices keep
    // their faces); an inner boundary around a missing face, where faces touch the boundary
    // at a corner only.
    PolyMesh missing = read_text(grid_obj(5, false, ""));
    PolyMesh without_centre;
    without_centre.positions = missing.positions;
    for (int f = 0; f < missing.num_faces(); ++f)
        if (f != 12) without_centre.add_face(std::vector<int>(missing.face(f), missing.face(f) + 4));
    const std::vector<std::pair<PolyMesh, bool>> cases = {
        {read_text(grid_obj(4, false, "")), false},
        {read_text(grid_obj(3, true, "")), true},
        {read_text(grid_obj(4, false, "t crease 8/1/0 0 1 1 2 2 3 3 4 10\n")), false},
        {without_centre, false},
    };
    for (const auto& [mesh, loop] : cases) {
        PolyMesh ours = mesh;
        tag_boundary_faces_as_holes(ours, build_poly_connectivity(ours));
        EXPECT_EQ(ours.creases.holes, adapters::opensubdiv::boundary_none_holes(mesh, loop));
        EXPECT_FALSE(ours.creases.holes.empty());
    }
#endif
}

TEST(ShapeTags, TaggedShapeFilesRefineAlikeInCoreAndOpenSubdiv) {
    CROSSDIV_REQUIRE_LIBRARIES("opensubdiv");
    // Each file as `crossdiv subdivide --impl core|opensubdiv` reads it: tags resolved into
    // the rule, two levels, hole faces not emitted; the emitted faces must be the same set and
    // the positions agree to the agreement tolerance (measured: 1e-17 of the diagonal).
    struct Case {
        std::string name, obj;
        Scheme scheme;
        int emitted;  ///< faces after two levels, counted by hand
    };
    const std::vector<Case> cases = {
        {"two holes", grid_obj(4, false, "t hole 2/0/0 5 10\n"), Scheme::CatmullClark, 16 * 14},
        {"boundary none", grid_obj(4, false, "t interpolateboundary 1/0/0 0\n"), Scheme::CatmullClark, 16 * 4},
        {"corners and a hole", grid_obj(4, false, "t interpolateboundary 1/0/0 1\nt hole 1/0/0 6\n"),
         Scheme::CatmullClark, 16 * 15},
        {"smooth triangles", grid_obj(2, true, "t smoothtriangles 0/0/1 smooth\n"), Scheme::CatmullClark, 8 * 3 * 4},
        {"loop holes and a crease", grid_obj(4, true, "t hole 3/0/0 0 9 17\nt crease 2/1/0 6 7 2.5\n"), Scheme::Loop,
         16 * 29},
        {"loop boundary none", grid_obj(4, true, "t interpolateboundary 1/0/0 0\n"), Scheme::Loop, 16 * 8},
    };
    const Implementation& core = find_implementation("core");
    const Implementation& osd = find_implementation("opensubdiv");
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        PolyMesh mesh = read_text(c.obj);
        const TagRules rules = resolve_tag_rules(c.scheme, "", mesh);
        RefineRequest r{c.scheme, rule_from_boundary_name(c.scheme, rules.boundary), 2};
        r.rule.catmull_clark.smooth_triangles = rules.smooth_triangles;
        const PolyMesh ours = core.refine_last(mesh, r), theirs = osd.refine_last(mesh, r);
        EXPECT_EQ(without_hole_faces(ours).num_faces(), c.emitted);
        const Correspondence m = match_nearest_and_faces(ours, theirs);
        ASSERT_NE(m.method, MatchMethod::None) << m.note;
        const MeshComparison cmp = compare_meshes(ours, theirs, m.ref_to_ours, 1);
        EXPECT_TRUE(cmp.topology_equal()) << cmp.faces_only_in_ours << " only in core, " << cmp.faces_only_in_ref
                                          << " only in opensubdiv";
        EXPECT_LE(cmp.max_rel, tolerances::kAgreementRelative);
    }
    // Without the tag's rule, the smooth-triangle file differs: the tag reaches both.
    PolyMesh mesh = read_text(grid_obj(2, true, ""));
    RefineRequest plain{Scheme::CatmullClark, rule_from_boundary_name(Scheme::CatmullClark, ""), 1};
    RefineRequest smooth = plain;
    smooth.rule.catmull_clark.smooth_triangles = true;
    EXPECT_NE(core.refine_last(mesh, plain).positions, core.refine_last(mesh, smooth).positions);
    EXPECT_NE(osd.refine_last(mesh, plain).positions, osd.refine_last(mesh, smooth).positions);
}

TEST(ShapeTags, AFlagWinsOverTheFilesBoundaryTagAndSaysSo) {
    PolyMesh mesh = read_text(grid_obj(2, false, "t interpolateboundary 1/0/0 1\n"));
    const TagRules from_tag = resolve_tag_rules(Scheme::CatmullClark, "", mesh);
    EXPECT_EQ(from_tag.boundary, "edge-and-corner");
    EXPECT_TRUE(from_tag.notes.empty());
    const TagRules from_flag = resolve_tag_rules(Scheme::CatmullClark, "edge-only", mesh);
    EXPECT_EQ(from_flag.boundary, "edge-only");
    ASSERT_EQ(from_flag.notes.size(), 1u);
    EXPECT_EQ(from_flag.notes[0], "--boundary edge-only wins over tagged.obj's 't interpolateboundary' (edge-and-corner)");
    // A scheme without OpenSubdiv's rules cannot take the tag's rule silently.
    EXPECT_THROW(resolve_tag_rules(Scheme::DooSabin, "", mesh), InputError);
    EXPECT_NO_THROW(resolve_tag_rules(Scheme::DooSabin, "chaikin-boundary", mesh));
}

}  // namespace
}  // namespace crossdiv::verification
