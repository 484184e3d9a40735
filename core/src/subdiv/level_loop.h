#pragma once
// N levels of a polygon scheme given its one-level step: the loop every RefinementStep
// scheme shares (connectivity rebuilt per level, positions and colors through the stencils).

#include <string>

#include "crossdiv/error.h"
#include "crossdiv/mesh/poly_connectivity.h"
#include "crossdiv/subdiv/nonmanifold_rule.h"
#include "crossdiv/subdiv/refinement.h"
#include "finite_level.h"

namespace crossdiv::detail {

/// `levels` levels of `step(mesh, level)` (a RefinementStep; level 0 = the first), each
/// level's positions required finite; the source (file lines) is not carried over.
template <class Step>
PolyMesh apply_levels(const PolyMesh& mesh, int levels, const Step& step) {
    if (levels < 0) throw InputError("number of levels must be >= 0, got " + std::to_string(levels));
    PolyMesh current = mesh;
    for (int l = 0; l < levels; ++l) {
        PolyMesh next = apply_step(step(current, l), current);
        require_finite_level(next.positions, current.positions, l + 1);
        current = std::move(next);
    }
    current.source = {};
    return current;
}

/// `step(mesh, conn, level)` returns the RefinementStep of level `level` (0 = the first); build_poly_connectivity checks
/// the input (and throws InputError naming the element) before the first step.
template <class Step>
PolyMesh refine_levels(const PolyMesh& mesh, int levels, const Step& step) {
    if (levels == 0) build_poly_connectivity(mesh);  // the same checks as a refinement
    return apply_levels(mesh, levels, [&](const PolyMesh& m, int l) { return step(m, build_poly_connectivity(m), l); });
}

/// A refinement of Loop or Catmull-Clark that takes OpenSubdiv's non-manifold rules
/// (nonmanifold.h) where they apply: `manifold()`, or `nonmanifold()` for a level whose edges
/// are stated per corner (one those rules refined) and, unless `rule` refuses, for a mesh
/// the manifold refinement finds is not a manifold (NonManifoldInput).
template <class Manifold, class NonManifold>
PolyMesh with_nonmanifold_rules(const PolyMesh& mesh, NonManifoldRule rule, const Manifold& manifold,
                                const NonManifold& nonmanifold) {
    if (!mesh.derived.empty()) return nonmanifold();
    try {
        return manifold();
    } catch (const NonManifoldInput&) {
        if (rule == NonManifoldRule::Refuse) throw;
        return nonmanifold();
    }
}

/// @throws InputError naming the first face that is not a triangle, for the schemes that
///         refine triangles only (sqrt3, the Butterflies).
inline void require_triangles(const PolyMesh& mesh, const char* scheme) {
    for (int f = 0; f < mesh.num_faces(); ++f)
        if (mesh.face_size(f) != 3)
            throw InputError(mesh.source.describe_face(f) + ": has " + std::to_string(mesh.face_size(f)) +
                             " corners; " + scheme + " refines triangles only");
}

/// @throws InputError for a mesh with hierarchical edits, which only catmull_clark_levels
///         applies (a step, or another scheme, would drop them: a silent wrong answer).
inline void require_no_hierarchical_edits(const PolyMesh& mesh, const char* what) {
    if (!mesh.creases.edits.empty())
        throw InputError((mesh.source.file.empty() ? std::string("the mesh") : mesh.source.file) + " has " +
                         std::to_string(mesh.creases.edits.size()) + " hierarchical edit(s) (the first: " +
                         describe(mesh.creases.edits.front()) + "); " + what +
                         " does not apply them (core applies them under Catmull-Clark, as Hbr does)");
}

/// @throws InputError for a mesh with crease, corner or hole tags, for the schemes without
///         those rules (sqrt3, Doo-Sabin, the Butterflies): dropping the tags would be a silent
///         wrong answer.
inline void require_no_creases(const PolyMesh& mesh, const char* scheme) {
    if (!mesh.creases.empty())
        throw InputError((mesh.source.file.empty() ? std::string("the mesh") : mesh.source.file) + " has " +
                         mesh.creases.describe() + "; " + scheme +
                         " has no crease or hole rules (Loop and Catmull-Clark have)");
}

}  // namespace crossdiv::detail
