// Programs under test: the command template, every named way a program fails, results in
// another numbering, result files, and the rule a subject follows, measured per vertex class.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/comparisons/refinement_comparison.h"
#include "crossdiv/verification/comparisons/shrink.h"
#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "crossdiv/verification/implementations/registry.h"
#include "test_inputs.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;

using test::kSource;
const std::string kStudent = "python3 " + kSource + "/examples/subjects/python-loop/loop.py {in} {levels} {out}";

std::string misbehaving(const std::string& mode) {
    return "python3 " + kSource + "/verification/tests/subjects/misbehaving_subject.py " + mode + " {in} {levels} {out}";
}

using test::bundled;

RefinementComparison compare_with(const Implementation& subject, const std::string& mesh, int levels) {
    RefinementRequest req;
    req.levels = levels;
    req.subject = &subject;
    return compare_refinement(datasets::bundled_mesh(mesh), mesh, req);
}

std::unique_ptr<Implementation> program(const std::string& command, double timeout = 60,
                                        LevelMode levels = LevelMode::Each) {
    ProgramSpec spec;
    spec.name = "subject";
    spec.command = command;
    spec.schemes = {Scheme::Loop};
    spec.levels = levels;
    spec.timeout_seconds = timeout;
    return make_program_implementation(spec);
}

TEST(CommandTemplate, SplitsLikeAShellWithoutOneAndSubstitutesEachPlaceholder) {
    const CommandTemplate t("prog 'a b' \"c {levels}\" x\\ y --out={out.off} {{lit}} {scheme} {weights} {boundary} {in}");
    EXPECT_TRUE(t.reads(MeshFormat::Obj));
    EXPECT_FALSE(t.reads(MeshFormat::Off));
    EXPECT_EQ(t.output_format(), MeshFormat::Off);
    TemplateValues v{"/t/in.obj", "/t/in.off", "/t/in.ply", "/t/out.off", {Scheme::Loop, {}, 3}, "/t/in-untagged.obj", "/t/submission", "/t/ops.txt"};
    v.request.rule.loop = {LoopWeights::Warren, LoopBoundary::EdgeAndCorner};
    const std::vector<std::string> want = {"prog", "a b", "c 3", "x y", "--out=/t/out.off", "{lit}", "loop",
                                           "warren", "edge-and-corner", "/t/in.obj"};
    EXPECT_EQ(t.expand(v), want);
    // A file name with a shell metacharacter stays one argument.
    v.in_obj = "/t/a;rm -rf x.obj";
    EXPECT_EQ(t.expand(v).back(), "/t/a;rm -rf x.obj");
}

TEST(Program, RunsFromAFolderWhoseNameAShellWouldInterpret) {
    // The program lives in a folder named with a space, a command substitution, quotes, a
    // non-ASCII letter and a byte that is not UTF-8. Run from an argument vector, it is found
    // and agrees with core, and nothing in the name is executed.
    const fs::path base = fs::temp_directory_path() / ("crossdiv subject $(touch PWNED) 'q' \xC3\xA9 \xFF " +
                                                       std::to_string(::getpid()));
    fs::create_directories(base);
    fs::copy_file(kSource + "/examples/subjects/python-loop/loop.py", base / "loop.py", fs::copy_options::overwrite_existing);
    const std::string command = "python3 \"" + (base / "loop.py").string() + "\" {in} {levels} {out}";
    const auto subject = program(command);
    const RefinementComparison c = compare_with(*subject, "octahedron", 1);
    EXPECT_EQ(c.subject_outcome.status, RunStatus::Ok) << c.subject_outcome.summary();
    ASSERT_TRUE(c.rules && c.rules->rule);
    EXPECT_EQ(c.rules->rule->loop.weights, LoopWeights::Warren);  // the assignment's 3/(8n), 3/32 at valence 4
    EXPECT_FALSE(fs::exists("PWNED"));
    EXPECT_FALSE(fs::exists(base / "PWNED"));
    EXPECT_FALSE(fs::exists(fs::temp_directory_path() / "PWNED"));
    fs::remove_all(base);
}

TEST(CommandTemplate, RefusesWhatCannotRun) {
    EXPECT_THROW(CommandTemplate("prog {in} {levels}"), InputError);            // no output
    EXPECT_THROW(CommandTemplate("prog {in} {outt}"), InputError);              // unknown placeholder
    EXPECT_THROW(CommandTemplate("prog {in} {out} {out.off}"), InputError);     // two formats
    EXPECT_THROW(CommandTemplate("prog 'unclosed {out}"), InputError);
    EXPECT_THROW(CommandTemplate("prog {in {out}"), InputError);
    EXPECT_THROW(CommandTemplate("   "), InputError);
    try {
        CommandTemplate("prog {input} {out}");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("{input}"), std::string::npos) << e.what();
    }
}

