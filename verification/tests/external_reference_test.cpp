// Programs as references: the float tier, a setup that says the program is not here, the
// manifest's reference and subject statements, and MeshLab's meshlabserver itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/nondeterminism.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/suite/manifest.h"
#include "crossdiv/verification/suite/runner.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;
using test::kSource;

using test::bundled;

ProgramSpec float_program(const std::string& name) {
    ProgramSpec spec;
    spec.name = name;
    spec.command = "python3 " + kSource + "/verification/tests/subjects/misbehaving_subject.py float {in} {levels} {out.ply}";
    spec.schemes = {Scheme::Loop};
    spec.precision = Precision::Float;
    return spec;
}

RefinementComparison compare_against(const std::string& reference, const std::string& mesh, int levels) {
    RefinementRequest req;
    req.levels = levels;
    req.references = {reference};
    return compare_refinement(datasets::bundled_mesh(mesh), mesh, req);
}

std::string write_manifest(const std::string& name, const std::string& text) {
    const fs::path dir = fs::temp_directory_path() / "crossdiv-external-reference-test";
    fs::create_directories(dir);
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p.string();
}

// A correct Loop rounded to float agrees in the float tier, read back exactly from binary PLY;
// the same output held to the double tier would not (it is 1e-8 off, 1e4 times the bound).
TEST(ExternalReference, AFloatProgramAgreesInTheFloatTierOnly) {
    register_reference(make_program_implementation(float_program("float-loop")));
    const RefinementComparison c = compare_against("float-loop", "icosahedron", 2);
    ASSERT_EQ(c.runs.size(), 1u);
    const RefinementRun& r = c.runs[0];
    EXPECT_EQ(r.verdict, Verdict::Agree) << r.explanation;
    EXPECT_NE(r.explanation.find("float tier"), std::string::npos) << r.explanation;
    EXPECT_GT(r.comparison.max_rel, 1e-12);  // float rounding, which the double tier would refuse
    EXPECT_LT(r.comparison.max_rel, 1e-6);

    ProgramSpec as_double = float_program("float-loop-as-double");
    as_double.precision = Precision::Double;
    register_reference(make_program_implementation(as_double));
    const RefinementComparison d = compare_against("float-loop-as-double", "icosahedron", 2);
    EXPECT_EQ(d.runs[0].verdict, Verdict::Diverge);
}

/// The single run of `c` ended with `status`, verdict `verdict`, its explanation saying `says`.
void expect_failed_run(const RefinementComparison& c, RunStatus status, Verdict verdict, const std::string& says) {
    ASSERT_EQ(c.runs.size(), 1u);
    EXPECT_EQ(c.runs[0].outcome.status, status);
    EXPECT_EQ(c.runs[0].verdict, verdict);
    EXPECT_NE(c.runs[0].explanation.find(says), std::string::npos) << c.runs[0].explanation;
}

TEST(ExternalReference, ASetupThatFailsMakesEveryRunUnavailable) {
    ProgramSpec spec = float_program("absent-program");
    spec.setup = "python3 -c 'import sys; sys.stderr.write(\"not installed\\n\"); sys.exit(1)'";
    register_reference(make_program_implementation(spec));
    expect_failed_run(compare_against("absent-program", "tetrahedron", 1), RunStatus::Unavailable, Verdict::RefUnavailable,
                      "not installed");
}

TEST(ExternalReference, DeclaredRulesAreTheOnesItIsAskedFor) {
    ProgramSpec spec = float_program("two-families");
    spec.weights = {"loop", "regularity"};
    spec.boundaries = {"edge-only"};
    const auto p = make_program_implementation(spec);
    SchemeRule warren;
    warren.loop = {LoopWeights::Warren, LoopBoundary::EdgeAndCorner};
    EXPECT_EQ(p->closest_rule(Scheme::Loop, warren).loop, (LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeOnly}));
    SchemeRule regularity;
    regularity.loop = {LoopWeights::Regularity, LoopBoundary::EdgeOnly};
    EXPECT_TRUE(p->applies(Scheme::Loop, regularity));
    spec.boundaries = {"drop-border-faces"};  // a Doo-Sabin rule, not Loop's
    EXPECT_THROW(make_program_implementation(spec), InputError);
    spec.boundaries = {};
    spec.weights = {"hexagonal"};
    EXPECT_THROW(make_program_implementation(spec), InputError);
}


