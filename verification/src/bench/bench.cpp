#include "crossdiv/verification/harness/interruption.h"
#include "crossdiv/verification/bench/bench.h"

#include <malloc.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <csignal>
#include <cstring>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/catmull_clark.h"
#include "crossdiv/subdiv/loop.h"
#include "crossdiv/verification/implementations/registry.h"

namespace crossdiv::verification {
namespace {

using Refine = std::function<size_t()>;

/// What the child sends back: the output size and each repeat's time, or a failure.
struct ChildReport {
    long long output_faces = -1;
    int repeats = 0;
    double ms[64] = {};
    char error[256] = {};
};

BenchRecord time_in_child(const Refine& refine, int repeats, bool cold) {
    BenchRecord r;
    repeats = std::clamp(repeats, 1, 64);
    int fd[2];
    if (pipe(fd) != 0) throw std::runtime_error("pipe failed");
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        // Keep freed memory in the process for every implementation alike: on this kind of
        // virtual machine a first-touch page fault costs microseconds, and returning memory
        // to the kernel between repeats would time the hypervisor instead of the algorithm.
        // The warm-up run pays the faults once; `crossdiv bench --cold` keeps them in.
        std::optional<WarmAllocator> warm;
        std::optional<ColdAllocator> cold_memory;
        if (cold) cold_memory.emplace();
        else warm.emplace();
        ChildReport rep;
        try {
            rep.output_faces = static_cast<long long>(refine());  // warm-up: page faults, caches
            for (int i = 0; i < repeats; ++i) {
                if (cold_memory) cold_memory->between_runs();
                const auto t0 = std::chrono::steady_clock::now();
                const size_t faces = refine();
                rep.ms[i] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
                if (static_cast<long long>(faces) != rep.output_faces) throw std::runtime_error("output size changed");
            }
            rep.repeats = repeats;
        } catch (const adapters::Rejected& e) {
            std::snprintf(rep.error, sizeof rep.error, "rejected: %s", e.what());
        } catch (const std::exception& e) {
            std::snprintf(rep.error, sizeof rep.error, "threw: %s", e.what());
        }
        const ssize_t n = write(fd[1], &rep, sizeof rep);
        _exit(n == static_cast<ssize_t>(sizeof rep) ? 0 : 1);
    }
    const RegisteredChild registration(pid, ChildRole::Isolated);
    close(fd[1]);
    ChildReport rep;
    size_t got = 0;
    for (ssize_t n; got < sizeof rep && (n = read(fd[0], reinterpret_cast<char*>(&rep) + got, sizeof rep - got)) > 0;)
        got += static_cast<size_t>(n);
    close(fd[0]);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    r.peak_rss_mb = usage.ru_maxrss / 1024.0;  // kilobytes on Linux
    if (WIFSIGNALED(status)) {
        r.status = std::string("crashed: signal ") + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
        return r;
    }
    if (got != sizeof rep || rep.error[0]) {
        r.status = got == sizeof rep ? rep.error : "child ended without a report";
        return r;
    }
    std::vector<double> ms(rep.ms, rep.ms + rep.repeats);
    r.runs_ms = ms;
    r.repeats = rep.repeats;
    r.output_faces = rep.output_faces;
    r.min_ms = *std::min_element(ms.begin(), ms.end());
    r.max_ms = *std::max_element(ms.begin(), ms.end());
    r.median_ms = median(ms);
    return r;
}

}  // namespace

std::vector<BenchRecord> time_in_rounds(const std::vector<std::function<size_t()>>& refines, int repeats, bool cold) {
    return time_in_rounds(refines, repeats, std::vector<bool>(refines.size(), cold));
}

