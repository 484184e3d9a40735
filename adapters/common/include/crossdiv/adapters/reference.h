#pragma once
/// @file
/// What every reference adapter returns and throws. Adapters never call each other and
/// never call our algorithms: each one drives its own library and reports what it made.

#include <stdexcept>
#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::adapters {

/// The reference refused the input or the requested rule (it cannot do Warren weights, it
/// could not add a face, its factory reported an error). The message says why in the
/// library's own words when it gave any.
class Rejected : public std::runtime_error {
public:
    explicit Rejected(const std::string& why) : std::runtime_error(why) {}
};

/// @throws Rejected when `mesh` has crease or corner tags and `library` has no crease rules:
///         refining it smooth would answer a different question.
inline void reject_crease_tags(const PolyMesh& mesh, const char* library) {
    if (!mesh.creases.empty())
        throw Rejected(std::string(library) + " has no crease rules; the mesh has " +
                       std::to_string(mesh.creases.edges.size()) + " crease and " +
                       std::to_string(mesh.creases.vertices.size()) + " corner tag(s)");
}

/// Each level of a refinement as the library holds it: levels[0] is the input as the
/// library stored it, levels[k] the mesh after k subdivision steps, vertices and faces in
/// the library's own order.
using LevelTrace = std::vector<PolyMesh>;

}  // namespace crossdiv::adapters