TEST(ExpectedCounts, FollowFromTheInputCounts) {
    const PolyMesh tet = datasets::bundled_mesh("tetrahedron");
    // Loop: V + E and 4F per level: 4 + 6 = 10, 16; then 10 + (2*6 + 3*4) = 34, 64.
    using Counts = std::vector<RefinedCounts>;
    EXPECT_EQ(expected_counts(Scheme::Loop, tet, 1), (Counts{{10, 16, ""}}));
    EXPECT_EQ(expected_counts(Scheme::Loop, tet, 2), (Counts{{34, 64, ""}}));
    // Catmull-Clark on the cube: 8 + 12 + 6 = 26 vertices, one quad per corner: 24.
    EXPECT_EQ(expected_counts(Scheme::CatmullClark, datasets::polygon_meshes().front().mesh, 1), (Counts{{26, 24, ""}}));
    // Doo-Sabin on the closed tetrahedron: a vertex per corner (12), a face per face, edge and
    // vertex (4 + 6 + 4); both border rules agree on a closed mesh.
    EXPECT_EQ(expected_counts(Scheme::DooSabin, tet, 1), (Counts{{12, 14, ""}}));
    // On a single triangle the border decides: Chaikin's keeps the triangle's corner points
    // (3), the edge points (2 per edge: 6) and makes a face per face, edge and vertex
    // (1 + 3 + 3); dropping the border leaves the corner triangle alone.
    PolyMesh triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.add_face(std::vector<int>{0, 1, 2});
    EXPECT_EQ(expected_counts(Scheme::DooSabin, triangle, 1),
              (Counts{{9, 7, "chaikin-boundary"}, {3, 1, "drop-border-faces"}}));
    // sqrt3 on the same triangle: the first step keeps the boundary in either parity (the
    // centroid and three triangles); the second trisects it only when counted from the input.
    EXPECT_EQ(expected_counts(Scheme::Sqrt3, triangle, 1), (Counts{{4, 3, ""}}));
    EXPECT_EQ(expected_counts(Scheme::Loop, datasets::polygon_meshes().front().mesh, 1), Counts{});
}

struct Failure {
    const char* mode;
    RunStatus status;
    const char* in_message;  ///< a piece of the message that shows the failure was named
};

class ProgramFailure : public ::testing::TestWithParam<Failure> {};

TEST_P(ProgramFailure, IsNamedAndNothingIsCompared) {
    const Failure f = GetParam();
    const auto subject = program(misbehaving(f.mode), 3);
    const RefinementComparison c = compare_with(*subject, "icosahedron", 2);
    EXPECT_EQ(c.subject_outcome.status, f.status) << c.subject_outcome.summary();
    EXPECT_NE(c.subject_outcome.message.find(f.in_message), std::string::npos) << c.subject_outcome.message;
    EXPECT_TRUE(c.subject_failed());
    EXPECT_TRUE(c.runs.empty());
}

INSTANTIATE_TEST_SUITE_P(
    Modes, ProgramFailure,
    ::testing::Values(Failure{"crash", RunStatus::Crashed, "signal 11"}, Failure{"hang", RunStatus::Timeout, "no result after 3 s"},
                      Failure{"exit", RunStatus::ExitStatus, "half-edge table overflow"},
                      Failure{"nothing", RunStatus::NoOutput, "no output file out.obj"},
                      Failure{"nan", RunStatus::NonFiniteOutput, "out.obj:"},
                      Failure{"garbage", RunStatus::UnreadableOutput, "out.obj:4"},
                      Failure{"wrong-count", RunStatus::WrongCount, "42 vertices, 80 faces"},
                      Failure{"quads", RunStatus::NotTriangles, "face 0"}),
    [](const auto& info) {
        std::string n = info.param.mode;
        for (char& ch : n)
            if (ch == '-') ch = '_';
        return n;
    });

/// One failure of a subject of one scheme: the misbehaving program started from the scheme's
/// course-style example (examples/subjects/python-schemes).
struct SchemeFailure {
    Scheme scheme;
    const char* mode;
    RunStatus status;          ///< RunStatus::Ok: the run succeeds (shuffle: another numbering; the others: faces not the scheme's)
    const char* in_message;    ///< in the run's message, or in why the subject fails
};

class SchemeProgramFailure : public ::testing::TestWithParam<SchemeFailure> {};

