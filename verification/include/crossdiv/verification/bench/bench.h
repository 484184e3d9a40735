#pragma once
/// @file
/// Side-by-side timing of Loop and Catmull-Clark subdivision: core against each reference's
/// native refinement (adapters' loop_native and catmull_clark_native: the library's own
/// structures, nothing converted back), single thread, each (input, levels, implementation) in its own child process so that its
/// peak resident memory can be read from the kernel (wait4's ru_maxrss).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"
#include "crossdiv/verification/implementations/scheme.h"

namespace crossdiv::verification {

struct BenchRecord {
    std::string impl;   ///< "core", "opensubdiv", "openmesh", "cgal"
    std::string scheme = "loop";
    std::string input;  ///< name of the input mesh
    int levels = 0;
    long long input_faces = 0, output_faces = 0;
    double median_ms = 0, min_ms = 0, max_ms = 0;
    int repeats = 0;
    double peak_rss_mb = 0;  ///< of the child process that ran the repeats
    std::string status = "ok";  ///< or the failure ("crashed: signal 11", "rejected: ...")
    std::string memory = "warm";  ///< "warm" (freed memory kept between repeats) or "cold"
    std::vector<double> runs_ms;  ///< every timed run
};

/// Rounds the Loop rows' repeats are spread over, every implementation in turn in each.
inline constexpr int kBenchRounds = 3;

struct BenchInput {
    std::string name;
    TriMesh mesh;  ///< Loop's input
    int levels;
    Scheme scheme = Scheme::Loop;
    PolyMesh polygons;  ///< Catmull-Clark's input
};

/// Times each refinement (a call returning its output's face count): `repeats` runs each,
/// spread over kBenchRounds rounds with every refinement in turn (a child process per
/// refinement and round, warmed up by one call), median reported; one that fails is recorded
/// with its status. The child keeps freed memory (WarmAllocator), or when `cold` returns it to
/// the kernel after every run (ColdAllocator). Only the
/// records' timings, sizes, memory and status are filled in.
std::vector<BenchRecord> time_in_rounds(const std::vector<std::function<size_t()>>& refines, int repeats, bool cold);
/// The same with a memory regime per refinement (cold[i] for refines[i]).
std::vector<BenchRecord> time_in_rounds(const std::vector<std::function<size_t()>>& refines, int repeats,
                                        const std::vector<bool>& cold);

/// Times every implementation on every input: `repeats` runs each, spread over kBenchRounds
/// rounds with every implementation in turn (a child per implementation and round, warmed up
/// by one run), median reported. A reference that fails is recorded with its status. Unless `cold`, the
/// child keeps freed memory (glibc mallopt) so repeats do not pay first-touch page faults
/// again; the same setting applies to every implementation.
/// Each input is refined by its scheme under `rule` (the member of that scheme).
std::vector<BenchRecord> run_bench(const std::vector<BenchInput>& inputs, const SchemeRule& rule, int repeats, bool cold);
/// The same in each of `regimes` (cold or not), every implementation in every regime timed in
/// the same rounds: the records of an input, regime after regime.
std::vector<BenchRecord> run_bench(const std::vector<BenchInput>& inputs, const SchemeRule& rule, int repeats,
                                   const std::vector<bool>& regimes);

/// The default series: benchmark_mesh() tori of about 320, 1280, 5120 and 20000 faces at 1
/// and 2 levels, and 20000 faces at 3 levels (1.28M output faces).
std::vector<BenchInput> default_bench_inputs(bool quick);
/// Catmull-Clark's series: quad meshes with extraordinary vertices (one Catmull-Clark level of
/// the irregular benchmark torus: valences 3 to 8) of about 1200, 4800 and 19200 quads at 1
/// and 2 levels, and 4800 quads at 3 levels (307k output faces); quick: 1200 and 19200.
std::vector<BenchInput> default_catmull_clark_bench_inputs(bool quick);

nlohmann::json to_json(const BenchRecord& r);

/// a's time over b's: paired_ratio of their runs, or of their medians when either has none.
double ratio_of(const BenchRecord& a, const BenchRecord& b);

/// The median of a[i] / b[i] over the runs both have (NaN when none): runs of the same round
/// (time_in_rounds) are taken close together, so a drift of a shared machine's speed, which
/// moves the two medians apart, cancels in each ratio.
double paired_ratio(const std::vector<double>& a, const std::vector<double>& b);

/// The median of timings: the middle one, or the mean of the two middle ones (every timing of
/// the bench, Loop and curves alike, is summarised by this one definition).
double median(std::vector<double> samples);

/// While it lives, glibc hands every block of 128 KB or more back to the kernel when it is freed
/// and trims the heap's free top, and `between_runs()` gives back what is left free: the bench's
/// cold setting. glibc's default raises that threshold to the largest block freed so far, so a
/// program that frees one large block keeps the ones after it: repeats in one process were warm
/// for an implementation with a few large blocks and cold for one with many smaller ones.
class ColdAllocator {
public:
    ColdAllocator();
    ColdAllocator(const ColdAllocator&) = delete;
    ColdAllocator& operator=(const ColdAllocator&) = delete;
    /// Returns every free page of the heap to the kernel (call it outside the timed span).
    void between_runs() const;
};

/// While it lives, glibc keeps freed memory for reuse (no mmap for large blocks, no trim), so
/// that repeated runs do not pay first-touch page faults again: the bench's warm setting.
/// Afterwards, glibc's defaults and the memory back to the kernel.
class WarmAllocator {
public:
    WarmAllocator();
    ~WarmAllocator();
    WarmAllocator(const WarmAllocator&) = delete;
    WarmAllocator& operator=(const WarmAllocator&) = delete;
};

/// The median wall time of `repeats` calls of `f` in this process, in milliseconds, after
/// one call that warms caches and the allocator up.
double median_ms(int repeats, const std::function<void()>& f);

/// The median wall times of `repeats` calls of each of `fs`, taken in turn (f0, f1, ..., f0,
/// f1, ...) after one warm-up call of each, so that a load on the machine that comes and goes
/// weighs on every one alike: for timings whose ratio is the result.
std::vector<double> interleaved_median_ms(int repeats, const std::vector<std::function<void()>>& fs);

/// The performance goals against the references, at every input whose output has at least
/// kBenchGoalMinFaces faces, core (Loop, Catmull-Clark) against the fastest reference on the same
/// input in the same memory regime: warm, at least kBenchGoalRatio times faster; cold (freed
/// memory returned to the kernel, page faults paid), Loop at least kBenchLoopColdGoalRatio times
/// faster, Catmull-Clark no slower (kBenchColdGoalRatio).
inline constexpr double kBenchGoalRatio = 4.0;
inline constexpr double kBenchLoopColdGoalRatio = 4.0;
inline constexpr double kBenchColdGoalRatio = 1.0;
/// Core Loop's goals on its own figures at the same inputs: warm, at most kLoopFloorGoal times
/// the floor (its output's bytes written once at the write bandwidth measured in the run); cold,
/// at most kLoopColdOverWarmGoal times its warm time on the same input.
inline constexpr double kLoopFloorGoal = 1.5;
inline constexpr double kLoopColdOverWarmGoal = 2.0;
inline constexpr long long kBenchGoalMinFaces = 300000;

/// How one measured input stands against its goal.
struct BenchGoal {
    std::string scheme;
    std::string input;
    int levels = 0;
    std::string memory;  ///< "warm" or "cold"
    long long output_faces = 0;
    double core_ms = 0;
    std::string fastest_reference;
    double fastest_reference_ms = 0;
    double ratio = 0;  ///< fastest reference time / core time (ratio_of)
    double target = 0;
    double core_peak_rss_mb = 0;
    bool met() const { return ratio >= target; }
};

/// The goals' figures from the records: one per input of at least kBenchGoalMinFaces output
/// faces and memory regime on which core and some reference ran.
std::vector<BenchGoal> bench_goals(const std::vector<BenchRecord>& records);

/// A goal on core's own figures rather than against a reference: core's time over a base
/// time (the floor, or its own warm time), to be at most `target`.
struct CoreGoal {
    enum class Kind { Floor, ColdOverWarm };
    Kind kind = Kind::Floor;
    std::string scheme;
    std::string input;
    int levels = 0;
    long long output_faces = 0;
    double core_ms = 0;  ///< warm (Floor) or cold (ColdOverWarm)
    double base_ms = 0;  ///< the floor (Floor) or core's warm time (ColdOverWarm)
    double ratio = 0;    ///< core over base: of the medians (Floor), of the runs side by side (ColdOverWarm)
    double target = 0;
    bool met() const { return ratio <= target; }
};

/// Core Loop's own goals from the records: the floor goal at every warm Loop record of at least
/// kBenchGoalMinFaces output faces (the floor from `write_gbs`), the cold-over-warm goal at every
/// such input timed in both regimes.
std::vector<CoreGoal> core_goals(const std::vector<BenchRecord>& records, double write_gbs);

/// The floor of a refinement's time: its output's bytes written once at `write_gbs` GB/s, in ms.
double floor_ms(const std::string& scheme, long long output_faces, double write_gbs);

/// The bytes of a Loop level of `output_faces` triangles on a closed mesh (V = F/2 + 2 - 2g;
/// F/2 for the tori): 24 per vertex, 12 per triangle, the least any implementation writes.
double loop_output_bytes(long long output_faces);
/// The bytes of a Catmull-Clark level of `output_faces` quads on a closed genus-1 mesh (V = F):
/// 24 per vertex, 16 per quad.
double catmull_clark_output_bytes(long long output_faces);

/// Memory bandwidth measured here and now: the best of `repeats` passes that write (fill) and
/// that copy a buffer far larger than the caches, in GB/s (bytes moved per second: a copy
/// counts its reads and writes).
struct Bandwidth {
    double write_gbs = 0, copy_gbs = 0;
    size_t buffer_bytes = 0;
};
Bandwidth measure_bandwidth(int repeats);

nlohmann::json to_json(const BenchGoal& g);
nlohmann::json to_json(const CoreGoal& g);

}  // namespace crossdiv::verification
