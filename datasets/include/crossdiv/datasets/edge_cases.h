#pragma once
/// @file
/// The edge-case catalog: named topology cases generated in code, after the kinds in
/// OpenSubdiv's regression/shapes (fans, poles, boundary fans, corners, saddles, non-manifold
/// edges and vertices, genus > 1) plus the numeric traps (tiny, huge and near-coincident
/// coordinates, slivers, zero area). Each case says whether it is a valid Loop input: the
/// invalid ones must be refused by core with an error naming the element, and what each
/// reference does with them is what the suite records.

#include <string>
#include <vector>

#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv::datasets {

struct EdgeCase {
    std::string name;
    std::string description;  ///< one line: the topology or numeric trap it sets
    bool valid_loop_input;    ///< a manifold, consistently oriented triangle mesh (else core refines it by OpenSubdiv's non-manifold rules, or refuses it)
    PolyMesh mesh;
};

/// Every case, in a fixed order (about 60). Source file of each mesh: "edgecase:NAME".
std::vector<EdgeCase> edge_cases();

/// The cases of polygons (Catmull-Clark's; not Loop input): polygons back to back, a hole
/// beside creases, a non-manifold quad edge, a duplicate quad, a quad naming a vertex twice.
/// `valid_loop_input` says here whether the mesh is a manifold, consistently oriented.
std::vector<EdgeCase> polygon_edge_cases();

/// One case by name, of either list or of the face-varying cases (uv_layouts.h).
/// @throws InputError naming the unknown name.
EdgeCase edge_case(const std::string& name);

/// The closed benchmark mesh: an irregular torus (valences 4..8) with 2 nu nv faces,
/// nu = nv = round(sqrt(faces / 2)).
PolyMesh benchmark_mesh(int faces);

}  // namespace crossdiv::datasets