TEST_P(SchemeProgramFailure, GetsItsOutcomeInEveryScheme) {
    const SchemeFailure f = GetParam();
    ProgramSpec spec;
    spec.name = "subject";
    spec.command = misbehaving(f.mode) + " " + to_string(f.scheme);
    spec.schemes = {f.scheme};
    spec.timeout_seconds = std::string_view(f.mode) == "hang" ? 2 : 60;
    const auto subject = make_program_implementation(spec);
    RefinementRequest req;
    req.scheme = f.scheme;
    req.levels = 2;
    req.subject = subject.get();
    // An open mesh: the schemes whose counts depend on the border are held to them.
    const RefinementComparison c = compare_refinement(datasets::bundled_mesh("open-patch"), "open-patch", req);
    EXPECT_EQ(c.subject_outcome.status, f.status) << to_string(f.scheme) << ": " << c.subject_outcome.summary();
    if (f.status != RunStatus::Ok) {
        EXPECT_NE(c.subject_outcome.message.find(f.in_message), std::string::npos) << c.subject_outcome.message;
        EXPECT_TRUE(c.subject_failed());
        EXPECT_TRUE(c.runs.empty());
        return;
    }
    if (std::string_view(f.mode) != "shuffle") {
        // The right positions, faces that are not the scheme's: a failure naming the faces.
        EXPECT_TRUE(c.subject_failed()) << to_string(f.scheme) << " " << f.mode;
        EXPECT_TRUE(c.runs.empty());
        const std::string why = c.subject_topology.empty() ? c.subject_unmatched : c.subject_topology;
        EXPECT_NE(why.find(f.in_message), std::string::npos) << to_string(f.scheme) << " " << f.mode << ": " << why;
        return;
    }
    // Shuffled: matched by position, and the example's rule is named whatever the numbering.
    ASSERT_FALSE(c.subject_failed()) << c.subject_unmatched;
    EXPECT_EQ(c.subject_match.method, MatchMethod::Nearest);
    ASSERT_TRUE(c.rules && c.rules->rule) << to_string(f.scheme);
    const std::string rule = rule_name(f.scheme, *c.rules->rule);
    const std::string want = f.scheme == Scheme::Loop                 ? "weights=loop boundary=edge-only"
                             : f.scheme == Scheme::CatmullClark        ? "edge-only"
                             : f.scheme == Scheme::DooSabin            ? "drop-border-faces"
                             : f.scheme == Scheme::Sqrt3               ? "restart-each-level"
                             : f.scheme == Scheme::Bilinear || f.scheme == Scheme::Midpoint ? "linear"
                                                                       : "reflected-wings";
    EXPECT_EQ(rule, want) << to_string(f.scheme);
}

std::vector<SchemeFailure> every_scheme_failure() {
    std::vector<SchemeFailure> out;
    for (Scheme s : all_schemes()) {
        out.push_back({s, "crash", RunStatus::Crashed, "signal 11"});
        out.push_back({s, "hang", RunStatus::Timeout, "no result after 2 s"});
        out.push_back({s, "nothing", RunStatus::NoOutput, "no output file out.obj"});
        out.push_back({s, "nan", RunStatus::NonFiniteOutput, "is nan"});
        out.push_back({s, "wrong-count", RunStatus::WrongCount, s == Scheme::DooSabin
                                                                    ? "(drop-border-faces)"
                                                                    : " makes "});
        out.push_back({s, "shuffle", RunStatus::Ok, ""});
        out.push_back({s, "reversed", RunStatus::Ok, "its faces are not core's: at level 1, "});
        out.push_back({s, "duplicate-face", RunStatus::Ok, "(first: face "});
    }
    out.push_back({Scheme::Loop, "scrambled", RunStatus::Ok, "its faces are not core's"});
    return out;
}

INSTANTIATE_TEST_SUITE_P(EveryScheme, SchemeProgramFailure, ::testing::ValuesIn(every_scheme_failure()),
                         [](const auto& info) {
                             std::string n = std::string(to_string(info.param.scheme)) + "_" + info.param.mode;
                             for (char& ch : n)
                                 if (ch == '-') ch = '_';
                             return n;
                         });

TEST(Program, ThatCannotStartIsRecorded) {
    const auto subject = program("/nonexistent/loop {in} {out}");
    const RefinementComparison c = compare_with(*subject, "tetrahedron", 1);
    EXPECT_EQ(c.subject_outcome.status, RunStatus::Crashed);
    EXPECT_NE(c.subject_outcome.message.find("cannot start"), std::string::npos) << c.subject_outcome.message;
}

/// Whether process `pid` is gone (or a zombie no one will ever run again).
bool process_gone(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    if (!std::getline(stat, text)) return true;
    const size_t close = text.rfind(')');
    return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z';
}

pid_t pid_in(const fs::path& file) {
    std::ifstream in(file);
    long pid = 0;
    in >> pid;
    return static_cast<pid_t>(pid);
}

TEST(Program, ThatLeavesAChildOutsideItsProcessGroupHasItKilledAtTheEndOfItsRun) {
    // The child calls setsid(): the kill of the program's group misses it; re-parented here
    // (adopt_orphans, as crossdiv's main does), it is found and killed when the run ends.
    adopt_orphans();
    const fs::path pidfile = fs::temp_directory_path() / ("crossdiv-escape-" + std::to_string(::getpid()) + ".pid");
    fs::remove(pidfile);
    const auto subject = program(misbehaving("escape") + " loop " + pidfile.string(), 60, LevelMode::Final);
    const RefinementComparison c = compare_with(*subject, "tetrahedron", 1);
    EXPECT_EQ(c.subject_outcome.status, RunStatus::Ok) << c.subject_outcome.summary();
    const pid_t escaped = pid_in(pidfile);
    ASSERT_GT(escaped, 1);
    EXPECT_TRUE(process_gone(escaped)) << "process " << escaped << " outlived the run";
    if (!process_gone(escaped)) ::kill(escaped, SIGKILL);
    fs::remove(pidfile);
}

