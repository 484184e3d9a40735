// OpenMesh as implementations: "openmesh" (LoopT, CatmullClarkT, Sqrt3T and ModifiedButterflyT
// called once per level; flips, splits and vertex normals) and "openmesh-one-call" (Sqrt3T
// asked for every level in one call, which counts the boundary generations from the input).
#include "crossdiv/adapters/openmesh.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

namespace om = adapters::openmesh;

/// Sqrt3T fills its weights for valences below 50 (init_weights(50)) and indexes the table
/// with the valence unchecked.
constexpr int kSqrt3MaxValence = 49;
constexpr const char* kSqrt3Table = "Sqrt3T::init_weights(50)";

class OpenMesh final : public Implementation {
public:
    OpenMesh()
        : Implementation("openmesh", om::version(), ImplementationKind::Library,
                         {.schemes = {supports(Scheme::Loop, {loop_rule(LoopWeights::Loop, LoopBoundary::EdgeOnly)}),
                                      supports(Scheme::CatmullClark, {catmull_clark_rule(CatmullClarkBoundary::MidpointAverage)}),
                                      supports(Scheme::Sqrt3, {sqrt3_rule(Sqrt3Parity::RestartEachLevel)}, false,
                                               kSqrt3MaxValence, kSqrt3Table),
                                      supports(Scheme::ModifiedButterfly, {SchemeRule{}})},
                          .edits = true,
                          .vertex_normals = true}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        switch (r.scheme) {
            case Scheme::Loop: return om::loop(triangles_for(mesh, r.scheme), closest_rule(r.scheme, r.rule).loop, r.levels);
            case Scheme::CatmullClark: return om::catmull_clark(mesh, r.levels);
            case Scheme::Sqrt3: return om::sqrt3(triangles_for(mesh, r.scheme), r.levels, false);
            default: return om::modified_butterfly(triangles_for(mesh, r.scheme), r.levels);
        }
    }

    size_t refine_native(const TriMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::Loop) return Implementation::refine_native(mesh, r);
        return om::loop_native(mesh, closest_rule(r.scheme, r.rule).loop, r.levels);
    }

    size_t refine_polygons_native(const PolyMesh& mesh, const RefineRequest& r) const override {
        if (r.scheme != Scheme::CatmullClark) return Implementation::refine_polygons_native(mesh, r);
        return om::catmull_clark_native(mesh, r.levels);
    }

    std::vector<NamedNormals> vertex_normals(const TriMesh& mesh) const override {
        std::vector<NamedNormals> out;
        for (auto [name, method, m] : {std::tuple{"openmesh-correct", "PolyMeshT::calc_vertex_normal_correct", om::NormalMethod::Correct},
                                       std::tuple{"openmesh-fast", "PolyMeshT::update_vertex_normals", om::NormalMethod::Fast}}) {
            NamedNormals n{name, method, {}, {}};
            try {
                n.normals = om::vertex_normals(mesh, m);
            } catch (const std::exception& e) {
                n.error = e.what();
            }
            out.push_back(std::move(n));
        }
        return out;
    }

    std::unique_ptr<EditSession> open_edit(const TriMesh& base) const override {
        return std::make_unique<LibraryEditSession<om::EditableMesh, true>>(base);
    }
};

class OpenMeshOneCall final : public Implementation {
public:
    OpenMeshOneCall()
        : Implementation("openmesh-one-call", om::version(), ImplementationKind::Library,
                         {.schemes = {supports(Scheme::Sqrt3, {sqrt3_rule(Sqrt3Parity::CountFromInput)}, false,
                                               kSqrt3MaxValence, kSqrt3Table)}}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        return om::sqrt3(triangles_for(mesh, r.scheme), r.levels, true);
    }
};

}  // namespace

std::vector<std::unique_ptr<Implementation>> make_openmesh_implementations() {
    std::vector<std::unique_ptr<Implementation>> out;
    out.push_back(std::make_unique<OpenMesh>());
    out.push_back(std::make_unique<OpenMeshOneCall>());
    return out;
}

}  // namespace crossdiv::verification::detail