// A reference with one weight family that is not Loop's (Open3D's Warren weights) applies that
// family whatever is asked; "same rules" there would hide a weight-family divergence as
// unexplained.
TEST(ExternalReference, AFamilyOfItsOwnIsTheRuleItApplies) {
    ProgramSpec spec = float_program("warren-only");
    spec.weights = {"warren"};
    spec.boundaries = {"edge-only"};
    const auto p = make_program_implementation(spec);
    SchemeRule asked;
    for (LoopBoundary b : {LoopBoundary::EdgeOnly, LoopBoundary::EdgeAndCorner}) {
        asked.loop = {LoopWeights::Loop, b};
        EXPECT_EQ(p->closest_rule(Scheme::Loop, asked).loop, (LoopOptions{LoopWeights::Warren, LoopBoundary::EdgeOnly}));
    }
    spec.boundaries = {"edge-only", "edge-and-corner"};
    asked.loop = {LoopWeights::Regularity, LoopBoundary::EdgeAndCorner};
    EXPECT_EQ(make_program_implementation(spec)->closest_rule(Scheme::Loop, asked).loop,
              (LoopOptions{LoopWeights::Warren, LoopBoundary::EdgeAndCorner}));
}
// Far from the origin a float's step (8 at 1e8) outgrows the mesh (a diagonal of 5): core's
// level has no two vertices a float tells apart, so a float program's result cannot be matched
// and nothing is compared, neither agreement nor a divergence (the run is no failure).
TEST(ExternalReference, AFloatProgramFarFromTheOriginIsNotCompared) {
    ProgramSpec spec = float_program("float-far");  // in its own numbering: matched by position only
    spec.command = "python3 " + kSource + "/verification/tests/subjects/misbehaving_subject.py float-shuffle {in} {levels} {out.ply}";
    register_reference(make_program_implementation(spec));
    RefinementRequest req;
    req.levels = 2;
    req.references = {"float-far"};
    const RefinementComparison c = compare_refinement(datasets::edge_case("far-from-origin").mesh, "far-from-origin", req);
    ASSERT_EQ(c.runs.size(), 1u);
    EXPECT_EQ(c.runs[0].verdict, Verdict::NotCompared) << c.runs[0].explanation;
    EXPECT_NE(c.runs[0].explanation.find("share a position once rounded to float (coordinates up to 1e+08, where a float's step is 8"),
              std::string::npos)
        << c.runs[0].explanation;
}

// A reference that says it has no rule for an input, by an exit status it declares, is
// ref-rejected with its words; the same status undeclared is a failed run.
TEST(ExternalReference, ADeclaredRefusalStatusIsARejectionWithItsReason) {
    ProgramSpec spec;
    spec.name = "refuses-by-status";
    spec.command = "python3 " + kSource + "/verification/tests/subjects/misbehaving_subject.py exit {in} {levels} {out}";
    spec.schemes = {Scheme::Loop};
    spec.refusal_exit_codes = {3};
    register_reference(make_program_implementation(spec));
    const RefinementComparison declared = compare_against("refuses-by-status", "tetrahedron", 1);
    ASSERT_EQ(declared.runs.size(), 1u);
    EXPECT_EQ(declared.runs[0].verdict, Verdict::RefRejected);
    EXPECT_NE(declared.runs[0].outcome.message.find("refuses the input (exit status 3 (level 1)): cannot subdivide: half-edge table overflow"),
              std::string::npos)
        << declared.runs[0].outcome.message;
    spec.name = "fails-by-status";
    spec.refusal_exit_codes = {4};
    register_reference(make_program_implementation(spec));
    const RefinementComparison undeclared = compare_against("fails-by-status", "tetrahedron", 1);
    ASSERT_EQ(undeclared.runs.size(), 1u);
    EXPECT_EQ(undeclared.runs[0].outcome.status, RunStatus::ExitStatus);
    EXPECT_EQ(undeclared.runs[0].verdict, Verdict::RefCrashed);
}

TEST(Manifest, ReferenceAndSubjectStatementsJoinTheCasesAfterThem) {
    const std::string script = "python3 " + kSource + "/verification/tests/subjects/misbehaving_subject.py ";
    const std::string cmd = script + "float {in} {levels} {out.ply}";
    const std::string shuffled = script + "shuffle {in} {levels} {out}";  // Loop's rule, in another numbering
    const std::string path = write_manifest("statements.suite", "suite statements\n"
                                                                "case bundled:tetrahedron loop levels=1\n"
                                                                "reference late-float command='" + cmd + "' schemes=loop precision=float\n"
                                                                "case bundled:tetrahedron loop levels=1\n"
                                                                "subject mine command='" + shuffled + "'\n"
                                                                "case bundled:octahedron loop levels=2\n");
    const Manifest m = read_manifest(path);
    ASSERT_EQ(m.entries.size(), 3u);
    auto has = [](const ManifestEntry& e, const std::string& n) {
        return std::find(e.request.references.begin(), e.request.references.end(), n) != e.request.references.end();
    };
    EXPECT_FALSE(has(m.entries[0], "late-float"));
    EXPECT_TRUE(has(m.entries[1], "late-float"));
    EXPECT_EQ(find_implementation("late-float").capabilities().precision, Precision::Float);
    EXPECT_EQ(m.entries[1].subject, nullptr);
    ASSERT_NE(m.entries[2].subject, nullptr);
    EXPECT_EQ(m.entries[2].subject->name, "mine");
    // Reading it again keeps one late-float (the same program under the same name).
    EXPECT_NO_THROW(read_manifest(path));

    // The subject's job: the program in core's place, recorded under its name.
    const std::vector<SuiteJob> jobs = expand_jobs(m);
    ASSERT_EQ(jobs.size(), 3u);
    EXPECT_NE(jobs[2].id.find("subject=mine"), std::string::npos) << jobs[2].id;
    const CaseRecord rec = run_job(jobs[2], (fs::temp_directory_path() / "crossdiv-external-reference-test").string());
    EXPECT_FALSE(rec.ours_failed) << rec.core_error;
    ASSERT_TRUE(rec.detail.contains("subject"));
    EXPECT_EQ(rec.detail["subject"]["name"], "mine");
    EXPECT_EQ(rec.detail["subject"]["rules"]["rule"], "weights=loop boundary=edge-only");
}