std::vector<BenchRecord> time_in_rounds(const std::vector<std::function<size_t()>>& refines, int repeats,
                                        const std::vector<bool>& cold) {
    // The repeats in rounds, every refinement in turn within a round (each in a child of its
    // own, warmed up once): the speed of a shared virtual machine drifts over seconds, and a
    // drift should weigh on every refinement alike, not on whichever ran during it.
    const int rounds = std::min(repeats, kBenchRounds);
    std::vector<BenchRecord> recs(refines.size());
    for (int round = 0; round < rounds; ++round)
        for (size_t i = 0; i < refines.size(); ++i) {
            const int runs = repeats / rounds + (round < repeats % rounds ? 1 : 0);
            BenchRecord& r = recs[i];
            if (r.status != "ok") continue;  // it failed: recorded once, not run again
            const BenchRecord part = time_in_child(refines[i], runs, cold[i]);
            if (part.status != "ok") {
                r = part;
                continue;
            }
            r.output_faces = part.output_faces;
            r.runs_ms.insert(r.runs_ms.end(), part.runs_ms.begin(), part.runs_ms.end());
            r.peak_rss_mb = std::max(r.peak_rss_mb, part.peak_rss_mb);
        }
    for (size_t i = 0; i < recs.size(); ++i) {
        BenchRecord& r = recs[i];
        r.memory = cold[i] ? "cold" : "warm";
        if (r.status == "ok" && !r.runs_ms.empty()) {
            r.repeats = static_cast<int>(r.runs_ms.size());
            r.min_ms = *std::min_element(r.runs_ms.begin(), r.runs_ms.end());
            r.max_ms = *std::max_element(r.runs_ms.begin(), r.runs_ms.end());
            r.median_ms = median(r.runs_ms);
        }
    }
    return recs;
}

std::vector<BenchRecord> run_bench(const std::vector<BenchInput>& inputs, const SchemeRule& rule, int repeats, bool cold) {
    return run_bench(inputs, rule, repeats, std::vector<bool>{cold});
}

std::vector<BenchRecord> run_bench(const std::vector<BenchInput>& inputs, const SchemeRule& rule, int repeats,
                                   const std::vector<bool>& regimes) {
    std::vector<BenchRecord> out;
    for (const BenchInput& in : inputs) {
        const RefineRequest request{in.scheme, rule, in.levels};
        const bool triangles = in.scheme == Scheme::Loop;
        // On a closed polygon mesh the boundary rule is moot: every implementation of the
        // scheme refines it alike (OpenMesh's Catmull-Clark has only its own boundary rule).
        const bool closed = !triangles && [&] {
            const PolyConnectivity c = build_poly_connectivity(in.polygons);
            return std::none_of(c.twin.begin(), c.twin.end(), [](int t) { return t < 0; });
        }();
        // Without crease tags the crease rules are moot too: an implementation with its own
        // (Hbr) refines such a mesh as the rule asked for.
        const bool untagged = in.polygons.creases.empty();  // a TriMesh carries no tags
        const auto applies = [&](const Implementation* impl) {
            if (impl->applies(in.scheme, request.rule)) return true;
            if (!untagged) return false;
            SchemeRule r = request.rule;
            r.loop.crease_rules = r.catmull_clark.crease_rules = CreaseRules::Hbr;
            return impl->applies(in.scheme, r);
        };
        std::vector<const Implementation*> impls;
        for (const Implementation* impl : implementations())
            if (impl->has(in.scheme) && (closed || applies(impl))) impls.push_back(impl);
        // Every implementation in every regime asked for, all in the same rounds.
        std::vector<Refine> refines;
        std::vector<bool> cold;
        for (const bool regime : regimes)
            for (const Implementation* impl : impls) {
                refines.push_back([&, impl] {
                    return triangles ? impl->refine_native(in.mesh, request) : impl->refine_polygons_native(in.polygons, request);
                });
                cold.push_back(regime);
            }
        std::vector<BenchRecord> recs = time_in_rounds(refines, repeats, cold);
        for (size_t i = 0; i < recs.size(); ++i) {
            BenchRecord& r = recs[i];
            r.impl = impls[i % impls.size()]->name();
            r.scheme = to_string(in.scheme);
            r.input = in.name;
            r.levels = in.levels;
            r.input_faces = triangles ? in.mesh.num_faces() : in.polygons.num_faces();
            out.push_back(r);
        }
    }
    return out;
}

std::vector<BenchInput> default_bench_inputs(bool quick) {
    std::vector<BenchInput> in;
    auto add = [&](int faces, int levels) {
        TriMesh m = to_tri_mesh(datasets::benchmark_mesh(faces), "benchmark");
        in.push_back({"torus-" + std::to_string(m.num_faces()), std::move(m), levels, Scheme::Loop, PolyMesh{}});
    };
    for (int faces : quick ? std::vector<int>{320, 20000} : std::vector<int>{320, 1280, 5120, 20000})
        for (int levels : {1, 2}) add(faces, levels);
    if (!quick) add(20000, 3);
    return in;
}

