#pragma once
// Between the adapter (hbr_subdivision.cpp, C++20 like the rest of crossdiv) and the one
// translation unit that includes Hbr (hbr_refiner.cpp), which is compiled as C++17: Hbr's
// headers declare constructors as `HbrSubdivision<T>()`, which C++20 no longer accepts. So
// this header holds plain arrays and no crossdiv type.
#include <string>
#include <vector>

namespace crossdiv::adapters::hbr::detail {

enum class HbrScheme { CatmullClark, Loop, Bilinear };

/// One hierarchical edit (crossdiv's HierarchicalEdit in plain numbers).
struct HbrEdit {
    int target = 0;  ///< 0 position (HbrVertexEdit), 1 vertex sharpness (HbrCornerEdit), 2 edge sharpness (HbrCreaseEdit), 3 hole (HbrHoleEdit)
    int op = 0;      ///< 0 set, 1 add, 2 subtract
    int face = 0;
    std::vector<int> children;
    int element = 0;
    float value[3] = {0, 0, 0};  ///< Hbr keeps its edits' values in float
};

/// Hbr's face-varying boundary methods (HbrMesh::InterpolateBoundaryMethod, as
/// SetFVarInterpolateBoundaryMethod takes them).
enum class HbrFVarBoundary { None, EdgeOnly, EdgeAndCorner, AlwaysSharp };

/// A mesh whose topology Hbr can hold (checked before: hbr_subdivision.cpp) and its tags.
struct HbrInput {
    HbrScheme scheme = HbrScheme::CatmullClark;
    bool edge_and_corner = false;   ///< k_InterpolateBoundaryEdgeAndCorner, else EdgeOnly
    bool chaikin = false;           ///< k_CreaseChaikin, else k_CreaseNormal
    bool smooth_triangles = false;  ///< Catmull-Clark's k_New triangle rule, else k_Normal
    std::vector<double> positions;  ///< x, y, z per vertex
    std::vector<int> face_sizes, corners;
    std::vector<int> crease_ends;  ///< two vertices per sharp edge
    std::vector<float> crease_sharpness;
    std::vector<int> corner_vertices;
    std::vector<float> corner_sharpness;
    std::vector<int> holes;
    std::vector<HbrEdit> edits;  ///< applied as Hbr applies them (paths checked before)
    /// One face-varying channel when fvar_width > 0: fvar_width numbers per value (Hbr keeps
    /// them in float), the value of every corner in the order of `corners`.
    int fvar_width = 0;
    std::vector<float> fvar_values;
    std::vector<int> fvar_corners;
    HbrFVarBoundary fvar_boundary = HbrFVarBoundary::None;
    bool fvar_propagate_corners = false;  ///< SetFVarPropagateCorners
    int levels = 1;
};

/// One refined level: vertices in order of first use by its faces, and each vertex's parent in
/// the level before (kind 0 vertex a, 1 edge a-b, 2 face a).
struct HbrLevel {
    std::vector<double> positions;
    std::vector<int> face_sizes, corners, holes;
    std::vector<int> parent_kind, parent_a, parent_b;
    /// The face-varying channel (with HbrInput::fvar_width): one value per face-varying datum
    /// Hbr keeps (corners of a vertex share a value exactly when Hbr gives them the same
    /// datum), numbered in order of first use by the corners.
    std::vector<float> fvar_values;
    std::vector<int> fvar_corners;
};

struct HbrOutput {
    std::vector<HbrLevel> levels;  ///< levels 1 .. HbrInput::levels
    std::string error;             ///< what Hbr could not do; then `levels` is incomplete
};

HbrOutput refine(const HbrInput& input);

/// "3.5.0".
std::string version();

}  // namespace crossdiv::adapters::hbr::detail
