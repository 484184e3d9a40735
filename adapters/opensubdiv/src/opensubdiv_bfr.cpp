// Catmull-Clark and Loop limit surface evaluation through OpenSubdiv's Bfr (3.5).
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>
#include <string>

#include "crossdiv/adapters/opensubdiv.h"
#include "opensubdiv_far.h"

namespace crossdiv::adapters::opensubdiv {

using namespace OpenSubdiv;

namespace {

/// Bfr's surface of one face of a refiner (boundary rule EDGE_ONLY: the library default,
/// NONE, would make boundary faces holes), evaluated at each (u, v).
LimitEvaluation evaluate(const PolyMesh& mesh, Sdc::SchemeType scheme, int face, std::span<const std::array<double, 2>> uv) {
    if (face < 0 || face >= mesh.num_faces())
        throw Rejected("face " + std::to_string(face) + " is not in a mesh of " + std::to_string(mesh.num_faces()) + " faces");
    const Sdc::Options sdc = detail::sdc_options(false, CreaseMethod::Uniform);  // edge-only
    const std::unique_ptr<Far::TopologyRefiner> refiner = detail::make_refiner(mesh, scheme, sdc);
    Bfr::RefinerSurfaceFactory<> factory(*refiner);
    Bfr::Surface<double> surface;
    if (!factory.InitVertexSurface(face, &surface) || !surface.IsValid())
        throw Rejected("Bfr has no limit surface for face " + std::to_string(face) + " (a hole or an invalid face)");
    std::vector<double> mesh_points;
    mesh_points.reserve(3 * mesh.positions.size());
    for (const Vec3& p : mesh.positions) mesh_points.insert(mesh_points.end(), {p.x(), p.y(), p.z()});
    std::vector<double> patch_points(3 * static_cast<size_t>(surface.GetNumPatchPoints()));
    const Bfr::Surface<double>::PointDescriptor xyz(3);
    surface.PreparePatchPoints(mesh_points.data(), xyz, patch_points.data(), xyz);

    LimitEvaluation out;
    out.regular = surface.IsRegular();
    out.samples.reserve(uv.size());
    for (const auto& st : uv) {
        double p[3], du[3], dv[3];
        surface.Evaluate(st.data(), patch_points.data(), xyz, p, du, dv);
        out.samples.push_back({Vec3(p[0], p[1], p[2]), Vec3(du[0], du[1], du[2]), Vec3(dv[0], dv[1], dv[2])});
    }
    return out;
}

}  // namespace

LimitEvaluation catmark_limit(const PolyMesh& mesh, int face, std::span<const std::array<double, 2>> uv) {
    return evaluate(mesh, Sdc::SCHEME_CATMARK, face, uv);
}

LimitEvaluation loop_limit_surface(const PolyMesh& mesh, int face, std::span<const std::array<double, 2>> uv) {
    for (int f = 0; f < mesh.num_faces(); ++f)
        if (mesh.face_size(f) != 3) throw Rejected("face " + std::to_string(f) + ": Loop needs triangles");
    return evaluate(mesh, Sdc::SCHEME_LOOP, face, uv);
}

}  // namespace crossdiv::adapters::opensubdiv
