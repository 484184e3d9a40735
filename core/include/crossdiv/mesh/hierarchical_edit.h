#pragma once
/// @file
/// Hierarchical edits: a change to one vertex, edge or face of a refined level, named by a path
/// from a base face down the levels. RenderMan's subdivision meshes have them, and OpenSubdiv's
/// Hbr implements them (HbrVertexEdit, HbrCornerEdit, HbrCreaseEdit, HbrHoleEdit); in a shape
/// file they are the tags
///
///     t vertexedit nint/nfloat/nstring  paths...  values...  (op P value|sharpness)...
///     t edgeedit   nint/nfloat/nstring  paths...  values...  (op P sharpness)...
///     t faceedit   nint/0/nstring       paths...  hole...
///
/// where a path is `length face child... element` (faceedit: `length face child...`), op is
/// `set`, `add` or `subtract`, and each path takes its values in turn (3 per `value`, 1 per
/// `sharpness`). OpenSubdiv's regression shapes `catmark_square_hedit0..4` use all four kinds.
///
/// The path numbers children as Hbr does: child i of a face is the quad at the face's corner i
/// (in the face's own corner order at that level); an element is a corner (a vertex) or the
/// edge leaving that corner. Hbr orders the corners of the children of a quad from that
/// corner's slot: child i of a quad holds the child of corner i in slot i, then the edge, face
/// and previous-edge points in turn, so slot j of child i is core's slot (j - i) mod 4 of the
/// same child (catmull_clark.h numbers every child from its corner's vertex). Children of other
/// faces start at slot 0 in both.

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace crossdiv {

/// What an edit does to its operand.
enum class EditOperation { Set, Add, Subtract };

/// "set", "add", "subtract".
constexpr std::string_view to_string(EditOperation op) {
    return op == EditOperation::Set ? "set" : op == EditOperation::Add ? "add" : "subtract";
}

/// What an edit changes.
enum class EditTarget {
    Position,         ///< a vertex's position (`t vertexedit ... P value`; HbrVertexEdit)
    VertexSharpness,  ///< a vertex's sharpness (`t vertexedit ... P sharpness`; HbrCornerEdit)
    EdgeSharpness,    ///< an edge's sharpness (`t edgeedit ... P sharpness`; HbrCreaseEdit)
    Hole,             ///< the face becomes a hole (`t faceedit ... hole`; HbrHoleEdit)
};

/// "position", "vertex sharpness", "edge sharpness", "hole".
constexpr std::string_view to_string(EditTarget t) {
    return t == EditTarget::Position          ? "position"
           : t == EditTarget::VertexSharpness ? "vertex sharpness"
           : t == EditTarget::EdgeSharpness   ? "edge sharpness"
                                              : "hole";
}

/// One edit at the level of its path's length.
struct HierarchicalEdit {
    EditTarget target = EditTarget::Position;
    EditOperation op = EditOperation::Set;
    int face = 0;               ///< the base face the path starts from
    std::vector<int> children;  ///< the child taken at each level (Hbr's numbering, above)
    /// The vertex (Position, VertexSharpness) or the edge leaving that vertex (EdgeSharpness)
    /// of the path's last face, in Hbr's slot order; -1 for a Hole.
    int element = -1;
    /// The operand: a position, or a sharpness in [0].
    std::array<double, 3> value{};
    int line = 0;  ///< 1-based line of its tag in the file, or 0

    /// The level it changes: 0 for the base mesh, 1 for the first refined level, ...
    int level() const { return static_cast<int>(children.size()); }
    friend bool operator==(const HierarchicalEdit&, const HierarchicalEdit&) = default;
};

/// "add position at level 2 (face 4, children 1 1, vertex 0)": an edit for a message.
std::string describe(const HierarchicalEdit& edit);

/// What is wrong with `edit`'s path on a base mesh of `num_faces` faces whose face `edit.face`
/// has `base_face_size` corners (ignored when the face is out of range), or "" when nothing
/// is: the face must exist, the first child must be one of its corners and every later one
/// of a quad's four (Catmull-Clark's children are quads), the element a corner of the last
/// face, and a hole names no element.
std::string hierarchical_edit_problem(const HierarchicalEdit& edit, int num_faces, int base_face_size);

}  // namespace crossdiv