std::vector<BenchInput> default_catmull_clark_bench_inputs(bool quick) {
    std::vector<BenchInput> in;
    auto add = [&](int quads, int levels) {
        // One level of the irregular triangle torus: quads only, the old vertices keeping their
        // valences 4 to 8, the face points of valence 3.
        PolyMesh m = catmull_clark_subdivide(datasets::benchmark_mesh(quads / 3), {CatmullClarkBoundary::EdgeOnly}, 1);
        const std::string name = "quads-" + std::to_string(m.num_faces());
        in.push_back({name, TriMesh{}, levels, Scheme::CatmullClark, std::move(m)});
    };
    for (int quads : quick ? std::vector<int>{1200, 19200} : std::vector<int>{1200, 4800, 19200})
        for (int levels : {1, 2}) add(quads, levels);
    if (!quick) add(4800, 3);
    return in;
}

nlohmann::json to_json(const BenchRecord& r) {
    return {{"impl", r.impl},         {"scheme", r.scheme},         {"input", r.input},
            {"levels", r.levels},     {"input_faces", r.input_faces}, {"output_faces", r.output_faces},
            {"median_ms", r.median_ms}, {"min_ms", r.min_ms},       {"max_ms", r.max_ms},
            {"repeats", r.repeats},   {"peak_rss_mb", r.peak_rss_mb}, {"status", r.status}, {"memory", r.memory}};
}

double paired_ratio(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> ratios;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) ratios.push_back(a[i] / b[i]);
    return median(std::move(ratios));
}

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

ColdAllocator::ColdAllocator() {
    // Set explicitly, the thresholds stay where they are (mallopt(3): no dynamic adjustment).
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
    mallopt(M_TRIM_THRESHOLD, 128 * 1024);
}

void ColdAllocator::between_runs() const { malloc_trim(0); }

WarmAllocator::WarmAllocator() {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, -1);
}

WarmAllocator::~WarmAllocator() {
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);  // glibc's defaults
    mallopt(M_TRIM_THRESHOLD, 128 * 1024);
    malloc_trim(0);
}