TEST(Program, ThatAsksForMoreMemoryThanItsCapFailsFast) {
#ifndef CROSSDIV_SANITIZED  // no cap under the address sanitizer (process.h)
    // 8 GiB at once is past kProgramMemoryBytes (6 GiB): Python's MemoryError, exit status 1.
    // Without the cap the kernel grants it (untouched pages) and the run succeeds.
    const auto subject = program(misbehaving("hog"), 60, LevelMode::Final);
    const RefinementComparison c = compare_with(*subject, "tetrahedron", 1);
    EXPECT_EQ(c.subject_outcome.status, RunStatus::ExitStatus) << c.subject_outcome.summary();
    EXPECT_NE(c.subject_outcome.message.find("MemoryError"), std::string::npos) << c.subject_outcome.message;
#endif
}

TEST(Process, StderrIsReadByItsHeadAndTailOnly) {
    // 64 MiB of a program's stderr: the sanitizer's first line at the head and the last words
    // at the tail are kept; the middle is never read.
    const fs::path file = fs::temp_directory_path() / ("crossdiv-stderr-" + std::to_string(::getpid()) + ".txt");
    {
        std::ofstream out(file, std::ios::binary);
        out << "==1==ERROR: AddressSanitizer: heap-buffer-overflow on address 0x1\n";
        const std::string line(1023, 'x');
        for (int i = 0; i < 64 * 1024; ++i) out << line << "\n";
        out << "the last words\n";
    }
    const std::string summary = tail_of_file(file.string());
    EXPECT_EQ(summary.rfind("==1==ERROR: AddressSanitizer: heap-buffer-overflow on address 0x1 ...", 0), 0u) << summary.substr(0, 200);
    EXPECT_TRUE(summary.ends_with("the last words")) << summary;
    const int fd = ::open(file.c_str(), O_RDONLY);
    EXPECT_EQ(head_and_tail(fd, 100).size(), 100u + 5u + 100u);
    ::close(fd);
    fs::remove(file);
}

TEST(Program, InAnotherNumberingIsMatchedByPositionAndAgrees) {
    const auto subject = program(misbehaving("shuffle"));
    const RefinementComparison c = compare_with(*subject, "open-patch", 2);
    ASSERT_FALSE(c.subject_failed()) << c.subject_outcome.summary() << c.subject_unmatched;
    // Old vertices are not first, so provenance cannot match it: positions do, at every level.
    EXPECT_EQ(c.subject_match.method, MatchMethod::Nearest);
    ASSERT_TRUE(c.rules && c.rules->rule);
    EXPECT_EQ(c.rules->rule->loop, (LoopOptions{LoopWeights::Loop, LoopBoundary::EdgeOnly}));
    EXPECT_EQ(c.rules->classified_level, 1);
    ASSERT_FALSE(c.runs.empty());
    for (const RefinementRun& r : c.runs) EXPECT_EQ(r.verdict, Verdict::Agree) << r.reference << ": " << r.explanation;
}

const RuleFit& fit(const VertexClassRow& row, LoopWeights w, LoopBoundary b) {
    for (const RuleFit& f : row.fits)
        if (f.rule.loop == LoopOptions{w, b}) return f;
    throw std::logic_error("no such rule");
}

const VertexClassRow& row(const RuleIdentification& id, VertexClass cls, int valence = 0) {
    for (const VertexClassRow& r : id.rows)
        if (r.cls == cls && r.valence == valence) return r;
    throw std::logic_error(std::string("no row ") + to_string(cls));
}

TEST(RuleIdentification, TheCourseStudentFollowsWarrenAtInteriorVerticesAndHasNoCornerRule) {
    const auto subject = program(kStudent);
    // The icosahedron: every vertex of valence 5, where Warren's beta 3/40 differs from Loop's.
    const RefinementComparison ico = compare_with(*subject, "icosahedron", 2);
    ASSERT_TRUE(ico.rules);
    const VertexClassRow& v5 = row(*ico.rules, VertexClass::InteriorVertex, 5);
    EXPECT_EQ(v5.count, 12);
    EXPECT_TRUE(fit(v5, LoopWeights::Warren, LoopBoundary::EdgeOnly).fits);
    EXPECT_FALSE(fit(v5, LoopWeights::Loop, LoopBoundary::EdgeOnly).fits);
    EXPECT_EQ(row(*ico.rules, VertexClass::InteriorEdgePoint).count, 30);
    ASSERT_TRUE(ico.rules->rule);
    EXPECT_EQ(ico.rules->rule->loop.weights, LoopWeights::Warren);
    for (const RefinementRun& r : ico.runs) {
        EXPECT_EQ(r.verdict, Verdict::Diverge) << r.reference << ": " << r.explanation;
        EXPECT_EQ(r.divergence_class, DivergenceClass::WeightFamily) << r.reference << ": " << r.explanation;
    }
    // The open patch: its two one-face corners are moved by the boundary mask (no corner rule).
    const RefinementComparison patch = compare_with(*subject, "open-patch", 2);
    ASSERT_TRUE(patch.rules);
    const VertexClassRow& corner = row(*patch.rules, VertexClass::Corner);
    EXPECT_EQ(corner.count, 2);
    EXPECT_TRUE(fit(corner, LoopWeights::Warren, LoopBoundary::EdgeOnly).fits);
    EXPECT_FALSE(fit(corner, LoopWeights::Warren, LoopBoundary::EdgeAndCorner).fits);

    RuleTally tally;
    tally.add(*ico.rules);
    tally.add(*patch.rules);
    EXPECT_EQ(tally.rule_phrase(), "Loop scheme, weights=warren at interior vertices (valence 5..6), edge-only boundary, "
                                   "no corner rule");
    EXPECT_EQ(tally.core_phrase().rfind("agrees with core weights=warren boundary=edge-only to ", 0), 0u) << tally.core_phrase();
    EXPECT_NE(tally.core_phrase().find("on 2 of 2 meshes"), std::string::npos) << tally.core_phrase();
}

