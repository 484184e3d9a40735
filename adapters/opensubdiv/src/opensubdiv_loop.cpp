#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
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

LevelTrace loop(const TriMesh& mesh, const LoopOptions& options, int levels, LevelBirths* births) {
    const auto refiner = refine_topology(mesh, options, levels, true);
    if (births) *births = child_births(*refiner);
    return interpolate_trace(*refiner, mesh.positions);
}

size_t loop_native(const TriMesh& mesh, const LoopOptions& options, int levels) {
    return interpolate_native(*refine_topology(mesh, options, levels, false), mesh.positions);
}

struct LoopFrames::Impl {
    std::unique_ptr<Far::TopologyRefiner> refiner;
    std::unique_ptr<const Far::StencilTableReal<double>> stencils;
    int levels = 0;
    mutable std::vector<Point3> scratch;  ///< every level's vertices, for by_levels
};

LoopFrames::LoopFrames(const TriMesh& mesh, const LoopOptions& options, int levels) : impl_(std::make_unique<Impl>()) {
    impl_->refiner = refine_topology(mesh, options, levels, false);
    impl_->levels = levels;
    Far::StencilTableFactoryReal<double>::Options o;
    o.generateIntermediateLevels = false;  // the last level only,
    o.factorizeIntermediateLevels = true;  // each stencil over the base vertices
    impl_->stencils.reset(Far::StencilTableFactoryReal<double>::Create(*impl_->refiner, o));
    impl_->scratch.resize(static_cast<size_t>(impl_->refiner->GetNumVerticesTotal()));
}

LoopFrames::~LoopFrames() = default;

int LoopFrames::num_stencils() const { return impl_->stencils->GetNumStencils(); }

size_t LoopFrames::num_stencil_terms() const { return impl_->stencils->GetControlIndices().size(); }

void LoopFrames::by_stencils(const std::vector<Vec3>& base, std::vector<Vec3>& out) const {
    static_assert(sizeof(Vec3) == sizeof(Point3), "a position and Far's primvar are the same three doubles");
    out.resize(static_cast<size_t>(num_stencils()));
    impl_->stencils->UpdateValues(reinterpret_cast<const Point3*>(base.data()), reinterpret_cast<Point3*>(out.data()));
}

void LoopFrames::by_levels(const std::vector<Vec3>& base, std::vector<Vec3>& out) const {
    Point3* src = impl_->scratch.data();
    for (size_t v = 0; v < base.size(); ++v) src[v] = {{base[v].x(), base[v].y(), base[v].z()}};
    const Far::PrimvarRefinerReal<double> primvar(*impl_->refiner);
    for (int level = 1; level <= impl_->levels; ++level) {
        Point3* dst = src + impl_->refiner->GetLevel(level - 1).GetNumVertices();
        primvar.Interpolate(level, src, dst);
        src = dst;
    }
    const int n = impl_->refiner->GetLevel(impl_->levels).GetNumVertices();
    out.resize(static_cast<size_t>(n));
    for (int v = 0; v < n; ++v) out[static_cast<size_t>(v)] = src[v].vec();
}

}  // namespace crossdiv::adapters::opensubdiv
