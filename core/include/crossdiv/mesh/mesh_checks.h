#pragma once
/// @file
/// Diagnostics for any polygon mesh: every problem found, each naming its element (and the
/// file line when known). `crossdiv check` prints these; schemes call require_* to refuse
/// input they cannot take with the first error as the message.

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

enum class MeshIssueKind {
    IndexOutOfRange,          ///< a face names a vertex that does not exist
    RepeatedVertex,           ///< a face uses the same vertex twice
    TooFewCorners,            ///< a face with fewer than 3 corners
    NonManifoldEdge,          ///< an edge shared by more than two faces
    InconsistentOrientation,  ///< two faces traverse a shared edge in the same direction
    NonManifoldVertex,        ///< a vertex whose faces form more than one fan (bowtie)
    IsolatedVertex,           ///< a vertex no face uses
    ZeroAreaFace,             ///< area below kZeroAreaRelative * (longest edge)^2
    NonFiniteCoordinate,      ///< NaN or infinity in a position
};

/// Errors break connectivity or arithmetic; warnings are legal but worth knowing.
enum class Severity { Error, Warning };

struct MeshIssue {
    MeshIssueKind kind;
    Severity severity;
    std::string message;  ///< names the element, e.g. "face 12 (a.obj:40): repeated vertex 7"
};

/// A face counts as zero-area when its area is below this times its longest edge squared:
/// a few ulps of the products that form the cross product, so exactly collinear corners
/// are caught whatever the mesh scale, and slivers that are merely thin are not.
inline constexpr double kZeroAreaRelative = 8.0 * 2.220446049250313e-16;

/// Every issue of the mesh, errors and warnings, in a deterministic order.
std::vector<MeshIssue> check_mesh(const PolyMesh& mesh);

/// Short stable name of an issue kind ("non-manifold-edge", ...), used in JSON output.
const char* to_string(MeshIssueKind kind);

}  // namespace crossdiv