TEST(RuleIdentification, FinalLevelOnlyIdentifiesTheWholeMeshRule) {
    const auto subject = program(kStudent, 60, LevelMode::Final);
    const RefinementComparison c = compare_with(*subject, "icosahedron", 2);
    ASSERT_TRUE(c.rules);
    EXPECT_EQ(c.rules->classified_level, 0);
    EXPECT_TRUE(c.rules->rows.empty());
    ASSERT_TRUE(c.rules->rule);
    EXPECT_EQ(c.rules->rule->loop.weights, LoopWeights::Warren);
}

TEST(ResultFile, ASubmittedResultIsComparedAtItsLevel) {
    const std::string path = (std::filesystem::temp_directory_path() / "crossdiv_result_file_test.obj").string();
    write_mesh(path, to_poly_mesh(loop_subdivide(bundled("octahedron"), {LoopWeights::Loop, LoopBoundary::EdgeOnly}, 2)));
    const auto subject = make_result_file_implementation("submitted", path, Scheme::Loop);
    const RefinementComparison c = compare_with(*subject, "octahedron", 2);
    ASSERT_FALSE(c.subject_failed()) << c.subject_outcome.summary();
    for (const RefinementRun& r : c.runs) EXPECT_EQ(r.verdict, Verdict::Agree) << r.reference << ": " << r.explanation;
    // At another level its counts are wrong: named, not compared.
    const RefinementComparison wrong = compare_with(*subject, "octahedron", 1);
    EXPECT_EQ(wrong.subject_outcome.status, RunStatus::WrongCount) << wrong.subject_outcome.summary();
    std::filesystem::remove(path);
}

// Shrinking driven by a subject: what no named rule explains, or a failure, down to a mesh
// small enough to read.
RefinementRequest subject_alone(const Implementation& subject, int levels) {
    RefinementRequest req;
    req.levels = levels;
    req.subject = &subject;
    req.without_references = true;
    return req;
}

TEST(ShrinkSubject, ABoundaryLeftInPlaceShrinksToTwoTriangles) {
    // No named rule keeps a boundary vertex of two faces in place (a one-face corner kept in
    // place is the corner rule), so the smallest mesh showing it has a boundary vertex with
    // two faces: two triangles.
    const auto subject = program(misbehaving("keep-boundary"));
    const ShrinkResult r = shrink_divergence(datasets::bundled_mesh("open-patch"), "open-patch", subject_alone(*subject, 2));
    EXPECT_EQ(r.symptom.kind, ShrinkSymptom::Kind::SubjectFollowsNoRule);
    EXPECT_EQ(r.minimal.num_faces(), 2);
    EXPECT_EQ(r.minimal.num_vertices(), 4);
    ASSERT_TRUE(r.minimal_comparison.rules);
    EXPECT_FALSE(r.minimal_comparison.rules->rule);
    // The classes that fit: interior edge point (one) and boundary edge points (four).
    for (const VertexClassRow& row : r.minimal_comparison.rules->rows) {
        const bool some_rule_fits =
            std::any_of(row.fits.begin(), row.fits.end(), [](const RuleFit& f) { return f.fits; });
        EXPECT_EQ(some_rule_fits, row.cls != VertexClass::BoundaryVertex) << to_string(row.cls);
    }
}

TEST(ShrinkSubject, AFailureShrinksToTheSmallestInputThatStillFailsTheSameWay) {
    const auto subject = program(misbehaving("closed-only"));
    const ShrinkResult r = shrink_divergence(datasets::bundled_mesh("open-patch"), "open-patch", subject_alone(*subject, 1));
    EXPECT_EQ(r.symptom.kind, ShrinkSymptom::Kind::SubjectFails);
    EXPECT_EQ(r.symptom.status, RunStatus::ExitStatus);
    EXPECT_EQ(r.minimal.num_faces(), 1);
    EXPECT_EQ(r.minimal_comparison.subject_outcome.status, RunStatus::ExitStatus);
}

TEST(ShrinkSubject, AgainstAReferenceKeepsTheReferencesDivergenceClass) {
    const auto subject = program(misbehaving("keep-boundary"));
    RefinementRequest req;
    req.levels = 1;
    req.subject = subject.get();
    req.references = {"opensubdiv"};
    const ShrinkResult r = shrink_divergence(datasets::bundled_mesh("open-patch"), "open-patch", req);
    EXPECT_EQ(r.symptom.kind, ShrinkSymptom::Kind::ReferenceDiverges);
    EXPECT_EQ(r.symptom.divergence_class, DivergenceClass::Unexplained);
    EXPECT_EQ(r.minimal.num_faces(), 2);
    EXPECT_EQ(r.minimal_comparison.runs.at(0).divergence_class, DivergenceClass::Unexplained);
}