TEST(Manifest, BadReferenceAndSubjectStatementsNameTheLine) {
    auto error = [](const std::string& text) {
        try {
            read_manifest(write_manifest("bad.suite", "suite bad\n" + text));
        } catch (const ParseError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error("reference x schemes=loop\n").find("bad.suite:2: program 'x' has no command"), std::string::npos);
    EXPECT_NE(error("reference y command='a {out}' precision=half\n").find(":2: precision must be double or float"),
              std::string::npos);
    EXPECT_NE(error("reference z command='a {out}' colour=red\n").find(":2: unknown key 'colour'"), std::string::npos);
    EXPECT_NE(error("reference r command='a {out}' rejects=4,0\n").find(":2: rejects takes exit statuses 1..255, got '0'"),
              std::string::npos);
    EXPECT_NE(error("subject t command='a {in} {out}' rejects=4\n").find(":2: rejects= is for references"), std::string::npos);
    EXPECT_NE(error("reference w command='a {out}\n").find(":2: unclosed '"), std::string::npos);
    EXPECT_NE(error("reference opensubdiv command='a {out}'\n").find(":2: a reference named 'opensubdiv' exists already"),
              std::string::npos);
    EXPECT_NE(error("subject s command='a {out}'\ncase catalog spectrum\n").find(":3: a subject is compared in the scheme comparisons, the invariance checks and the course tasks only"),
              std::string::npos);
    // A subject named as core or a reference would be taken for it.
    EXPECT_NE(error("subject core command='a {in} {out}'\n").find(":2: a subject cannot be named 'core'"), std::string::npos);
    EXPECT_NE(error("subject cgal result='r/{input}.obj'\n").find(":2: a subject cannot be named 'cgal'"), std::string::npos);
    // The course tasks: a subject before them, each key where its task reads it.
    EXPECT_NE(error("case curve:flower tessellate\n").find(":2: the tessellate task puts a subject in core's place"), std::string::npos);
    const std::string s = "subject s command='a {in} {out}'\n";
    EXPECT_NE(error(s + "case curve:flower tessellate t=0.3\n").find(":3: the tessellate task takes no t= key (casteljau does)"),
              std::string::npos);
    EXPECT_NE(error(s + "case x.bzc casteljau t=2\n").find(":3: t must be in [0, 1], got 2"), std::string::npos);
    EXPECT_NE(error(s + "case x.bez patch res=0\n").find(":3: res=0 is not a whole number in [1, 1024]"), std::string::npos);
    EXPECT_NE(error(s + "case bundled:torus flip-split\n").find(":3: the flip-split task needs ops="), std::string::npos);
    EXPECT_NE(error(s + "case bundled:torus flip-split ops='turn 1 2'\n").find("bad.suite:3:"), std::string::npos);
    EXPECT_NE(error("subject s result='r/{input}.obj'\ncase bundled:torus vertex-normals\n").find(":3: the vertex-normals task runs a program"),
              std::string::npos);
}

// A C++ function in core's place: its rule is identified like a program's, and a function
// that crashes is that run's outcome, not the end of the comparison.
TEST(Callback, IsComparedAndItsRuleNamed) {
    const auto warren = make_callback_implementation("mine", {Scheme::Loop}, [](const PolyMesh& m, const RefineRequest& r) {
        return to_poly_mesh(loop_subdivide(to_tri_mesh(m, "mine"), {LoopWeights::Warren, LoopBoundary::EdgeOnly}, r.levels));
    });
    RefinementRequest req;
    req.levels = 2;
    req.subject = warren.get();
    const RefinementComparison c = compare_refinement(datasets::bundled_mesh("icosahedron"), "icosahedron", req);
    ASSERT_FALSE(c.subject_failed()) << c.subject_outcome.summary();
    ASSERT_TRUE(c.rules && c.rules->rule);
    EXPECT_EQ(c.rules->rule->loop, (LoopOptions{LoopWeights::Warren, LoopBoundary::EdgeOnly}));
    for (const RefinementRun& r : c.runs) EXPECT_EQ(r.divergence_class, DivergenceClass::WeightFamily) << r.reference;

    const auto crashing = make_callback_implementation("crashing", {Scheme::Loop}, [](const PolyMesh&, const RefineRequest&) -> PolyMesh {
        std::abort();
    });
    req.subject = crashing.get();
    const RefinementComparison d = compare_refinement(datasets::bundled_mesh("tetrahedron"), "tetrahedron", req);
    EXPECT_EQ(d.subject_outcome.status, RunStatus::Crashed);
    EXPECT_TRUE(d.subject_failed());
}

/// Core's levels of `request`, one call per level, as a library double's starting point.
adapters::LevelTrace core_levels(const PolyMesh& mesh, const RefineRequest& request) {
    adapters::LevelTrace trace{mesh};
    for (int l = 1; l <= request.levels; ++l) {
        RefineRequest one = request;
        one.levels = 1;
        trace.push_back(core_implementation().refine_last(trace.back(), one));
    }
    return trace;
}

// A library that returns NaN (OpenMesh's sqrt3 reading past its weight table does) gave no
// answer: ref-invalid-output naming the vertex and level, never a distance of inf.
class NonFiniteLibrary final : public Implementation {
public:
    NonFiniteLibrary()
        : Implementation("non-finite", "test", ImplementationKind::Library,
                         {.schemes = {{Scheme::Loop, {SchemeRule{}}, false, 0, ""}}}) {}
    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& request) const override {
        adapters::LevelTrace trace = core_levels(mesh, request);
        trace.back().positions[3].y() = std::numeric_limits<double>::infinity();
        return trace;
    }
};

