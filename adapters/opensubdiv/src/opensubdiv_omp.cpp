// OpenSubdiv on every core: Far's float stencil table evaluated by Osd::OmpEvaluator.
#include <opensubdiv/far/stencilTable.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/osd/bufferDescriptor.h>
#include <opensubdiv/osd/ompEvaluator.h>

#include <memory>

#include "crossdiv/adapters/opensubdiv.h"
#include "opensubdiv_far.h"

namespace crossdiv::adapters::opensubdiv {

using namespace detail;

struct OmpStencils::Impl {
    std::unique_ptr<const Far::StencilTable> stencils;

    /// The last level's stencils, factorized to the base vertices.
    void build(Far::TopologyRefiner& refiner, int levels) {
        refine_uniform(refiner, levels, false);
        Far::StencilTableFactory::Options o;
        o.generateIntermediateLevels = false;
        o.factorizeIntermediateLevels = true;
        stencils.reset(Far::StencilTableFactory::Create(refiner, o));
    }
};

OmpStencils::OmpStencils(const TriMesh& mesh, const LoopOptions& options, int levels) : impl_(std::make_unique<Impl>()) {
    impl_->build(*make_refiner(to_poly_mesh(mesh), Sdc::SCHEME_LOOP, loop_options(options)), levels);
}

OmpStencils::OmpStencils(const PolyMesh& mesh, const CatmullClarkOptions& options, int levels)
    : impl_(std::make_unique<Impl>()) {
    impl_->build(*make_refiner(mesh, Sdc::SCHEME_CATMARK, catmark_options(options)), levels);
}

OmpStencils::~OmpStencils() = default;

int OmpStencils::num_stencils() const { return impl_->stencils->GetNumStencils(); }

void OmpStencils::evaluate(const std::vector<float>& base, std::vector<float>& out, int threads) const {
    const Far::StencilTable& t = *impl_->stencils;
    out.resize(3 * static_cast<size_t>(t.GetNumStencils()));
    const Osd::BufferDescriptor xyz(0, 3, 3);
    Osd::OmpEvaluator::SetNumThreads(threads);
    Osd::OmpEvaluator::EvalStencils(base.data(), xyz, out.data(), xyz, t.GetSizes().data(), t.GetOffsets().data(),
                                    t.GetControlIndices().data(), t.GetWeights().data(), 0, t.GetNumStencils());
}

}  // namespace crossdiv::adapters::opensubdiv
