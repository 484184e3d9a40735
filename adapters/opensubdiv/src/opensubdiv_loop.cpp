#include <opensubdiv/version.h>

#include <memory>
#include <string>

#include "crossdiv/adapters/opensubdiv.h"
#include "opensubdiv_far.h"

namespace crossdiv::adapters::opensubdiv {

using namespace detail;

bool supports(const LoopOptions& options) { return options.weights == LoopWeights::Loop; }

std::string version() {
    return "OpenSubdiv " + std::to_string(OPENSUBDIV_VERSION_MAJOR) + "." + std::to_string(OPENSUBDIV_VERSION_MINOR) +
           "." + std::to_string(OPENSUBDIV_VERSION_PATCH);
}

namespace {

/// Far's refiner for `mesh` under `options`, uniformly refined `levels` times. Full topology
/// in the last level (edges, for Limit() and the trace) is optional: the benchmark does not
/// need it, and OpenSubdiv is fastest without it.
std::unique_ptr<Far::TopologyRefiner> refine_topology(const TriMesh& mesh, const LoopOptions& options, int levels,
                                                      bool full_topology_in_last_level) {
    if (!supports(options)) throw Rejected("OpenSubdiv's Loop scheme has Loop's 1987 weights only (no Warren)");

    const Sdc::Options sdc = sdc_options(options.boundary == LoopBoundary::EdgeAndCorner, options.creasing);
    std::vector<int> verts_per_face(static_cast<size_t>(mesh.num_faces()), 3);
    std::vector<int> indices;
    indices.reserve(3 * static_cast<size_t>(mesh.num_faces()));
    for (const Triangle& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
    std::unique_ptr<Far::TopologyRefiner> refiner =
        make_refiner(mesh.num_vertices(), verts_per_face, indices, Sdc::SCHEME_LOOP, sdc);
    refine_uniform(*refiner, levels, full_topology_in_last_level);
    return refiner;
}

}  // namespace

LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels) {
    return interpolate_trace(*refine_topology(mesh, options, levels, true), mesh.positions);
}

size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels) {
    const std::unique_ptr<Far::TopologyRefiner> refiner = refine_topology(mesh, options, levels, false);
    std::vector<Point3> points = base_points(*refiner, mesh.positions);
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    Point3* src = points.data();
    for (int level = 1; level <= levels; ++level) {
        Point3* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        src = dst;
    }
    return static_cast<size_t>(refiner->GetLevel(levels).GetNumFaces());
}

}  // namespace crossdiv::adapters::opensubdiv