TEST(LibraryReference, WithANonFiniteCoordinateIsAnInvalidOutput) {
    register_reference(std::make_unique<NonFiniteLibrary>());
    expect_failed_run(compare_against("non-finite", "octahedron", 2), RunStatus::NonFiniteOutput, Verdict::RefInvalidOutput,
                      "vertex 3 of level 2 is not finite");
}

// A library whose weight table ends below the input's valence, as OpenMesh's Sqrt3T (50
// entries) on pole-64: at every level it puts the vertices past its table at three times their
// distance from the origin, as what Sqrt3T reads past its vector may. Their neighbourhoods then
// land among other vertices and pair with the wrong ones, so the final level has no vertex
// correspondence (moved a thousand times as far, the faces would still place them); level 1
// still shows the cause: exactly the vertices past the table differ.
// With `not_a_number`, it puts NaN there instead, as Sqrt3T does when what lies past its vector
// reads as NaN.
class ShortTableLibrary final : public Implementation {
public:
    explicit ShortTableLibrary(bool not_a_number = false)
        : Implementation(not_a_number ? "short-table-nan" : "short-table", "test", ImplementationKind::Library,
                         {.schemes = {{Scheme::Sqrt3, {SchemeRule{.sqrt3 = {Sqrt3Parity::RestartEachLevel}}}, false, 49,
                                       "a table of 50 weights"}}}),
          not_a_number_(not_a_number) {}
    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& request) const override {
        adapters::LevelTrace trace{mesh}, clean{mesh};
        for (int l = 1; l <= request.levels; ++l) {
            RefineRequest one = request;
            one.levels = 1;
            one.rule.sqrt3 = {Sqrt3Parity::RestartEachLevel};
            // NaN stays where it is put (the next level is refined from the finite positions,
            // as a library that does not check its coordinates goes on).
            const PolyMesh& coarse = not_a_number_ ? clean.back() : trace.back();
            PolyMesh fine = core_implementation().refine_last(coarse, one);
            const MeshTopology topo = mesh_topology(coarse);
            if (not_a_number_) clean.push_back(fine);  // after the last use of `coarse`, which it may move
            for (size_t v = 0; v < topo.valence.size(); ++v)  // core keeps the old vertices first
                if (topo.valence[v] > 49) fine.positions[v] = not_a_number_ ? Vec3::Constant(NAN) : Vec3(3 * fine.positions[v]);
            trace.push_back(std::move(fine));
        }
        return trace;
    }

private:
    bool not_a_number_;
};

/// `levels` of sqrt3 on pole-64 against `reference` alone.
RefinementComparison sqrt3_on_pole_64(const std::string& reference, int levels) {
    RefinementRequest req;
    req.scheme = Scheme::Sqrt3;
    req.levels = levels;
    req.references = {reference};
    return compare_refinement(datasets::bundled_mesh("pole-64"), "pole-64", req);
}

