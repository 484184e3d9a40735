// VTK as an implementation: "vtk", vtkLoopSubdivisionFilter, vtkButterflySubdivisionFilter and
// vtkLinearSubdivisionFilter called once per level. VTK's filters store the points they make in single precision
// (vtkPoints of VTK_FLOAT, whatever the input's type), so it is held to the float tier.
//
// Its Butterfly filter is the modified Butterfly (Zorin et al.) with VTK's boundary choices,
// core's rule other-face-wings (butterfly_mask.h). Its linear filter is the midpoint scheme
// (midpoint.h).
#include "crossdiv/adapters/vtk.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

namespace vt = adapters::vtk;

class Vtk final : public Implementation {
public:
    Vtk()
        : Implementation("vtk", vt::version(), ImplementationKind::Library,
                         {.schemes = {supports(Scheme::Loop, {loop_rule(LoopWeights::Loop, LoopBoundary::EdgeOnly)}),
                                      supports(Scheme::ModifiedButterfly, {butterfly_rule(ButterflyWings::OtherFaceVertex)}),
                                      supports(Scheme::Midpoint, {SchemeRule{}})},
                          .precision = Precision::Float}) {}

    adapters::LevelTrace refine(const PolyMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        return vt::subdivide(triangles_for(mesh, r.scheme), filter(r.scheme), r.levels);
    }

    size_t refine_native(const TriMesh& mesh, const RefineRequest& r) const override {
        check_refinable(r.scheme);
        return vt::subdivide_native(mesh, filter(r.scheme), r.levels);
    }

private:
    static vt::Filter filter(Scheme scheme) {
        return scheme == Scheme::ModifiedButterfly ? vt::Filter::Butterfly
               : scheme == Scheme::Midpoint        ? vt::Filter::Linear
                                                   : vt::Filter::Loop;
    }
};

}  // namespace

std::unique_ptr<Implementation> make_vtk_implementation() { return std::make_unique<Vtk>(); }

}  // namespace crossdiv::verification::detail
