// The default suite fails on realistic bugs in core: each fault is seeded through a test
// double (a stand-in for core's implementation, or for one feature the suite's checks call),
// never by editing core, and the default manifest's jobs that cover the feature are run as
// `crossdiv suite` runs them. Each must end with failures (the command's exit 1) and a JUnit
// failure naming the feature; the same jobs with core pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <unistd.h>

#include "crossdiv/mesh/halfedge_mesh.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/surfaces/sweep_mesh.h"
#include "crossdiv/verification/harness/mesh_topology.h"
#include "crossdiv/verification/implementations/callback_implementation.h"
#include "crossdiv/verification/implementations/registry.h"
#include "crossdiv/verification/suite/features_under_test.h"
#include "crossdiv/verification/suite/manifest.h"
#include "crossdiv/verification/suite/operations.h"
#include "crossdiv/verification/suite/outputs.h"
#include "crossdiv/verification/suite/runner.h"
#include "fault_doubles.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;

/// What a run of some of the default manifest's jobs left: its failures and junit.xml.
struct SuiteRun {
    int failures = 0;
    std::string junit;
};

/// A job of `operation` whose id contains `id_part`.
struct JobKind {
    std::string operation, id_part;
};

#ifdef CROSSDIV_SANITIZED
/// Under the sanitizers the jobs that must pass are every third job of each kind: each
/// feature's code still runs on several inputs (the first of each kind among them); the release
/// build runs them all. (All of them took 222 s of the sanitizer run.)
constexpr size_t kPassingJobStride = 3;
#else
constexpr size_t kPassingJobStride = 1;
#endif

/// A planted fault is run through every third job of each kind (every ninth under the
/// sanitizers; the first among them): the suite's failures are the union of its jobs'
/// failures, so a fault that fails a part of the default suite's jobs fails the whole suite.
/// (All the jobs took 39 s of the release run for the Catmull-Clark fault alone, 71 s for the
/// seven faults; every third job 48 s under the sanitizers for that one fault.)
constexpr size_t kFaultJobStride = 3 * kPassingJobStride;

/// The library references of a comparison case: its named references without the programs
/// (all references of its scheme when it names none). External programs (Open3D, MeshLab,
/// Blender, started once per run: 1 to 2 s each, 4 of the 6 minutes these jobs took with them)
/// compare the same core result that the libraries compare, and add nothing to what a fault in
/// core does to the suite. Empty when it names programs only: such a job is left out.
std::vector<std::string> library_references(const ManifestEntry& e) {
    std::vector<std::string> names;
    if (e.request.references.empty()) {
        for (const Implementation* r : references_for(e.request.scheme))
            if (r->kind() != ImplementationKind::Program) names.push_back(r->name());
    } else {
        for (const std::string& name : e.request.references)
            if (find_implementation(name).kind() != ImplementationKind::Program) names.push_back(name);
    }
    return names;
}

