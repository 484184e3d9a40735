#include "crossdiv/verification/bench/thread_bench.h"

#include <cmath>
#include <memory>
#include <optional>

#include "crossdiv/subdiv/catmull_clark_streaming.h"
#include "crossdiv/subdiv/loop_streaming.h"
#include "crossdiv/verification/harness/json_text.h"
#ifdef CROSSDIV_HAS_OPENSUBDIV
#include "crossdiv/adapters/opensubdiv.h"
#endif

namespace crossdiv::verification {

std::vector<ThreadRow> run_thread_bench(const std::vector<BenchInput>& inputs, int threads, int repeats) {
    const LoopOptions loop{LoopWeights::Loop, LoopBoundary::EdgeOnly};
    const CatmullClarkOptions catmull_clark{CatmullClarkBoundary::EdgeOnly};
    std::vector<ThreadRow> rows;
    for (const BenchInput& in : inputs) {
        const bool triangles = in.scheme == Scheme::Loop;
        // Loop: four triangles a triangle; Catmull-Clark: a quad a corner, then four a quad.
        const long long output_faces = triangles ? static_cast<long long>(in.mesh.num_faces()) << (2 * in.levels)
                                                 : static_cast<long long>(in.polygons.face_vertices.size()) << (2 * (in.levels - 1));
        std::vector<std::function<size_t()>> refines;
        for (int n : {1, threads})
            refines.push_back([&, n, triangles] {
                return triangles ? loop_subdivide_streaming(in.mesh, loop, in.levels, n).triangles.size()
                                 : static_cast<size_t>(catmull_clark_subdivide_streaming(in.polygons, catmull_clark, in.levels, n).num_faces());
            });
#ifdef CROSSDIV_HAS_OPENSUBDIV
        std::vector<float> base;
        for (const Vec3& p : triangles ? in.mesh.positions : in.polygons.positions)
            base.insert(base.end(), {float(p.x()), float(p.y()), float(p.z())});
        for (int n : {1, threads}) {
            // The table is built in the child's warm-up call (the parent never makes one), and
            // kept for the timed calls.
            auto table = std::make_shared<std::optional<adapters::opensubdiv::OmpStencils>>();
            auto out = std::make_shared<std::vector<float>>();
            refines.push_back([&, n, table, out, triangles] {
                if (!*table) {
                    if (triangles) table->emplace(in.mesh, loop, in.levels);
                    else table->emplace(in.polygons, catmull_clark, in.levels);
                }
                (*table)->evaluate(base, *out, n);
                return static_cast<size_t>(output_faces);
            });
        }
#endif
        const std::vector<BenchRecord> r = time_in_rounds(refines, repeats, false);
        ThreadRow row{to_string(in.scheme), in.name, in.levels, output_faces, threads, r[0].median_ms, r[1].median_ms, NAN, NAN};
        row.speedup = paired_ratio(r[0].runs_ms, r[1].runs_ms);
        if (r.size() == 4) {
            row.omp_one_ms = r[2].median_ms;
            row.omp_many_ms = r[3].median_ms;
            row.over_omp = paired_ratio(r[3].runs_ms, r[1].runs_ms);
        }
        const char* names[] = {"core", "core", "OmpEvaluator", "OmpEvaluator"};
        for (size_t i = 0; i < r.size(); ++i)
            if (r[i].status != "ok") {
                if (i >= 2) row.omp_one_ms = row.omp_many_ms = NAN;
                else row.core_one_ms = row.core_many_ms = row.speedup = NAN;
                row.over_omp = NAN;
                if (row.status == "ok") row.status = std::string(names[i]) + ": " + r[i].status;
            }
        rows.push_back(row);
    }
    return rows;
}

std::vector<BenchInput> catmull_clark_thread_inputs(bool quick) {
    std::vector<BenchInput> in;
    for (BenchInput& b : default_catmull_clark_bench_inputs(true))
        if (b.polygons.num_faces() > 10000 && b.levels == 2) {
            in.push_back(b);
            if (quick) continue;
            b.levels = 3;
            in.push_back(std::move(b));
        }
    return in;
}

nlohmann::json to_json(const ThreadRow& r) {
    return {{"scheme", r.scheme},
            {"input", r.input},
            {"levels", r.levels},
            {"output_faces", r.output_faces},
            {"threads", r.threads},
            {"core_one_thread_ms", finite_or_null(r.core_one_ms)},
            {"core_threads_ms", finite_or_null(r.core_many_ms)},
            {"omp_one_thread_ms", finite_or_null(r.omp_one_ms)},
            {"omp_threads_ms", finite_or_null(r.omp_many_ms)},
            {"speedup", finite_or_null(r.speedup)},
            {"omp_over_core", finite_or_null(r.over_omp)},
            {"status", r.status}};
}

}  // namespace crossdiv::verification
