#pragma once
/// @file
/// Ways of writing the same input otherwise, each with what it must do to a refinement: the
/// transformations of metamorphic (invariance) testing. A refinement of the transformed input
/// must be the refinement of the input, transformed alike:
///
///   rotate-corners        every face starts at its next corner: the same surface, the same
///                         faces (matched through the vertex correspondence)
///   rotate-corners-random every face starts at a corner drawn from the seed
///   reverse-faces         the faces listed last to first
///   rotate-faces          the face list rotated by half (the second half first): where a
///                         library reads something off the first face around a vertex, an
///                         order other than the reversed one
///   shuffle-faces         the faces in an order drawn from the seed
///   relabel-vertices      the vertices renumbered by a permutation drawn from the seed
///   reverse-orientation   every face's corners in the other order: the same points, every
///                         face reversed
///   translate             every position moved by a power of two times the diagonal (the
///                         bounding box's largest side rounded up to a power of two): exact
///                         in floating point only where the sums keep their exponents, so
///                         compared within the tier
///   scale                 every position times 2: exact (a power of two scales every sum
///                         without rounding), bit for bit
///   swap-axes             x and y exchanged: exact, bit for bit
///   mirror                x negated: exact, bit for bit
///   rotate                a general rotation (about the axis (1, 2, 3) by 0.7 rad): within
///                         the tier
///   components            each connected component (faces joined through shared vertices)
///                         refined on its own, the vertices no face uses with the first: the
///                         union of the results is the refinement of the whole, within the tier
///                         (each part is numbered otherwise, so sums may run in another order)
///   level-by-level        one level at a time, each run given the last one's result: the
///                         same as all the levels in one run, within the tier. Not where the
///                         rule counts levels from the input (sqrt3 count-from-input on a mesh
///                         with a boundary) nor on a tagged mesh (the levels returned carry no
///                         sharpness, corner or hole tags), nor for one level
///   repeat                the same input again: identical bytes (determinism)
///
/// Crease, corner and hole tags and face-varying channels travel with their vertices, faces
/// and corners. The first eleven write the input otherwise (transform_input); components and
/// level-by-level run the implementation otherwise on the input as it is (runs_otherwise).

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::verification {

enum class InputTransformation {
    RotateCorners,
    RotateCornersRandom,
    ReverseFaces,
    RotateFaces,
    ShuffleFaces,
    RelabelVertices,
    ReverseOrientation,
    Translate,
    Scale,
    SwapAxes,
    Mirror,
    Rotate,
    SplitComponents,
    LevelByLevel,
    Repeat,
};
inline constexpr std::array kInputTransformations{
    InputTransformation::RotateCorners,    InputTransformation::RotateCornersRandom, InputTransformation::ReverseFaces,
    InputTransformation::RotateFaces,      InputTransformation::ShuffleFaces,        InputTransformation::RelabelVertices,
    InputTransformation::ReverseOrientation,
    InputTransformation::Translate,        InputTransformation::Scale,               InputTransformation::SwapAxes,
    InputTransformation::Mirror,           InputTransformation::Rotate,              InputTransformation::SplitComponents,
    InputTransformation::LevelByLevel,     InputTransformation::Repeat};

/// The transformation runs the implementation otherwise (several runs) on the input as it is
/// rather than once on the input written otherwise: components, level-by-level.
constexpr bool runs_otherwise(InputTransformation t) {
    return t == InputTransformation::SplitComponents || t == InputTransformation::LevelByLevel;
}

/// The transformation writes the same mesh in another order (its faces, their corners or its
/// vertices) rather than moving it or running the implementation otherwise.
constexpr bool reorders(InputTransformation t) {
    switch (t) {
        case InputTransformation::RotateCorners:
        case InputTransformation::RotateCornersRandom:
        case InputTransformation::ReverseFaces:
        case InputTransformation::RotateFaces:
        case InputTransformation::ShuffleFaces:
        case InputTransformation::RelabelVertices:
        case InputTransformation::ReverseOrientation: return true;
        default: return false;
    }
}

/// "rotate-corners", "rotate-corners-random", "reverse-faces", "rotate-faces", ... (the names above).
const char* to_string(InputTransformation t);
/// @throws InputError naming the known names.
InputTransformation input_transformation_from_string(std::string_view name);

/// The input written otherwise, and what the refinement of it must be.
struct TransformedInput {
    PolyMesh mesh;
    /// The map applied to positions: p -> linear * p + offset (the identity for the
    /// combinatorial transformations).
    Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
    Vec3 offset = Vec3::Zero();
    /// Every face of the refinement of `mesh` is reversed against the refinement of the input
    /// (reverse-orientation).
    bool reversed = false;
    /// Floating point makes the expected result exact: the two refinements must agree bit for
    /// bit after the map (scale, swap-axes, mirror, repeat). Elsewhere they agree within the
    /// tier (summation order, rounding of a translation or rotation).
    bool exact = false;
};

/// `mesh` under `t`; `seed` draws the random ones (the same seed, the same transformation). For
/// the transformations that run otherwise (runs_otherwise), `mesh` itself under the identity.
TransformedInput transform_input(const PolyMesh& mesh, InputTransformation t, std::uint64_t seed);

/// The connected components of `mesh` (faces joined through a shared vertex, so a bowtie stays
/// whole), each with its faces in input order and its vertices in input order, its tags and
/// face-varying corners; the vertices no face uses go with the first. One part when the mesh
/// is connected.
std::vector<PolyMesh> connected_components(const PolyMesh& mesh);

/// `mesh` with its faces listed in `order` (order[i]: the face that becomes face i), hole tags
/// and face-varying corners following their faces.
PolyMesh with_face_order(const PolyMesh& mesh, const std::vector<int>& order);

}  // namespace crossdiv::verification
