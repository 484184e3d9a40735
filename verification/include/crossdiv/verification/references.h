#pragma once
/// @file
/// The reference libraries compiled into this build, by name. The harness reaches every
/// adapter through this table; adapters never see each other.

#include <string>
#include <vector>

#include "crossdiv/adapters/reference.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/subdiv/loop_mask.h"

namespace crossdiv::verification {

struct LoopReference {
    std::string name;     ///< "opensubdiv", "openmesh", "cgal"
    std::string version;  ///< as the library reports it
    bool (*supports)(const LoopOptions&);
    adapters::LevelTrace (*loop)(const TriMesh&, const LoopOptions&, int levels);
    /// The same refinement kept in the library's structures; returns the output face count.
    size_t (*loop_native)(const TriMesh&, const LoopOptions&, int levels);
};

/// The references built in (CROSSDIV_WITH_* options), in a fixed order.
const std::vector<LoopReference>& loop_references();

/// @throws InputError naming the unknown reference and listing the available ones.
const LoopReference& find_loop_reference(const std::string& name);

/// The requested options if the reference has them; otherwise the closest rules it has
/// (Loop weights for Warren, EdgeOnly for EdgeAndCorner), so it can still be run and the
/// difference classified.
LoopOptions closest_supported(const LoopReference& ref, const LoopOptions& requested);

}  // namespace crossdiv::verification
