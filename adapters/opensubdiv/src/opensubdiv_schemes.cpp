// Catmull-Clark and bilinear refinement and the limit positions of Loop and Catmull-Clark through Far.
#include <Eigen/Geometry>  // cross()
#include <memory>
#include <string>

#include "crossdiv/adapters/opensubdiv.h"
#include "opensubdiv_far.h"

namespace crossdiv::adapters::opensubdiv {

using namespace detail;

bool supports(const CatmullClarkOptions& options) {
    return options.boundary != CatmullClarkBoundary::MidpointAverage;
}

namespace {

/// Refines `levels` levels with full topology in the last one and evaluates Limit() there.
LimitPoints limit_of(Far::TopologyRefiner& refiner, const std::vector<Vec3>& positions, int levels) {
    refine_uniform(refiner, levels, true);
    std::vector<Point3> points;
    LevelTrace trace = interpolate_trace(refiner, positions, &points);
    const int nv = refiner.GetLevel(levels).GetNumVertices();
    const Point3* last = points.data() + (points.size() - static_cast<size_t>(nv));
    std::vector<Point3> pos(static_cast<size_t>(nv)), tan1(pos.size()), tan2(pos.size());
    Far::PrimvarRefinerReal<double>(refiner).Limit(last, pos, tan1, tan2);
    if (!g_far_errors.empty()) throw Rejected("Far reported: " + g_far_errors);
    LimitPoints out{std::move(trace.back()), {}, {}};
    out.position.reserve(pos.size());
    out.normal.reserve(pos.size());
    for (size_t v = 0; v < pos.size(); ++v) {
        out.position.push_back(pos[v].vec());
        const Vec3 n = tan1[v].vec().cross(tan2[v].vec());
        out.normal.push_back(n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero());
    }
    return out;
}

std::vector<int> triangle_corners(const TriMesh& mesh) {
    std::vector<int> corners;
    corners.reserve(3 * static_cast<size_t>(mesh.num_faces()));
    for (const Triangle& t : mesh.triangles) corners.insert(corners.end(), t.begin(), t.end());
    return corners;
}

}  // namespace

LevelTrace catmull_clark(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels, LevelBirths* births) {
    std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(mesh, Sdc::SCHEME_CATMARK, catmark_options(options));
    refine_uniform(*refiner, levels, true);
    if (births) *births = child_births(*refiner);
    return interpolate_trace(*refiner, mesh.positions);
}

LevelTrace bilinear(const PolyMesh& mesh, int levels, LevelBirths* births) {
    reject_crease_tags(mesh, "OpenSubdiv's bilinear scheme (as compared here)");
    std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(mesh, Sdc::SCHEME_BILINEAR, sdc_options(false, CreaseMethod::Uniform));
    refine_uniform(*refiner, levels, true);
    if (births) *births = child_births(*refiner);
    return interpolate_trace(*refiner, mesh.positions);
}

size_t catmull_clark_native(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels) {
    std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(mesh, Sdc::SCHEME_CATMARK, catmark_options(options));
    refine_uniform(*refiner, levels, false);
    return interpolate_native(*refiner, mesh.positions);
}

std::vector<int> boundary_none_holes(const PolyMesh& mesh, bool loop) {
    Sdc::Options sdc = sdc_options(false, mesh.creases.method.value_or(CreaseMethod::Uniform));
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_NONE);
    const std::unique_ptr<Far::TopologyRefiner> refiner =
        make_refiner(mesh, loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc);
    std::vector<int> holes;
    const Far::TopologyLevel& base = refiner->GetLevel(0);
    for (int f = 0; f < base.GetNumFaces(); ++f)
        if (base.IsFaceHole(f)) holes.push_back(f);
    return holes;
}

LevelTrace loop(const PolyMesh& mesh, const LoopOptions& options, int levels, LevelBirths* births) {
    std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(mesh, Sdc::SCHEME_LOOP, loop_options(options));
    refine_uniform(*refiner, levels, true);
    if (births) *births = child_births(*refiner);
    return interpolate_trace(*refiner, mesh.positions);
}

LimitPoints loop_limit(const TriMesh& mesh, const LoopOptions& options, int levels) {
    std::unique_ptr<Far::TopologyRefiner> refiner =
        make_refiner(mesh.num_vertices(), std::vector<int>(static_cast<size_t>(mesh.num_faces()), 3),
                     triangle_corners(mesh), Sdc::SCHEME_LOOP, loop_options(options));
    return limit_of(*refiner, mesh.positions, levels);
}

LimitPoints catmull_clark_limit(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels) {
    std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(mesh, Sdc::SCHEME_CATMARK, catmark_options(options));
    return limit_of(*refiner, mesh.positions, levels);
}

}  // namespace crossdiv::adapters::opensubdiv