TEST(LibraryReference, PastItsValenceTableIsAValenceLimitEvenWithoutACorrespondence) {
    register_reference(std::make_unique<ShortTableLibrary>());
    const RefinementComparison c = sqrt3_on_pole_64("short-table", 3);
    ASSERT_EQ(c.runs.size(), 1u);
    const RefinementRun& r = c.runs[0];
    EXPECT_EQ(r.correspondence.method, MatchMethod::None) << r.correspondence.note;  // level 3 cannot be matched
    EXPECT_EQ(r.verdict, Verdict::Diverge);
    EXPECT_EQ(r.divergence_class, DivergenceClass::ValenceLimit) << r.explanation;
    // pole-64's two poles have valence 64.
    EXPECT_NE(r.explanation.find("exactly the 2 vertices of larger valence (up to 64) differ"), std::string::npos)
        << r.explanation;
}

// NaN past the table is the same valence limit (and not an invalid output, which made the
// class flip from run to run with what Sqrt3T found past its vector).
TEST(LibraryReference, NaNPastItsValenceTableIsAValenceLimit) {
    register_reference(std::make_unique<ShortTableLibrary>(true));
    const RefinementComparison c = sqrt3_on_pole_64("short-table-nan", 2);
    ASSERT_EQ(c.runs.size(), 1u);
    const RefinementRun& r = c.runs[0];
    EXPECT_EQ(r.outcome.status, RunStatus::NonFiniteOutput);
    EXPECT_EQ(r.verdict, Verdict::Diverge);
    EXPECT_EQ(r.divergence_class, DivergenceClass::ValenceLimit) << r.explanation;
    EXPECT_NE(r.explanation.find("exactly the 2 vertices of larger valence (up to 64) differ, all to non-finite positions"),
              std::string::npos) << r.explanation;
}

// A library that leaves one vertex's new position unwritten (as OpenMesh's Loop does at an
// isolated vertex): it reads whatever its allocation held. Each isolated run fills the heap
// with one byte, so the result is the same every time; run again with another, it changes, and
// the run is ref-nondeterministic, naming the vertex and both values.
class UnwrittenVertexLibrary final : public Implementation {
public:
    UnwrittenVertexLibrary()
        : Implementation("unwritten-vertex", "test", ImplementationKind::Library, {.schemes = {{Scheme::Loop, {SchemeRule{}}, false, 0, ""}}}) {}
    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& request) const override {
        adapters::LevelTrace trace = core_levels(mesh, request);
        // A fresh allocation, never written, copied byte for byte (reading indeterminate bytes
        // as unsigned char is defined).
        auto* unwritten = static_cast<unsigned char*>(std::malloc(4096));
        std::memcpy(trace.back().positions[0].data(), unwritten + 2048, 3 * sizeof(double));
        std::free(unwritten);
        return trace;
    }
};

TEST(LibraryReference, ThatReadsMemoryItNeverWroteIsNondeterministic) {
#ifdef CROSSDIV_SANITIZED
    // The heap fill is glibc's mallopt, which the address sanitizer's allocator replaces (it
    // fills new memory with its own byte in both runs): the detection itself is tested below,
    // on hand-made results, in every build.
    GTEST_SKIP() << "the address sanitizer's allocator replaces glibc's heap fill";
#endif
    register_reference(std::make_unique<UnwrittenVertexLibrary>());
    const RefinementComparison c = compare_against("unwritten-vertex", "octahedron", 2);
    ASSERT_EQ(c.runs.size(), 1u);
    const RefinementRun& r = c.runs[0];
    EXPECT_EQ(r.verdict, Verdict::RefNondeterministic) << r.explanation;
    EXPECT_FALSE((Outcome{r.verdict, r.divergence_class}.is_failure()));
    EXPECT_NE(r.explanation.find("unwritten-vertex gives another result when run again on the same input with its heap "
                                 "filled otherwise (it reads memory it never wrote, or depends on more than its input): "
                                 "level 2 vertex 0 is ("),
              std::string::npos) << r.explanation;
    EXPECT_NE(r.explanation.find("; the first run: "), std::string::npos) << r.explanation;
    // The same comparison again: the same verdict and the same numbers (the fill makes the
    // unwritten bytes the same in every run, whatever this process's heap held).
    std::vector<char*> clutter;  // change this process's heap between the comparisons
    for (int i = 0; i < 100; ++i) clutter.push_back(static_cast<char*>(std::malloc(4096 + 64 * i))), clutter.back()[0] = 1;
    const RefinementComparison again = compare_against("unwritten-vertex", "octahedron", 2);
    for (char* p : clutter) std::free(p);
    EXPECT_EQ(again.runs[0].verdict, Verdict::RefNondeterministic);
    EXPECT_EQ(again.runs[0].explanation, r.explanation);
}

// Where two runs part, in every build: statuses, counts, the first vertex by its bits (a NaN
// equals itself), faces; nothing when equal.
/// A run whose input and level 1 are both `level` (the first level that differs is 0).
IsolatedTrace run_that_made(const PolyMesh& level) {
    IsolatedTrace r;
    r.trace.emplace(adapters::LevelTrace{level, level});
    return r;
}

