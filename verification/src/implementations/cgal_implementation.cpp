// CGAL as implementations: "cgal" (Subdivision_method_3's Loop, Catmull-Clark, Doo-Sabin and
// sqrt3 called once per level; Euler flips and splits; PMP vertex normals, the closed-mesh
// report and jet-fitted curvatures) and "cgal-one-call" (Sqrt3 asked for every level in one call).
#include "crossdiv/adapters/cgal.h"
#include "crossdiv/mesh/vertex_normals.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

namespace cg = adapters::cgal;

/// Face samples of each mesh for the Hausdorff distance: the distance of the farthest sample
/// is a lower bound that misses at most the gap between samples; 20000 points on a mesh of a
/// few thousand triangles put several on each.
constexpr int kHausdorffFaceSamples = 20000;

class Cgal final : public Implementation {
public:
    Cgal()
        : Implementation("cgal", cg::version(), ImplementationKind::Library,
                         {.schemes = {supports(Scheme::Loop, {loop_rule(LoopWeights::Loop, LoopBoundary::EdgeOnly)}),
                                      supports(Scheme::CatmullClark, {catmull_clark_rule(CatmullClarkBoundary::EdgeOnly)}),
                                      supports(Scheme::DooSabin, {doo_sabin_rule(DooSabinBoundary::DropBorderFaces)}),
                                      supports(Scheme::Sqrt3, {sqrt3_rule(Sqrt3Parity::RestartEachLevel)})},
                          .edits = true,
                          .vertex_normals = true,
                          .closed_mesh_report = true,
                          .curvatures = true,
                          .hausdorff_distance = true,
                          .simplification = true}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        switch (r.scheme) {
            case Scheme::Loop: return cg::loop(triangles_for(mesh, r.scheme), closest_rule(r.scheme, r.rule).loop, r.levels);
            case Scheme::CatmullClark: return cg::catmull_clark(mesh, r.levels);
            case Scheme::DooSabin: return cg::doo_sabin(mesh, r.levels);
            default: return cg::sqrt3(triangles_for(mesh, r.scheme), r.levels, false);
        }
    }

    size_t refine_native(const TriMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::Loop) return Implementation::refine_native(mesh, r);
        return cg::loop_native(mesh, closest_rule(r.scheme, r.rule).loop, r.levels);
    }

    size_t refine_polygons_native(const PolyMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::CatmullClark) return Implementation::refine_polygons_native(mesh, r);
        return cg::catmull_clark_native(mesh, r.levels);
    }

    std::vector<NamedNormals> vertex_normals(const TriMesh& mesh) const override {
        NamedNormals n{"cgal", "PMP::compute_vertex_normals", {}, {}};
        try {
            n.normals = cg::vertex_normals(mesh);
        } catch (const std::exception& e) {
            n.error = e.what();
        }
        return {n};
    }

    std::unique_ptr<EditSession> open_edit(const TriMesh& base) const override {
        return std::make_unique<LibraryEditSession<cg::EditableMesh, false>>(base);
    }

    adapters::ClosedMeshReport closed_mesh_report(const TriMesh& mesh) const override { return cg::closed_mesh_report(mesh); }

    /// PMP::approximate_symmetric_Hausdorff_distance with each mesh's vertices, edge samples and
    /// kHausdorffFaceSamples random points on its faces from a fixed seed (reproducible).
    double hausdorff_distance(const TriMesh& a, const TriMesh& b) const override {
        return cg::hausdorff_distance(a, b, kHausdorffFaceSamples, 1);
    }

    TriMesh simplify(const TriMesh& mesh, int edges) const override { return cg::simplify(mesh, edges); }

    /// A degree-2 jet over the 2-ring (at least 7 points around an interior vertex for the 6
    /// coefficients), the fit CGAL's own example makes; oriented by our angle-weighted normals.
    PrincipalCurvatures curvatures(const TriMesh& mesh) const override {
        const cg::MongeCurvatures m = cg::monge_curvatures(mesh, crossdiv::vertex_normals(mesh, NormalWeighting::Angle), 2, 2);
        PrincipalCurvatures out{"Monge_via_jet_fitting, degree 2, 2-ring", m.fitted, m.k1, m.k2, {}, {}, m.direction1};
        for (size_t v = 0; v < m.k1.size(); ++v) {
            out.mean.push_back((m.k1[v] + m.k2[v]) / 2);
            out.gaussian.push_back(m.k1[v] * m.k2[v]);
        }
        return out;
    }
};

class CgalOneCall final : public Implementation {
public:
    CgalOneCall()
        : Implementation("cgal-one-call", cg::version(), ImplementationKind::Library,
                         {.schemes = {supports(Scheme::Sqrt3, {sqrt3_rule(Sqrt3Parity::CountFromInput)})}}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        return cg::sqrt3(triangles_for(mesh, r.scheme), r.levels, true);
    }
};

}  // namespace

std::vector<std::unique_ptr<Implementation>> make_cgal_implementations() {
    std::vector<std::unique_ptr<Implementation>> out;
    out.push_back(std::make_unique<Cgal>());
    out.push_back(std::make_unique<CgalOneCall>());
    return out;
}

}  // namespace crossdiv::verification::detail
