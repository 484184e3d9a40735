// VTK as an implementation: "vtk", vtkLoopSubdivisionFilter called once per level. VTK's
// filters store the points they make in single precision (vtkPoints of VTK_FLOAT, whatever the
// input's type), so it is held to the float tier.
//
// Its Butterfly and linear filters are in the adapter (adapters/vtk) but not declared here:
// vtkButterflySubdivisionFilter is the modified Butterfly with a boundary treatment of its own
// (a missing wing point replaced by the other face's opposite vertex; an extraordinary vertex
// whose walk meets the boundary read by the eight-point stencil; valence counted in faces), a
// rule core does not have yet, and the linear filter's midpoint split is a scheme core lacks.
#include "crossdiv/adapters/vtk.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

namespace vt = adapters::vtk;

class Vtk final : public Implementation {
public:
    Vtk()
        : Implementation("vtk", vt::version(), ImplementationKind::Library,
                         {.schemes = {supports(Scheme::Loop, {loop_rule(LoopWeights::Loop, LoopBoundary::EdgeOnly)})},
                          .precision = Precision::Float}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        return vt::subdivide(triangles_for(mesh, r.scheme), vt::Filter::Loop, r.levels);
    }

    size_t refine_native(const TriMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        return vt::subdivide_native(mesh, vt::Filter::Loop, r.levels);
    }
};

}  // namespace

std::unique_ptr<Implementation> make_vtk_implementation() { return std::make_unique<Vtk>(); }

}  // namespace crossdiv::verification::detail