TEST(Nondeterminism, FirstDifferenceNamesWhereTwoRunsPart) {
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, NAN)};
    m.add_face({0, 1, 2});
    const IsolatedTrace a = run_that_made(m);
    EXPECT_FALSE(first_difference(a, run_that_made(m)));
    PolyMesh moved = m;
    moved.positions[1].x() = 2;
    EXPECT_EQ(first_difference(a, run_that_made(moved)).value_or(""),
              "level 0 vertex 1 is (1, 0, 0) in one run and (2, 0, 0) in the other");
    PolyMesh turned = m;
    turned.face_vertices = {0, 2, 1};
    EXPECT_EQ(first_difference(a, run_that_made(turned)).value_or(""), "level 0's faces differ between the runs");
    // Texture coordinates: a value that changes, and a value whose index changes.
    PolyMesh with_uv = m;
    with_uv.face_varying.push_back({"uv", 2, {0, 0, 1, 0, 0, 1}, {0, 1, 2}});
    const IsolatedTrace u = run_that_made(with_uv);
    EXPECT_FALSE(first_difference(u, run_that_made(with_uv)));
    PolyMesh other_value = with_uv;
    other_value.face_varying[0].values[3] = 0.5;
    EXPECT_EQ(first_difference(u, run_that_made(other_value)).value_or(""),
              "level 0's face-varying value 1 of channel 'uv' is 0 in one run and 0.5 in the other");
    PolyMesh other_index = with_uv;
    other_index.face_varying[0].corner_values = {0, 1, 1};
    EXPECT_EQ(first_difference(u, run_that_made(other_index)).value_or(""),
              "level 0's face-varying channel 'uv' is indexed differently in the two runs");
    EXPECT_EQ(first_difference(u, a).value_or(""), "level 0 has 1 face-varying channels in one run, 0 in the other");
    IsolatedTrace crashed;
    crashed.outcome.status = RunStatus::Crashed;
    EXPECT_EQ(first_difference(a, crashed).value_or(""), "one run ended ok, the other crashed");
    EXPECT_FALSE(reruns_for_determinism(RunStatus::Timeout));
    EXPECT_FALSE(reruns_for_determinism(RunStatus::Rejected));
    EXPECT_TRUE(reruns_for_determinism(RunStatus::Crashed));
}

// MeshLab as the default suite has it: Loop under each of its weight families against core in
// the float tier. Needs Debian's meshlab, xvfb and xauth, which run.sh installs before it runs
// the tests: a machine without them fails here, naming the packages.
TEST(MeshLab, AgreesWithCoreUnderEachOfItsWeightFamilies) {
    const Manifest m = read_manifest(kSource + "/verification/suites/default.suite");
    ASSERT_TRUE(is_built("meshlab"));
    const Implementation& meshlab = find_implementation("meshlab");
    ASSERT_NO_THROW(meshlab.refine_last(to_poly_mesh(bundled("tetrahedron")), {Scheme::Loop, SchemeRule{}, 1}))
        << "meshlab is unavailable (apt-get install meshlab xvfb xauth)";
    for (LoopWeights w : {LoopWeights::Loop, LoopWeights::Regularity, LoopWeights::Continuity})
        for (const char* mesh : {"cube-asymmetric", "fan-5", "open-patch"}) {
            RefinementRequest req;
            req.levels = 2;
            req.rule.loop = {w, LoopBoundary::EdgeOnly};
            req.references = {"meshlab"};
            const RefinementComparison c = compare_refinement(datasets::bundled_mesh(mesh), mesh, req);
            ASSERT_EQ(c.runs.size(), 1u);
            EXPECT_EQ(c.runs[0].verdict, Verdict::Agree) << to_string(w) << " " << mesh << ": " << c.runs[0].explanation;
        }
    // Warren's weights MeshLab lacks: it runs Loop's, and the difference is the weight family.
    RefinementRequest req;
    req.levels = 2;
    req.rule.loop = {LoopWeights::Warren, LoopBoundary::EdgeOnly};
    req.references = {"meshlab"};
    const RefinementComparison c = compare_refinement(datasets::bundled_mesh("icosahedron"), "icosahedron", req);
    EXPECT_EQ(c.runs[0].divergence_class, DivergenceClass::WeightFamily) << c.runs[0].explanation;
}

