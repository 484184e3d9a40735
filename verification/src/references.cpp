#include "crossdiv/verification/references.h"

#include "crossdiv/error.h"
#ifdef CROSSDIV_HAS_OPENSUBDIV
#include "crossdiv/adapters/opensubdiv.h"
#endif
#ifdef CROSSDIV_HAS_OPENMESH
#include "crossdiv/adapters/openmesh.h"
#endif
#ifdef CROSSDIV_HAS_CGAL
#include "crossdiv/adapters/cgal.h"
#endif

namespace crossdiv::verification {

const std::vector<LoopReference>& loop_references() {
    static const std::vector<LoopReference> refs = [] {
        std::vector<LoopReference> r;
#ifdef CROSSDIV_HAS_OPENSUBDIV
        r.push_back({"opensubdiv", adapters::opensubdiv::version(), adapters::opensubdiv::supports, adapters::opensubdiv::loop,
                     adapters::opensubdiv::loop_native});
#endif
#ifdef CROSSDIV_HAS_OPENMESH
        r.push_back({"openmesh", adapters::openmesh::version(), adapters::openmesh::supports, adapters::openmesh::loop,
                     adapters::openmesh::loop_native});
#endif
#ifdef CROSSDIV_HAS_CGAL
        r.push_back({"cgal", adapters::cgal::version(), adapters::cgal::supports, adapters::cgal::loop,
                     adapters::cgal::loop_native});
#endif
        return r;
    }();
    return refs;
}

const LoopReference& find_loop_reference(const std::string& name) {
    std::string known;
    for (const LoopReference& r : loop_references()) {
        if (r.name == name) return r;
        known += (known.empty() ? "" : ", ") + r.name;
    }
    throw InputError("unknown or not built reference '" + name + "' (built: " + (known.empty() ? "none" : known) + ")");
}

LoopOptions closest_supported(const LoopReference& ref, const LoopOptions& requested) {
    const LoopOptions candidates[] = {requested,
                                      {LoopWeights::Loop, requested.boundary},
                                      {requested.weights, LoopBoundary::EdgeOnly},
                                      {LoopWeights::Loop, LoopBoundary::EdgeOnly}};
    for (const LoopOptions& o : candidates)
        if (ref.supports(o)) return o;
    return requested;  // the adapter will reject it, and the run records why
}

}  // namespace crossdiv::verification
