#include <opensubdiv/far/error.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <opensubdiv/version.h>

#include <memory>
#include <string>

#include "crossdiv/adapters/opensubdiv.h"

namespace crossdiv::adapters::opensubdiv {
namespace {

using namespace OpenSubdiv;

/// Primvar with the Clear/AddWithWeight interface PrimvarRefiner expects.
struct Point3 {
    double p[3];
    void Clear() { p[0] = p[1] = p[2] = 0.0; }
    void AddWithWeight(const Point3& src, double w) {
        p[0] += w * src.p[0];
        p[1] += w * src.p[1];
        p[2] += w * src.p[2];
    }
};

// Far reports topology errors through a global C callback; collect them for Rejected.
std::string g_far_errors;
void collect_far_error(Far::ErrorType, const char* message) {
    g_far_errors += message;
    g_far_errors += "; ";
}

PolyMesh level_mesh(const Far::TopologyLevel& level, const Point3* points) {
    PolyMesh m;
    m.positions.reserve(static_cast<size_t>(level.GetNumVertices()));
    for (int v = 0; v < level.GetNumVertices(); ++v) m.positions.emplace_back(points[v].p[0], points[v].p[1], points[v].p[2]);
    for (int f = 0; f < level.GetNumFaces(); ++f) {
        Far::ConstIndexArray fv = level.GetFaceVertices(f);
        for (int k = 0; k < fv.size(); ++k) m.face_vertices.push_back(fv[k]);
        m.face_start.push_back(static_cast<int>(m.face_vertices.size()));
    }
    return m;
}

}  // namespace

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

    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(options.boundary == LoopBoundary::EdgeOnly
                                        ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                        : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    std::vector<int> verts_per_face(static_cast<size_t>(mesh.num_faces()), 3);
    std::vector<int> indices;
    indices.reserve(3 * static_cast<size_t>(mesh.num_faces()));
    for (const Triangle& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());

    Far::TopologyDescriptor desc;
    desc.numVertices = mesh.num_vertices();
    desc.numFaces = mesh.num_faces();
    desc.numVertsPerFace = verts_per_face.data();
    desc.vertIndicesPerFace = indices.data();

    g_far_errors.clear();
    Far::SetErrorCallback(collect_far_error);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(Sdc::SCHEME_LOOP, sdc)));
    if (!refiner) throw Rejected("Far::TopologyRefinerFactory failed: " + g_far_errors);

    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = full_topology_in_last_level;
    refiner->RefineUniform(uniform);
    if (!g_far_errors.empty()) throw Rejected("Far reported: " + g_far_errors);
    return refiner;
}

std::vector<Point3> base_points(const Far::TopologyRefiner& refiner, const TriMesh& mesh) {
    std::vector<Point3> points(static_cast<size_t>(refiner.GetNumVerticesTotal()));
    for (int v = 0; v < mesh.num_vertices(); ++v) points[v] = {{mesh.positions[v].x(), mesh.positions[v].y(), mesh.positions[v].z()}};
    return points;
}

}  // namespace

LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels) {
    const std::unique_ptr<Far::TopologyRefiner> refiner = refine_topology(mesh, options, levels, true);
    std::vector<Point3> points = base_points(*refiner, mesh);
    LevelTrace trace;
    trace.push_back(level_mesh(refiner->GetLevel(0), points.data()));
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    Point3* src = points.data();
    for (int level = 1; level <= levels; ++level) {
        Point3* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        trace.push_back(level_mesh(refiner->GetLevel(level), dst));
        src = dst;
    }
    return trace;
}

size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels) {
    const std::unique_ptr<Far::TopologyRefiner> refiner = refine_topology(mesh, options, levels, false);
    std::vector<Point3> points = base_points(*refiner, mesh);
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
