#pragma once
/// @file
/// What every reference adapter returns and throws. Adapters never call each other and
/// never call our algorithms: each one drives its own library and reports what it made.

#include <stdexcept>
#include <string>
#include <optional>
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

/// The library made a result that is not a mesh (a face whose corners never close, a corner
/// that names no vertex): the harness records it as the library's invalid output, naming the
/// element, instead of reading on.
class InvalidResult : public std::runtime_error {
public:
    explicit InvalidResult(const std::string& why) : std::runtime_error(why) {}
};

/// @throws Rejected when `mesh` has crease or corner tags and `library` has no crease rules:
///         refining it smooth would answer a different question.
inline void reject_crease_tags(const PolyMesh& mesh, const char* library) {
    if (!mesh.creases.empty())
        throw Rejected(std::string(library) + " has no crease or hole rules; the mesh has " + mesh.creases.describe());
}

/// Each level of a refinement as the library holds it: levels[0] is the input as the
/// library stored it, levels[k] the mesh after k subdivision steps, vertices and faces in
/// the library's own order.
using LevelTrace = std::vector<PolyMesh>;

/// Where a refined vertex was born, in the numbering of the level before.
struct VertexBirth {
    enum class Kind : unsigned char { Vertex, Edge, Face };
    Kind kind = Kind::Vertex;
    int a = -1, b = -1;  ///< Vertex: a; Edge: its ends a, b (a == b for a degenerate edge); Face: a, the face
    bool operator==(const VertexBirth&) const = default;
};
/// births[l-1]: the birth of each vertex of level l of a LevelTrace.
using LevelBirths = std::vector<std::vector<VertexBirth>>;

/// A point of a limit surface with its first partial derivatives.
struct LimitSample {
    Vec3 position, du, dv;
};
struct LimitEvaluation {
    bool regular = false;  ///< Bfr represents the face exactly by one regular bicubic patch
    std::vector<LimitSample> samples;
};

/// Limit positions and limit normals of every vertex of a refined level (the normal is the
/// normalized cross product of the two limit tangents, zero where they are parallel); `level`
/// is that level's mesh in the library's order. When the request refines texture coordinates,
/// `uv` holds the limit values of the level's first channel, indexed by its corners.
struct LimitPoints {
    PolyMesh level;
    std::vector<Vec3> position, normal;
    std::optional<FaceVaryingChannel> uv = std::nullopt;
};

/// Position and first and second derivatives at each requested parameter.
struct SplineSamples {
    std::vector<Vec3> position, d1, d2;
};

/// What a library says about a triangle mesh as a closed surface (CGAL: is_valid_polygon_mesh,
/// is_closed, PMP::is_outward_oriented, PMP::volume).
struct ClosedMeshReport {
    bool built = false;           ///< Surface_mesh accepted every face
    std::string error;            ///< why not, naming the face
    bool valid = false;           ///< CGAL::is_valid_polygon_mesh
    bool closed = false;          ///< CGAL::is_closed (no border halfedge)
    bool outward = false;         ///< PMP::is_outward_oriented (only computed when closed)
    double volume = 0;            ///< PMP::volume (only computed when closed)
};

}  // namespace crossdiv::adapters
