#pragma once
/// @file
/// The studies of schemes and limit behaviour, each a suite operation over a fixed catalog
/// (operations.h): measured checks, each with its named tolerance, and the full tables. One
/// file per study in src/studies/ (the larger ones have their own header beside this one).
///
/// Adding a study: its file in src/studies/ (a function returning a CheckReport), its
/// declaration here, one line in suite_operations() (operations.cpp: its name, the catalog it
/// runs over, a one-line description), and its line in reports/suite-manifest.md. The report
/// finds it by its kind in results.json; a section of its own for its tables goes in
/// reports/report/sections.py.

#include "crossdiv/mesh/poly_mesh.h"
#include "crossdiv/verification/properties/check.h"

namespace crossdiv::verification {

/// The Butterfly properties of both variants on the bundled meshes, and the rule oracles of
/// Doo-Sabin's boundaries, sqrt3's parities and the classic Butterfly's wings.
CheckReport schemes_study();
/// The crease catalog against OpenSubdiv, and the crease-cube figure.
CheckReport creases_study();
/// Limit positions and interior normals against OpenSubdiv's Limit(), and Bfr's (u, v)
/// evaluation against core's exact limit.
CheckReport limit_positions_study();
/// Vertex age (subdiv/vertex_age.h) of every scheme, 3 levels of core on the icosahedron:
/// the vertices born at each level against the counts the topology dictates; the Butterflies'
/// oldest vertices at their input positions; Loop's and Catmull-Clark's meshes for the figure.
CheckReport vertex_age_study();
/// The eigen table, valence 3..20, Loop, Warren, Catmull-Clark, each against its published
/// closed form; and the Loop rule oracle (loop_rule_oracle.h) of each Loop rule it knows.
CheckReport spectrum_study();
/// The convergence table, valence 3..12, levels 1..8.
CheckReport convergence_study();
/// The identity OpenSubdiv documents for face-varying data: texture coordinates copied from x
/// and y, one per vertex, refine under the smooth rule (`none`) exactly as the positions do.
/// Checked for core and for every reference that refines face-varying data, Catmull-Clark on
/// every catalog and crease mesh and Loop on the triangle ones, both boundary rules, 2 levels.
CheckReport face_varying_study();

/// A mesh as {positions, faces} for the report's figures (mesh_json.cpp).
nlohmann::json mesh_json(const PolyMesh& m);

}  // namespace crossdiv::verification
