#include "crossdiv/mesh/hierarchical_edit.h"

namespace crossdiv {

std::string describe(const HierarchicalEdit& edit) {
    // Appended piece by piece (GCC 12 warns falsely on chains of string + to_string).
    std::string s(to_string(edit.op));
    s += ' ';
    s += to_string(edit.target);
    s += " at level ";
    s += std::to_string(edit.level());
    s += " (face ";
    s += std::to_string(edit.face);
    if (!edit.children.empty()) {
        s += ", children";
        for (int c : edit.children) {
            s += ' ';
            s += std::to_string(c);
        }
    }
    if (edit.target != EditTarget::Hole) {
        s += edit.target == EditTarget::EdgeSharpness ? ", edge " : ", vertex ";
        s += std::to_string(edit.element);
    }
    s += ')';
    if (edit.line > 0) {
        s += " from line ";
        s += std::to_string(edit.line);
    }
    return s;
}

std::string hierarchical_edit_problem(const HierarchicalEdit& edit, int num_faces, int base_face_size) {
    if (edit.face < 0 || edit.face >= num_faces)
        return "face " + std::to_string(edit.face) + " out of range: tags count from 0 and the mesh has " +
               std::to_string(num_faces) + " faces";
    for (size_t l = 0; l < edit.children.size(); ++l) {
        const int corners = l == 0 ? base_face_size : 4;
        if (edit.children[l] < 0 || edit.children[l] >= corners)
            return "child " + std::to_string(edit.children[l]) + " at level " + std::to_string(l + 1) +
                   " is not one of the parent face's " + std::to_string(corners) + " corners";
    }
    if (edit.target == EditTarget::Hole) {
        if (edit.element != -1) return "a hole names no vertex or edge";
        return "";
    }
    const int corners = edit.children.empty() ? base_face_size : 4;
    if (edit.element < 0 || edit.element >= corners)
        return std::string(edit.target == EditTarget::EdgeSharpness ? "edge " : "vertex ") + std::to_string(edit.element) +
               " is not one of the face's " + std::to_string(corners) + " " +
               (edit.target == EditTarget::EdgeSharpness ? "edges" : "corners");
    return "";
}

}  // namespace crossdiv
