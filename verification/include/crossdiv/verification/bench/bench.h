#pragma once
/// @file
/// Side-by-side timing of Loop subdivision: core against each reference's native
/// refinement (adapters' loop_native: the library's own structures, nothing converted back),
/// single thread, each (input, levels, implementation) in its own child process so that its
/// peak resident memory can be read from the kernel (wait4's ru_maxrss).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

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
};

struct BenchInput {
    std::string name;
    TriMesh mesh;
    int levels;
};

/// Times every implementation on every input: `repeats` runs each (after one warm-up run),
/// median reported. A reference that fails is recorded with its status. Unless `cold`, the
/// child keeps freed memory (glibc mallopt) so repeats do not pay first-touch page faults
/// again; the same setting applies to every implementation.
std::vector<BenchRecord> run_bench(const std::vector<BenchInput>& inputs, const LoopOptions& options, int repeats,
                                   bool cold);

/// The default series: benchmark_mesh() tori of about 320, 1280, 5120 and 20000 faces at 1
/// and 2 levels, and 20000 faces at 3 levels (1.28M output faces).
std::vector<BenchInput> default_bench_inputs(bool quick);

nlohmann::json to_json(const BenchRecord& r);

}  // namespace crossdiv::verification