// The tuned families at a bowtie (nonmanifold.h): core reads each fan alone in the tuned edge
// mask, and so does VCG's walk around a vertex. One level, so that only the bowtie vertex's
// own rule can differ: MeshLab moves it by the boundary rule within one fan, OpenSubdiv's rule
// (core's) keeps it as a corner; every other vertex agrees in float, the edge points where
// the tuned mask departs from Loop's among them.
TEST(MeshLab, ReadsEachFanOfABowtieAloneInTheTunedEdgeMask) {
    const Manifest m = read_manifest(kSource + "/verification/suites/default.suite");
    ASSERT_TRUE(is_built("meshlab"));
    const PolyMesh bowtie = datasets::edge_case("bowtie-open-fans").mesh;
    for (LoopWeights w : {LoopWeights::Regularity, LoopWeights::Continuity}) {
        SCOPED_TRACE(to_string(w));
        RefinementRequest req;
        req.levels = 1;
        req.rule.loop = {w, LoopBoundary::EdgeOnly};
        req.references = {"meshlab"};
        const RefinementComparison c = compare_refinement(bowtie, "bowtie-open-fans", req);
        ASSERT_EQ(c.runs.size(), 1u);
        const MeshComparison& mc = c.runs[0].comparison;
        ASSERT_TRUE(mc.topology_equal()) << c.runs[0].explanation;
        ASSERT_GE(mc.worst.size(), 2u);
        EXPECT_EQ(mc.worst[0].ours_index, 0);
        EXPECT_GT(mc.worst[0].distance, 0.01 * mc.diagonal);  // measured: 0.062 of the diagonal
        // Float rounding (measured: 3e-8 of the diagonal), far below the tuned mask's effect.
        EXPECT_LE(mc.worst[1].distance, 1e-6 * mc.diagonal);
        const PolyMesh tuned = loop_subdivide(bowtie, req.rule.loop, 1);
        const PolyMesh plain = loop_subdivide(bowtie, {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 1);
        double moved = 0.0;
        for (int v = bowtie.num_vertices(); v < tuned.num_vertices(); ++v)
            moved = std::max(moved, (tuned.positions[v] - plain.positions[v]).norm());
        EXPECT_GT(moved, 0.01 * mc.diagonal);  // the tuned edge mask acts on these edge points
    }
}

// MeshLab's classic Butterfly (VCG's MidPointButterfly): on a closed mesh the eight-point
// stencil everywhere, as core's; on an open one its wing points beyond the boundary are the
// triangle's own opposite vertex, and core with that rule agrees in the float tier.
TEST(MeshLab, ButterflyTakesTheOppositeVertexForAWingBeyondTheBoundary) {
    const Manifest m = read_manifest(kSource + "/verification/suites/default.suite");
    ASSERT_TRUE(is_built("meshlab"));
    for (const char* mesh : {"icosahedron", "open-patch", "cube-asymmetric"}) {
        for (ButterflyWings wings : kAllButterflyWings) {
            RefinementRequest req;
            req.scheme = Scheme::Butterfly;
            req.rule.butterfly_wings = wings;
            req.levels = 2;
            req.references = {"meshlab"};
            const RefinementComparison c = compare_refinement(datasets::bundled_mesh(mesh), mesh, req);
            ASSERT_EQ(c.runs.size(), 1u);
            const bool open = std::string(mesh) == "open-patch";
            if (!open || wings == ButterflyWings::OppositeVertex) {
                EXPECT_EQ(c.runs[0].verdict, Verdict::Agree) << mesh << " " << to_string(wings) << ": " << c.runs[0].explanation;
            } else {
                EXPECT_EQ(c.runs[0].divergence_class, DivergenceClass::WingRule) << c.runs[0].explanation;
                EXPECT_GT(c.runs[0].comparison.max_rel, 0.01);  // measured: 0.049 of the diagonal
            }
        }
    }
}

// Open3D as the default suite has it (adapters/open3d): TriangleMesh.subdivide_loop. Needs
// Debian's python3-open3d, which run.sh installs before it runs the tests.
const Implementation& open3d_from_default_suite() {
    const Manifest m = read_manifest(kSource + "/verification/suites/default.suite");
    EXPECT_TRUE(is_built("open3d"));
    return find_implementation("open3d");
}

// Its vertex rule, by hand: the apex of a four-triangle pyramid (apex (0,0,1), base corners
// (+-1,0,0), (0,+-1,0)) moves to (1 - 4 beta) (0,0,1) + beta (sum of the corners) with Warren's
// beta = 3/(8*4) = 3/32: z = 1 - 12/32 = 0.625. Loop's beta (31/256) would give 0.515625.
TEST(Open3D, MovesAnInteriorVertexByWarrensWeights) {
    const Implementation& open3d = open3d_from_default_suite();
    PolyMesh pyramid;
    pyramid.positions = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    for (int k = 0; k < 4; ++k) pyramid.add_face({0, 1 + k, 1 + (k + 1) % 4});
    PolyMesh once;
    ASSERT_NO_THROW(once = open3d.refine_last(pyramid, {Scheme::Loop, SchemeRule{}, 1}))
        << "open3d is unavailable (apt-get install python3-open3d)";
    ASSERT_EQ(once.num_vertices(), 13);  // 5 vertices + 8 edges
    // The program's vertex order is its own; the apex is the one point on the axis above z = 0.5.
    int on_axis = 0;
    for (const Vec3& p : once.positions)
        if (p.x() == 0 && p.y() == 0 && p.z() > 0.5) {
            EXPECT_EQ(p.z(), 0.625);
            ++on_axis;
        }
    EXPECT_EQ(on_axis, 1);
}

// Against core: Warren's weights with the edge-only boundary agree to rounding (double); asked
// for Loop's weights it still applies Warren's, and the divergence is the weight family (with
// the corner rule, which it lacks, where the boundary has corners).
TEST(Open3D, AgreesWithCoreUnderWarrensWeightsAndNamesTheRest) {
    open3d_from_default_suite();
    auto compare = [](const char* mesh, LoopWeights w, LoopBoundary b) {
        RefinementRequest req;
        req.levels = 2;
        req.rule.loop = {w, b};
        req.references = {"open3d"};
        RefinementComparison c = compare_refinement(datasets::bundled_mesh(mesh), mesh, req);
        EXPECT_EQ(c.runs.size(), 1u);
        return c.runs.at(0);
    };
    for (const char* mesh : {"cube-asymmetric", "fan-5", "open-patch", "icosahedron"}) {
        const auto run = compare(mesh, LoopWeights::Warren, LoopBoundary::EdgeOnly);
        EXPECT_EQ(run.verdict, Verdict::Agree) << mesh << ": " << run.explanation;
    }
    EXPECT_EQ(compare("icosahedron", LoopWeights::Loop, LoopBoundary::EdgeOnly).divergence_class, DivergenceClass::WeightFamily);
    EXPECT_EQ(compare("open-patch", LoopWeights::Loop, LoopBoundary::EdgeAndCorner).divergence_class,
              DivergenceClass::WeightFamilyAndCornerRule);
}

// A vertex without faces: Open3D divides by its valence, 0, and writes NaN for it; recorded as
// the reference's invalid output, never compared as a surface.
TEST(Open3D, WritesNaNForAVertexWithoutFaces) {
    open3d_from_default_suite();
    RefinementRequest req;
    req.levels = 1;
    req.rule.loop = {LoopWeights::Warren, LoopBoundary::EdgeOnly};
    req.references = {"open3d"};
    const RefinementComparison c = compare_refinement(datasets::edge_case("isolated-vertex").mesh, "isolated-vertex", req);
    ASSERT_EQ(c.runs.size(), 1u);
    EXPECT_EQ(c.runs[0].outcome.status, RunStatus::NonFiniteOutput) << c.runs[0].outcome.message;
    EXPECT_EQ(c.runs[0].verdict, Verdict::RefInvalidOutput);
}

// Blender 3.4's Subdivision Surface modifier (adapters/blender, Blender run headless once per
// level, its float32 coordinates held to the float tier): Catmull-Clark under both of
// OpenSubdiv's boundary rules (boundary_smooth ALL and PRESERVE_CORNERS) and Simple agree with
// core on an open quad grid. A first measure of the reference, not yet in the default
// suite. Needs Debian's blender, which run.sh installs.
TEST(Blender, TheSubdivisionSurfaceModifierAgreesWithCoreInTheFloatTier) {
    ProgramSpec spec;
    spec.name = "blender";
    const std::string script = kSource + "/adapters/blender/blender_subdivide.py";
    spec.command = "blender --background --factory-startup --python " + script + " -- {scheme} {levels} {boundary} all {in} {out.ply}";
    spec.schemes = {Scheme::CatmullClark, Scheme::Bilinear};
    spec.boundaries = {"edge-only", "edge-and-corner", "linear"};
    spec.precision = Precision::Float;
    spec.setup = "/usr/bin/python3 " + script + " --check";
    register_reference(make_program_implementation(spec));
    auto compare = [](const char* mesh, Scheme scheme, const SchemeRule& rule) {
        RefinementRequest req;
        req.scheme = scheme;
        req.rule = rule;
        req.levels = 2;
        req.references = {"blender"};
        const RefinementComparison c = compare_refinement(datasets::bundled_mesh(mesh), mesh, req);
        EXPECT_EQ(c.runs.size(), 1u);
        return c.runs.at(0);
    };
    // An open grid, where the two boundary rules differ (each Blender start costs about 1.5 s).
    for (CatmullClarkBoundary b : {CatmullClarkBoundary::EdgeOnly, CatmullClarkBoundary::EdgeAndCorner}) {
        SchemeRule rule;
        rule.catmull_clark.boundary = b;
        const auto run = compare("quad-grid", Scheme::CatmullClark, rule);
        EXPECT_EQ(run.verdict, Verdict::Agree) << to_string(b) << ": " << run.explanation << run.outcome.message;
        EXPECT_GT(run.comparison.max_rel, 0.0);  // float, not bit for bit
    }
    const auto simple = compare("quad-grid", Scheme::Bilinear, SchemeRule{});
    EXPECT_EQ(simple.verdict, Verdict::Agree) << simple.explanation << simple.outcome.message;
}

}  // namespace
}  // namespace crossdiv::verification