TEST(ShrinkSubject, ASubjectThatFollowsANamedRuleHasNothingToShrink) {
    const auto student = program(kStudent);
    EXPECT_THROW(shrink_divergence(datasets::bundled_mesh("open-patch"), "open-patch", subject_alone(*student, 1)), InputError);
}


// Subjects of the other schemes: a callback in core's place, whose rule is named from core's
// named rules of its scheme, class by class where the scheme is primal.
std::unique_ptr<Implementation> core_as_subject(Scheme scheme, SchemeRule rule) {
    return make_callback_implementation("mine", {scheme}, [scheme, rule](const PolyMesh& m, const RefineRequest& r) {
        return core_implementation().refine_last(m, {scheme, rule, r.levels});
    });
}

/// `subject` in core's place under `scheme` on a bundled mesh, two levels.
RefinementComparison compare_scheme_subject(Scheme scheme, const Implementation& subject, const std::string& mesh,
                                            bool with_references) {
    RefinementRequest req;
    req.scheme = scheme;
    req.levels = 2;
    req.subject = &subject;
    req.without_references = !with_references;
    return compare_refinement(datasets::bundled_mesh(mesh), mesh, req);
}

const VertexClassRow* class_row(const RuleIdentification& id, VertexClass cls, int valence = 0) {
    for (const VertexClassRow& r : id.rows)
        if (r.cls == cls && r.valence == valence) return &r;
    return nullptr;
}

TEST(SchemeSubject, WhenNoRuleOfItsSchemeFitsTheSchemesWithItsConnectivityAreTried) {
    // A midpoint subdivision handed in as Loop: no Loop rule fits, and at level 1 it is the
    // midpoint scheme, whose connectivity is Loop's; no Butterfly fits it.
    const auto midpoint = program(misbehaving("midpoint"));
    const RefinementComparison mid = compare_with(*midpoint, "open-patch", 2);
    ASSERT_TRUE(mid.rules) << mid.subject_outcome.summary();
    EXPECT_FALSE(mid.rules->rule);
    const OtherSchemeFit* it = mid.rules->other_scheme();
    ASSERT_TRUE(it);
    EXPECT_EQ(it->scheme, Scheme::Midpoint);
    EXPECT_EQ(it->label(), "midpoint");
    EXPECT_EQ(it->max_rel, 0);  // the same sums in the same order
    for (const OtherSchemeFit& f : mid.rules->other_schemes) {
        if (f.scheme == Scheme::Butterfly || f.scheme == Scheme::ModifiedButterfly) {
            EXPECT_FALSE(f.fits) << f.label();
        }
    }

    // The classic Butterfly handed in as the modified one: at level 1 it is the classic one;
    // every Loop rule is off by the difference between approximating and interpolating.
    ProgramSpec spec;
    spec.name = "classic";
    spec.command = "python3 " + kSource + "/examples/subjects/python-schemes/butterfly.py {in} {levels} {out}";
    spec.schemes = {Scheme::ModifiedButterfly};
    const auto classic = make_program_implementation(spec);
    RefinementRequest req;
    req.scheme = Scheme::ModifiedButterfly;
    req.levels = 2;
    req.subject = classic.get();
    const RefinementComparison b = compare_refinement(datasets::bundled_mesh("icosahedron"), "icosahedron", req);
    ASSERT_TRUE(b.rules) << b.subject_outcome.summary();
    EXPECT_FALSE(b.rules->rule);
    ASSERT_TRUE(b.rules->other_scheme());
    EXPECT_EQ(b.rules->other_scheme()->scheme, Scheme::Butterfly);
    for (const OtherSchemeFit& f : b.rules->other_schemes) {
        if (f.scheme == Scheme::Loop) {
            EXPECT_GT(f.max_rel, 0.01) << f.label();
        }
    }

    // A subject that follows a rule of its scheme is not measured against the others.
    const auto student = program(kStudent);
    const RefinementComparison own = compare_with(*student, "icosahedron", 2);
    ASSERT_TRUE(own.rules && own.rules->rule);
    EXPECT_TRUE(own.rules->other_schemes.empty());
}

