#pragma once
/// @file
/// Where a mesh's elements came from, so that a diagnostic found long after reading
/// ("face 17 is a quad", "vertex 3 is NaN") can still name the file and line.

#include <string>
#include <vector>

namespace crossdiv {

/// Source lines of a mesh's elements. Empty vectors for a mesh generated in code.
struct MeshSource {
    std::string file;              ///< path as given by the user; empty when generated
    std::vector<int> vertex_line;  ///< 1-based line of each vertex, or empty
    std::vector<int> face_line;    ///< 1-based line of each face, or empty
    /// What the reader skipped or assumed, one sentence each with the line (e.g. lines of
    /// HTML around an OBJ saved from a browser, as in the course files).
    std::vector<std::string> notes;
    /// Tags the reader does not know, each as "'name' at file:line": refining without them
    /// would follow other rules than the file states, so the commands that refine refuse
    /// such a mesh unless told to ignore them (--ignore-unknown-tags).
    std::vector<std::string> unknown_tags;

    /// "vertex 12 (bunny.obj:17)" or "vertex 12" when the line is unknown.
    std::string describe_vertex(int v) const { return describe("vertex", v, vertex_line); }
    /// "face 3 (patch.obj:21)" or "face 3" when the line is unknown.
    std::string describe_face(int f) const { return describe("face", f, face_line); }

private:
    std::string describe(const char* kind, int i, const std::vector<int>& lines) const {
        std::string s = std::string(kind) + " " + std::to_string(i);
        if (i >= 0 && static_cast<size_t>(i) < lines.size())
            s += " (" + file + ":" + std::to_string(lines[static_cast<size_t>(i)]) + ")";
        return s;
    }
};

}  // namespace crossdiv