double median_ms(int repeats, const std::function<void()>& f) {
    std::vector<double> ms;
    for (int rep = 0; rep <= repeats; ++rep) {  // rep 0 warms up
        const auto t0 = std::chrono::steady_clock::now();
        f();
        if (rep > 0) ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    return median(ms);
}

std::vector<double> interleaved_median_ms(int repeats, const std::vector<std::function<void()>>& fs) {
    std::vector<std::vector<double>> ms(fs.size());
    for (int rep = 0; rep <= repeats; ++rep)  // rep 0 warms up
        for (size_t i = 0; i < fs.size(); ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            fs[i]();
            if (rep > 0) ms[i].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        }
    std::vector<double> out;
    for (std::vector<double>& m : ms) out.push_back(median(std::move(m)));
    return out;
}

double ratio_of(const BenchRecord& a, const BenchRecord& b) {
    return a.runs_ms.empty() || b.runs_ms.empty() ? a.median_ms / b.median_ms : paired_ratio(a.runs_ms, b.runs_ms);
}

std::vector<BenchGoal> bench_goals(const std::vector<BenchRecord>& records) {
    std::vector<BenchGoal> goals;
    for (const BenchRecord& core : records) {
        if (core.impl != "core" || core.output_faces < kBenchGoalMinFaces || core.status != "ok") continue;
        const BenchRecord* fastest = nullptr;
        for (const BenchRecord& r : records)
            if (r.impl != "core" && r.scheme == core.scheme && r.input == core.input && r.levels == core.levels &&
                r.memory == core.memory && r.status == "ok" && (!fastest || r.median_ms < fastest->median_ms))
                fastest = &r;
        if (!fastest) continue;
        goals.push_back({core.scheme, core.input, core.levels, core.memory, core.output_faces, core.median_ms, fastest->impl,
                         fastest->median_ms, ratio_of(*fastest, core),
                         core.memory == "warm"    ? kBenchGoalRatio
                         : core.scheme == "loop" ? kBenchLoopColdGoalRatio
                                                 : kBenchColdGoalRatio,
                         core.peak_rss_mb});
    }
    return goals;
}

nlohmann::json to_json(const BenchGoal& g) {
    return {{"scheme", g.scheme}, {"input", g.input}, {"levels", g.levels}, {"memory", g.memory}, {"output_faces", g.output_faces},
            {"core_ms", g.core_ms}, {"fastest_reference", g.fastest_reference}, {"fastest_reference_ms", g.fastest_reference_ms},
            {"ratio", g.ratio}, {"target_ratio", g.target}, {"met", g.met()}, {"core_peak_rss_mb", g.core_peak_rss_mb}};
}

std::vector<CoreGoal> core_goals(const std::vector<BenchRecord>& records, double write_gbs) {
    std::vector<CoreGoal> goals;
    for (const BenchRecord& warm : records) {
        if (warm.impl != "core" || warm.scheme != "loop" || warm.memory != "warm" || warm.status != "ok" ||
            warm.output_faces < kBenchGoalMinFaces)
            continue;
        const double floor = floor_ms(warm.scheme, warm.output_faces, write_gbs);
        goals.push_back({CoreGoal::Kind::Floor, warm.scheme, warm.input, warm.levels, warm.output_faces, warm.median_ms, floor,
                         warm.median_ms / floor, kLoopFloorGoal});
        for (const BenchRecord& cold : records)
            if (cold.impl == "core" && cold.scheme == warm.scheme && cold.input == warm.input && cold.levels == warm.levels &&
                cold.memory == "cold" && cold.status == "ok")
                goals.push_back({CoreGoal::Kind::ColdOverWarm, warm.scheme, warm.input, warm.levels, warm.output_faces,
                                 cold.median_ms, warm.median_ms, ratio_of(cold, warm), kLoopColdOverWarmGoal});
    }
    return goals;
}

nlohmann::json to_json(const CoreGoal& g) {
    return {{"goal", g.kind == CoreGoal::Kind::Floor ? "floor" : "cold over warm"},
            {"scheme", g.scheme},
            {"input", g.input},
            {"levels", g.levels},
            {"output_faces", g.output_faces},
            {"core_ms", g.core_ms},
            {"base_ms", g.base_ms},
            {"ratio", g.ratio},
            {"target_ratio", g.target},
            {"met", g.met()}};
}

double floor_ms(const std::string& scheme, long long output_faces, double write_gbs) {
    const double bytes = scheme == "loop" ? loop_output_bytes(output_faces) : catmull_clark_output_bytes(output_faces);
    return bytes / (write_gbs * 1e9) * 1e3;
}

double loop_output_bytes(long long output_faces) {
    const double faces = static_cast<double>(output_faces);
    return faces / 2 * sizeof(Vec3) + faces * sizeof(Triangle);
}

double catmull_clark_output_bytes(long long output_faces) {
    const double faces = static_cast<double>(output_faces);
    return faces * sizeof(Vec3) + faces * 4 * sizeof(int);
}

Bandwidth measure_bandwidth(int repeats) {
    // 256 MiB: eight times the largest last-level cache of the machines this runs on.
    Bandwidth b;
    b.buffer_bytes = size_t{256} << 20;
    const size_t n = b.buffer_bytes / sizeof(double);
    std::vector<double> src(n, 1.0), dst(n, 0.0);  // touched once here: the passes pay no page faults
    double best_write = INFINITY, best_copy = INFINITY;
    for (int r = 0; r < std::max(repeats, 1); ++r) {
        auto t0 = std::chrono::steady_clock::now();
        std::fill(dst.begin(), dst.end(), static_cast<double>(r));
        best_write = std::min(best_write, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        t0 = std::chrono::steady_clock::now();
        std::memcpy(dst.data(), src.data(), b.buffer_bytes);
        best_copy = std::min(best_copy, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    // Read back so that the passes cannot be dropped as dead stores.
    if (dst[n / 2] != 1.0) throw std::runtime_error("bandwidth: the copy did not copy");
    b.write_gbs = static_cast<double>(b.buffer_bytes) / best_write / 1e9;
    b.copy_gbs = 2.0 * static_cast<double>(b.buffer_bytes) / best_copy / 1e9;
    return b;
}

}  // namespace crossdiv::verification