TEST(SchemeSubject, IsGivenTheTagsInItsObjAndOneThatReadsPastThemIsNamedSo) {
    // A cube whose top edges are sharp (sharpness 10), as OpenSubdiv's OBJ states them.
    PolyMesh cube = datasets::crease_cube(datasets::CreaseCubeVariant::SharpTop);
    const auto run = [&](const std::string& command) {
        ProgramSpec spec;
        spec.name = "cc";
        spec.command = command;
        spec.schemes = {Scheme::CatmullClark};
        const auto subject = make_program_implementation(spec);
        RefinementRequest req;
        req.scheme = Scheme::CatmullClark;
        req.levels = 2;
        req.subject = subject.get();
        return compare_refinement(cube, "creased-cube", req);
    };
    // crossdiv's own subdivide reads the 't' lines of {in}: it follows the tags.
    const RefinementComparison own =
        run(test::kCrossdiv + " subdivide {in} --scheme catmull-clark --levels {levels} -o {out}");
    ASSERT_TRUE(own.core_error.empty()) << own.core_error;
    ASSERT_EQ(own.subject_outcome.status, RunStatus::Ok) << own.subject_outcome.summary();
    ASSERT_TRUE(own.rules && own.rules->rule) << own.subject_unmatched;
    EXPECT_EQ(own.rules->rule->catmull_clark.boundary, CatmullClarkBoundary::EdgeOnly);
    // The course program skips the 't' lines: no rule fits, and it is core on the untagged cube.
    const std::string course = "python3 " + kSource + "/examples/subjects/python-schemes/catmull_clark.py ";
    const RefinementComparison skips = run(course + "{in} {levels} {out}");
    ASSERT_TRUE(skips.rules) << skips.subject_outcome.summary();
    EXPECT_FALSE(skips.rules->rule);
    ASSERT_TRUE(skips.rules->other_scheme());
    EXPECT_EQ(skips.rules->other_scheme()->scheme, Scheme::CatmullClark);
    EXPECT_EQ(skips.rules->other_scheme()->rule, "edge-only, tags ignored");
    // Given the OBJ without tags, the program is refused the tagged input, the tags named.
    const RefinementComparison untagged = run(course + "{in.untagged} {levels} {out}");
    EXPECT_EQ(untagged.subject_outcome.status, RunStatus::Rejected);
    EXPECT_NE(untagged.subject_outcome.message.find("4 crease and 0 corner tag(s)"), std::string::npos)
        << untagged.subject_outcome.message;
    // The untagged cube is its input: it is compared as any subject.
    cube.creases = {};
    const RefinementComparison plain = run(course + "{in.untagged} {levels} {out}");
    ASSERT_TRUE(plain.rules && plain.rules->rule) << plain.subject_outcome.summary();
}

TEST(SchemeSubject, ACatmullClarkWithOpenMeshsBoundaryIsNamedClassByClass) {
    const auto mine = core_as_subject(Scheme::CatmullClark, rule_from_boundary_name(Scheme::CatmullClark, "midpoint-average"));
    const RefinementComparison c = compare_scheme_subject(Scheme::CatmullClark, *mine, "quad-grid", true);
    ASSERT_FALSE(c.subject_failed()) << c.subject_outcome.summary() << c.subject_unmatched;
    ASSERT_TRUE(c.rules && c.rules->rule);
    EXPECT_EQ(c.rules->rule->catmull_clark.boundary, CatmullClarkBoundary::MidpointAverage);
    // Level 1, class by class: the face points (quads) and the interior fit every rule; the
    // boundary vertices only midpoint-average.
    const VertexClassRow* faces = class_row(*c.rules, VertexClass::FacePoint, 4);
    const VertexClassRow* boundary = class_row(*c.rules, VertexClass::BoundaryVertex);
    ASSERT_TRUE(faces && boundary);
    EXPECT_TRUE(std::all_of(faces->fits.begin(), faces->fits.end(), [](const RuleFit& f) { return f.fits; }));
    for (const RuleFit& f : boundary->fits)
        EXPECT_EQ(f.fits, f.rule.catmull_clark.boundary == CatmullClarkBoundary::MidpointAverage) << f.name;
    for (const RefinementRun& r : c.runs) {
        SCOPED_TRACE(r.reference + ": " + r.explanation);
        if (r.rule.starts_with("midpoint-average")) EXPECT_EQ(r.verdict, Verdict::Agree);
        else EXPECT_EQ(r.divergence_class, DivergenceClass::BoundaryRule);
    }
}

TEST(SchemeSubject, ATaggedMeshsVerticesAreClassedByTheirSharpEdges) {
    // crease-cube-top: the top face's four edges are sharp. By hand: each top vertex has two
    // sharp edges (crease-vertex, 4), each bottom vertex none (interior, valence 3, 4); four
    // crease edge points and eight smooth ones; six face points.
    const auto follows = core_as_subject(Scheme::CatmullClark, rule_from_boundary_name(Scheme::CatmullClark, "edge-only"));
    const RefinementComparison c = compare_scheme_subject(Scheme::CatmullClark, *follows, "crease-cube-top", false);
    ASSERT_TRUE(c.rules && c.rules->rule) << c.subject_outcome.summary() << c.subject_unmatched;
    const std::vector<std::tuple<VertexClass, int, int>> want{{VertexClass::CreaseVertex, 0, 4},
                                                              {VertexClass::InteriorVertex, 3, 4},
                                                              {VertexClass::CreaseEdgePoint, 0, 4},
                                                              {VertexClass::InteriorEdgePoint, 0, 8},
                                                              {VertexClass::FacePoint, 4, 6}};
    ASSERT_EQ(c.rules->rows.size(), want.size());
    for (const auto& [cls, valence, count] : want) {
        const VertexClassRow* row = class_row(*c.rules, cls, valence);
        ASSERT_TRUE(row) << to_string(cls);
        EXPECT_EQ(row->count, count) << to_string(cls);
    }
    // The course program reads past the tags: only the crease classes fit no rule.
    ProgramSpec spec;
    spec.name = "cc";
    spec.command = "python3 " + kSource + "/examples/subjects/python-schemes/catmull_clark.py {in} {levels} {out}";
    spec.schemes = {Scheme::CatmullClark};
    const auto course = make_program_implementation(spec);
    const RefinementComparison skips = compare_scheme_subject(Scheme::CatmullClark, *course, "crease-cube-top", false);
    ASSERT_TRUE(skips.rules) << skips.subject_outcome.summary();
    for (const VertexClassRow& row : skips.rules->rows) {
        const bool fits = std::any_of(row.fits.begin(), row.fits.end(), [](const RuleFit& f) { return f.fits; });
        EXPECT_EQ(fits, row.cls != VertexClass::CreaseVertex && row.cls != VertexClass::CreaseEdgePoint) << to_string(row.cls);
    }
}