/// The default manifest's jobs of those kinds (every `stride`-th of each kind, the first
/// always; a comparison against its library references only), run with two workers, the
/// outputs written as `crossdiv suite` writes them.
SuiteRun run_default_jobs(const std::vector<JobKind>& kinds, size_t stride) {
    static const Manifest manifest = read_manifest(default_manifest_path());
    static std::deque<ManifestEntry> library_entries;  // the jobs' entries without their programs
    std::vector<SuiteJob> jobs;
    std::vector<size_t> seen(kinds.size(), 0);
    for (SuiteJob j : expand_jobs(manifest))
        for (size_t k = 0; k < kinds.size(); ++k) {
            if (j.entry->operation->name != kinds[k].operation || j.id.find(kinds[k].id_part) == std::string::npos) continue;
            if (j.entry->operation->kind == OperationKind::Comparison) {
                ManifestEntry e = *j.entry;
                e.request.references = library_references(e);
                if (e.request.references.empty()) break;
                j.entry = &library_entries.emplace_back(std::move(e));
            }
            if (seen[k]++ % stride == 0) jobs.push_back(j);
            break;
        }
    EXPECT_FALSE(jobs.empty());
    const fs::path dir = fs::temp_directory_path() / ("crossdiv-faults-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::vector<CaseRecord> records = run_jobs(jobs, 2, dir.string(), [](int, int, const CaseRecord&) {});
    const SuiteSummary summary = write_suite_outputs(dir.string(), {{"tool", "crossdiv suite"}, {"suite", "default"}}, records);
    std::ifstream in(dir / "junit.xml");
    std::stringstream text;
    text << in.rdbuf();
    fs::remove_all(dir);
    return {summary.failures, text.str()};
}

/// The first failing test case of junit.xml that names `feature` (recorded in the test's
/// output for a reader), or nothing.
std::optional<std::string> junit_failure(const std::string& junit, const std::string& feature) {
    size_t at = 0;
    while ((at = junit.find("<testcase", at)) != std::string::npos) {
        const size_t end = junit.find("</testcase>", at);
        const std::string one = junit.substr(at, end == std::string::npos ? std::string::npos : end - at);
        if (one.find("<failure") != std::string::npos && one.find(feature) != std::string::npos) return one;
        at += 9;
    }
    return std::nullopt;
}

/// Every failing test case of junit.xml, for the message of a test that expected none.
std::string junit_failures(const std::string& junit) {
    std::string all;
    for (size_t at = 0; (at = junit.find("<testcase", at)) != std::string::npos; at += 9) {
        const size_t end = junit.find("</testcase>", at);
        const std::string one = junit.substr(at, end == std::string::npos ? std::string::npos : end - at);
        if (one.find("<failure") != std::string::npos) all += one + "\n";
    }
    return all;
}

bool junit_fails(const std::string& junit, const std::string& feature) {
    const std::optional<std::string> f = junit_failure(junit, feature);
    if (f) ::testing::Test::RecordProperty(feature, *f);
    return f.has_value();
}

/// The jobs of those kinds end with failures (`crossdiv suite` exits 1), and junit.xml has a
/// failing test case naming each of `features`.
void expect_failures_naming(const std::vector<JobKind>& kinds, const std::vector<std::string>& features) {
    const SuiteRun run = run_default_jobs(kinds, kFaultJobStride);
    EXPECT_GT(run.failures, 0);
    for (const std::string& f : features) EXPECT_TRUE(junit_fails(run.junit, f)) << f;
}

/// Core's implementation with `slip` applied to each level of `scheme` under `applies`.
std::unique_ptr<Implementation> core_with_slip(Scheme scheme, std::function<bool(const SchemeRule&)> applies,
                                               std::function<void(const PolyMesh& coarse, PolyMesh& fine)> slip) {
    const Implementation& core = core_implementation();
    return make_callback_implementation(
        "core", {Scheme::Loop, Scheme::CatmullClark, Scheme::DooSabin, Scheme::Sqrt3, Scheme::Butterfly, Scheme::ModifiedButterfly},
        [&core, scheme, applies, slip](const PolyMesh& mesh, const RefineRequest& request) {
            if (request.scheme != scheme || !applies(request.rule)) return core.refine_last(mesh, request);
            PolyMesh current = mesh;
            for (int l = 0; l < request.levels; ++l) {
                RefineRequest one = request;
                one.levels = 1;
                PolyMesh next = core.refine_last(current, one);
                slip(current, next);
                current = std::move(next);
            }
            return current;
        });
}

TEST(SuiteFaults, TheJobsThatCoverEachFeaturePassWithCore) {
    const SuiteRun run = run_default_jobs({{"edits", ""}, {"normals", ""}, {"spectrum", ""}, {"schemes", ""},
                                           {"catmull-clark", "bundled:"}, {"doo-sabin", "bundled:"},
                                           {"sqrt3", "bundled:"}, {"modified-butterfly", "bundled:"},
                                           {"surfaces", "surface:vase"}, {"loop", "warren boundary=edge-only L2 weak"},
                                           {"loop", "warren boundary=edge-only L3 geometric"}},
                                          kPassingJobStride);
    EXPECT_EQ(run.failures, 0) << junit_failures(run.junit);
}

TEST(SuiteFaults, AFlipThatForgetsTheVertexHalfedgeFails) {
    FeaturesUnderTest f;
    f.edits.flip = [](HalfedgeMesh& m, EdgeId e) {
        const HalfedgeId h = HalfedgeMesh::halfedge(e);
        const VertexId a = m.origin(h);
        const FlipRefusal r = m.flip(e);
        if (r == FlipRefusal::None) m.set_vertex_halfedge(a, h);  // h no longer leaves a
        return r;
    };
    const ScopedFeaturesUnderTest fault(std::move(f));
    expect_failures_naming({{"edits", "bundled:"}}, {"edit-differential"});
}

TEST(SuiteFaults, ASplitAtTheEdgesOriginFails) {
    FeaturesUnderTest f;
    f.edits.split = [](HalfedgeMesh& m, std::vector<Vec3>& positions, EdgeId e) {
        const VertexId a = m.origin(HalfedgeMesh::halfedge(e));
        const VertexId v = split_at_midpoint(m, positions, e);
        positions[static_cast<size_t>(v.idx)] = positions[static_cast<size_t>(a.idx)];
        return v;
    };
    const ScopedFeaturesUnderTest fault(std::move(f));
    expect_failures_naming({{"edits", "bundled:"}}, {"edit-differential"});
}

TEST(SuiteFaults, AreaAndUniformNormalWeightingSwappedFails) {
    FeaturesUnderTest f;
    f.normals = [](const TriMesh& mesh, NormalWeighting w) {
        if (w == NormalWeighting::Area) return vertex_normals(mesh, NormalWeighting::Uniform);
        if (w == NormalWeighting::Uniform) return vertex_normals(mesh, NormalWeighting::Area);
        return vertex_normals(mesh, w);
    };
    const ScopedFeaturesUnderTest fault(std::move(f));
    expect_failures_naming({{"normals", ""}}, {"normals area", "normals uniform"});
}

TEST(SuiteFaults, WarrensBetaAsThreeOverNineNFails) {
    const ScopedCoreImplementation fault(core_with_slip(
        Scheme::Loop, [](const SchemeRule& r) { return r.loop.weights == LoopWeights::Warren; },
        test::warren_beta_slip));
    expect_failures_naming({{"spectrum", ""}, {"loop", "warren boundary=edge-only L2 weak"}}, {"loop rule oracle", "weights=warren"});
}

TEST(SuiteFaults, AModifiedButterflyWeightSlipFails) {
    // Each new vertex pushed off its edge's midpoint by half again what the stencil moves it:
    // the 1/16 and 1/8 terms of the eight-point stencil mistyped larger.
    const ScopedCoreImplementation fault(core_with_slip(
        Scheme::ModifiedButterfly, [](const SchemeRule&) { return true; },
        [](const PolyMesh& coarse, PolyMesh& fine) {
            const int nv = coarse.num_vertices();
            std::vector<Vec3> ends(fine.positions.size(), Vec3::Zero());
            std::vector<int> count(fine.positions.size(), 0);
            for (int f = 0; f < fine.num_faces(); ++f)
                for (int k = 0; k < fine.face_size(f); ++k) {
                    const int v = fine.face(f)[k];
                    if (v < nv) continue;
                    for (int j = 0; j < fine.face_size(f); ++j) {
                        const int w = fine.face(f)[j];
                        if (w < nv) {
                            ends[static_cast<size_t>(v)] += fine.positions[static_cast<size_t>(w)];
                            ++count[static_cast<size_t>(v)];
                        }
                    }
                }
            // An edge point meets each end once in each face around it: the ends' mean is the midpoint.
            for (size_t v = static_cast<size_t>(nv); v < fine.positions.size(); ++v)
                if (count[v] > 0) fine.positions[v] += 0.5 * (fine.positions[v] - ends[v] / count[v]);
        }));
    expect_failures_naming({{"modified-butterfly", "bundled:"}}, {"modified-butterfly"});
}

TEST(SuiteFaults, ACatmullClarkVertexWeightSlipFails) {
    // Each vertex point moved a quarter further from its old position than the rule puts it:
    // the weight (n - 3) / n of the old vertex mistyped smaller, at every vertex, boundary
    // vertices too.
    const ScopedCoreImplementation fault(core_with_slip(
        Scheme::CatmullClark, [](const SchemeRule&) { return true; },
        [](const PolyMesh& coarse, PolyMesh& fine) {
            for (size_t v = 0; v < coarse.positions.size(); ++v)
                fine.positions[v] += 0.25 * (fine.positions[v] - coarse.positions[v]);
        }));
    expect_failures_naming({{"catmull-clark", "bundled:"}}, {"catmull-clark"});
}

TEST(SuiteFaults, ATessellationThatDropsItsLastPointFails) {
    FeaturesUnderTest f;
    f.sweep = test::sweep_dropping_last_point;
    const ScopedFeaturesUnderTest fault(std::move(f));
    expect_failures_naming({{"surfaces", "surface:vase"}}, {"watertight"});
}

}  // namespace
}  // namespace crossdiv::verification
