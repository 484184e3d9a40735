#include "crossdiv/subdiv/hole_faces.h"

#include <algorithm>
#include <utility>

#include "crossdiv/subdiv/crease_mask.h"

namespace crossdiv {

PolyMesh without_hole_faces(const PolyMesh& mesh) {
    PolyMesh out;
    out.positions = mesh.positions;
    out.colors = mesh.colors;
    out.creases = mesh.creases;
    out.creases.holes.clear();
    out.source.file = mesh.source.file;
    out.source.vertex_line = mesh.source.vertex_line;
    out.source.notes = mesh.source.notes;
    for (const FaceVaryingChannel& ch : mesh.face_varying) {
        out.face_varying.push_back(ch);
        out.face_varying.back().corner_values.clear();
    }
    for_each_emitted_face(mesh, [&](int f) {
        out.face_vertices.insert(out.face_vertices.end(), mesh.face(f), mesh.face(f) + mesh.face_size(f));
        for (size_t k = 0; k < mesh.face_varying.size(); ++k) {
            const std::vector<int>& from = mesh.face_varying[k].corner_values;
            out.face_varying[k].corner_values.insert(out.face_varying[k].corner_values.end(),
                                                     from.begin() + mesh.face_start[f], from.begin() + mesh.face_start[f + 1]);
        }
        out.face_start.push_back(static_cast<int>(out.face_vertices.size()));
        if (static_cast<size_t>(f) < mesh.source.face_line.size()) out.source.face_line.push_back(mesh.source.face_line[f]);
    });
    return out;
}

void tag_boundary_faces_as_holes(PolyMesh& mesh, const PolyConnectivity& conn) {
    // Boundary edges the tags make infinitely sharp already: Far leaves their vertices' faces.
    std::vector<std::pair<int, int>> inf_sharp;
    for (const SharpEdge& e : mesh.creases.edges)
        if (is_infinitely_sharp(e.sharpness)) inf_sharp.emplace_back(std::min(e.a, e.b), std::max(e.a, e.b));
    std::sort(inf_sharp.begin(), inf_sharp.end());
    auto smooth_boundary_edge = [&](int a, int b) {
        return !std::binary_search(inf_sharp.begin(), inf_sharp.end(), std::pair{std::min(a, b), std::max(a, b)});
    };
    std::vector<char> hole(static_cast<size_t>(mesh.num_faces()), 0);
    for (int f : mesh.creases.holes) hole[static_cast<size_t>(f)] = 1;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (!conn.is_boundary_vertex(v)) continue;
        const PolyConnectivity::BoundaryNeighbors nb = conn.boundary_neighbors(v);
        if (!smooth_boundary_edge(nb.before, v) && !smooth_boundary_edge(v, nb.after)) continue;
        for (int c = conn.vertex_corner[v]; c >= 0;) {
            hole[static_cast<size_t>(conn.corner_face[c])] = 1;
            c = conn.next_around_vertex(c);
            if (c == conn.vertex_corner[v]) break;
        }
    }
    mesh.creases.holes.clear();
    for (int f = 0; f < mesh.num_faces(); ++f)
        if (hole[static_cast<size_t>(f)]) mesh.creases.holes.push_back(f);
}

}  // namespace crossdiv
