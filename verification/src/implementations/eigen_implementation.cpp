// Eigen's unsupported Splines module as the curves' reference: B-spline evaluation by
// Cox-de Boor with derivatives.
#include "crossdiv/adapters/eigen_splines.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

namespace es = adapters::eigen_splines;

class EigenSplines final : public Implementation {
public:
    EigenSplines()
        : Implementation("eigen", es::version(), ImplementationKind::Library, {.schemes = {}, .spline_evaluation = true}) {}

    adapters::SplineSamples evaluate_spline(SplineKind kind, std::span<const Vec3> control,
                                            std::span<const double> params) const override {
        return kind == SplineKind::UniformCubicBSpline ? es::uniform_cubic_bspline(control, params)
                                                       : es::clamped_bezier(control, params);
    }
};

}  // namespace

std::unique_ptr<Implementation> make_eigen_implementation() { return std::make_unique<EigenSplines>(); }

}  // namespace crossdiv::verification::detail