TEST(SchemeSubject, ARuleCoreRefusesOnTheInputFitsNothingAndTheOthersAreMeasured) {
    // A tagged mesh: core has no midpoint-average rule with crease tags (it refuses the input
    // under it), so that rule does not fit; the subject is named edge-only.
    const auto mine = core_as_subject(Scheme::CatmullClark, rule_from_boundary_name(Scheme::CatmullClark, "edge-only"));
    const RefinementComparison c = compare_scheme_subject(Scheme::CatmullClark, *mine, "crease-cube-top", false);
    ASSERT_TRUE(c.rules && c.rules->rule) << c.subject_outcome.summary() << c.subject_unmatched;
    EXPECT_EQ(rule_name(Scheme::CatmullClark, *c.rules->rule), "edge-only");
    for (const RuleFit& f : c.rules->whole) {
        if (f.rule.catmull_clark.boundary == CatmullClarkBoundary::MidpointAverage) {
            EXPECT_FALSE(f.fits) << f.name;
        }
    }
}

TEST(SchemeSubject, ADooSabinThatDropsTheBorderIsMatchedInThatRulesNumbering) {
    // Dropping the border faces changes the vertex set: the subject is matched to core under
    // the rule whose levels it has, and named by it.
    const auto mine = core_as_subject(Scheme::DooSabin, rule_from_boundary_name(Scheme::DooSabin, "drop-border-faces"));
    const RefinementComparison c = compare_scheme_subject(Scheme::DooSabin, *mine, "quad-grid", false);
    ASSERT_TRUE(c.rules && c.rules->rule) << c.subject_outcome.summary() << c.subject_unmatched;
    EXPECT_EQ(rule_name(Scheme::DooSabin, *c.rules->rule), "drop-border-faces");
    // Its corner points by face size and boundary: the 4 x 4 quad grid has 64 corners, 36 of
    // them at its 9 interior vertices; on quads Doo and Sabin's weights and Catmull and Clark's
    // are the same, so every rule with the grid's vertex count fits.
    ASSERT_EQ(c.rules->rows.size(), 2u);
    EXPECT_EQ(c.rules->rows[0].cls, VertexClass::CornerPoint);
    EXPECT_EQ(c.rules->rows[0].valence, 4);
    EXPECT_EQ(c.rules->rows[0].count, 36);
    EXPECT_EQ(c.rules->rows[1].cls, VertexClass::BoundaryCornerPoint);
    EXPECT_EQ(c.rules->rows[1].count, 28);
    for (const VertexClassRow& row : c.rules->rows)
        for (const RuleFit& f : row.fits) EXPECT_EQ(f.fits, f.rule.doo_sabin.boundary == DooSabinBoundary::DropBorderFaces) << f.name;
}

TEST(SchemeSubject, AWrongWeightFitsNoRuleAndAFailureIsTheSubjectsForEveryScheme) {
    // sqrt3 whose new points are pulled a thousandth of the way to vertex 0 (still matched by
    // position, as a dual scheme is): no rule fits.
    const auto off = make_callback_implementation("off", {Scheme::Sqrt3}, [](const PolyMesh& m, const RefineRequest& r) {
        PolyMesh out = core_implementation().refine_last(m, r);
        for (int v = m.num_vertices(); v < out.num_vertices(); ++v) out.positions[v] += 1e-3 * (out.positions[0] - out.positions[v]);
        return out;
    });
    RefinementRequest req;
    req.scheme = Scheme::Sqrt3;
    req.levels = 1;
    req.subject = off.get();
    req.without_references = true;
    const RefinementComparison c = compare_refinement(datasets::bundled_mesh("icosahedron"), "icosahedron", req);
    ASSERT_TRUE(c.rules.has_value()) << c.subject_unmatched;
    EXPECT_FALSE(c.rules->rule.has_value());
    for (const Scheme scheme : {Scheme::CatmullClark, Scheme::Butterfly, Scheme::Bilinear}) {
        const auto crashing = make_callback_implementation("crashing", {scheme}, [](const PolyMesh&, const RefineRequest&) -> PolyMesh {
            std::abort();
        });
        const RefinementComparison failed = compare_scheme_subject(scheme, *crashing, "octahedron", false);
        EXPECT_TRUE(failed.subject_failed()) << to_string(scheme);
        EXPECT_EQ(failed.subject_outcome.status, RunStatus::Crashed) << to_string(scheme);
    }
}

}  // namespace
}  // namespace crossdiv::verification
