#pragma once
/// @file
/// Face-varying layouts put on any mesh, so that every catalog mesh can be refined with
/// texture coordinates: no seam, a seam on every edge, one seam across the mesh (seams meet
/// the boundary, end inside as darts, cross creases), and three UV regions meeting at
/// junctions. Values are a smooth but not affine function of the position (every linear
/// rule reproduces affine data exactly, so affine values would hide which rule was used).

#include <array>
#include <string>
#include <vector>
#include <string_view>

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/named_variant.h"

namespace crossdiv::datasets {

enum class UvLayout {
    Welded,        ///< one value per vertex: the face-varying topology is the vertex topology
    PerFace,       ///< one value per corner: every edge is a seam (equal numbers, distinct values)
    HalfSeam,      ///< faces right of the mesh's centroid get their own values, offset: one seam
    ThreeRegions,  ///< faces in three sectors around the centroid (in x, y), each offset: junctions
};

inline constexpr std::array kUvLayouts{UvLayout::Welded, UvLayout::PerFace, UvLayout::HalfSeam, UvLayout::ThreeRegions};

/// "welded", "per-face", "half-seam", "three-regions".
constexpr std::string_view to_string(UvLayout l) {
    switch (l) {
        case UvLayout::Welded: return "welded";
        case UvLayout::PerFace: return "per-face";
        case UvLayout::HalfSeam: return "half-seam";
        case UvLayout::ThreeRegions: return "three-regions";
    }
    return "?";
}

/// The layout named `name`. @throws InputError listing the names.
inline UvLayout uv_layout_from_string(std::string_view name) {
    return variant_from_string<UvLayout>(name, kUvLayouts, "UV layout");
}

/// The texture coordinate of a position (before a region's offset): u = x + 0.37 y^2 - 0.11 z,
/// v = y - 0.23 x z + 0.05 x^2.
std::array<double, 2> uv_of_position(const Vec3& p);

/// `mesh` with its face-varying channels replaced by one channel "uv" in `layout`.
PolyMesh with_uv_layout(const PolyMesh& mesh, UvLayout layout);

/// `mesh` with one channel "uv" whose regions are given per face: corners of faces of one
/// region share their vertex's value there (uv_of_position offset by the region), faces of
/// different regions meet at seams.
PolyMesh with_uv_regions(const PolyMesh& mesh, const std::vector<int>& face_region);

/// The face-varying edge cases (their names start "uv-"), each on a 4 x 4 quad grid and on its
/// triangulation ("-tri"): a seam across the grid, a seam ending inside (a dart), a seam
/// inside the grid (two darts), three regions meeting at a junction, a one-face island
/// (four UV corners inside the mesh), a region touching itself at a vertex only (a value of
/// two disjoint spans), seams on infinitely sharp and on semi-sharp creases, and one value
/// per corner. Source file of each mesh: "edgecase:NAME"; edge_case() finds them.
struct UvEdgeCase {
    std::string name;
    std::string description;
    PolyMesh mesh;
};
std::vector<UvEdgeCase> uv_edge_cases();

}  // namespace crossdiv::datasets
