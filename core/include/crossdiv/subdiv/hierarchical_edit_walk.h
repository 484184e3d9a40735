#pragma once
/// @file
/// Hierarchical edits (mesh/hierarchical_edit.h) applied during a Catmull-Clark refinement:
/// each edit's path is followed one level at a time, from its base face to the face of its
/// level, and the edit is applied to that level's mesh before the next level is made from it,
/// as Hbr applies them (an edited vertex is used edited by every later level).
///
/// Following a path needs catmull_clark.h's numbering only: face f's children are its
/// corners, quad k being the one at corner k. Hbr numbers the slots of a quad's children from
/// the corner they sit at, so the walk keeps, per path, how far Hbr's slots are turned from
/// core's in the current face.

#include <vector>

#include "crossdiv/mesh/hierarchical_edit.h"
#include "crossdiv/mesh/poly_mesh.h"

namespace crossdiv {

class HierarchicalEditWalk {
public:
    /// The walk of `base.creases.edits`, each at its base face.
    /// @throws InputError naming the edit (and its line) for a path that leaves `base`
    ///         (hierarchical_edit_problem).
    explicit HierarchicalEditWalk(const PolyMesh& base);

    /// Applies the edits of level `level` to `mesh`, that level's mesh, in their order: a
    /// position is set, added to or subtracted from; a sharpness likewise, kept within
    /// [0, 10] as Hbr keeps it (HbrCornerEdit, HbrCreaseEdit); a hole edit makes the face a
    /// hole (its children are holes too).
    void apply(PolyMesh& mesh, int level) const;

    /// Follows every path that goes deeper than `level` from `coarse` (the mesh of level
    /// `level`) to the child it names in the next Catmull-Clark level.
    void descend(const PolyMesh& coarse, int level);

    bool empty() const { return edits_.empty(); }

private:
    struct Cursor {
        int face;      ///< the path's face in the current level
        int rotation;  ///< Hbr's slot j is core's slot (j - rotation) mod n there
    };
    std::vector<HierarchicalEdit> edits_;
    std::vector<Cursor> cursors_;
};

}  // namespace crossdiv
