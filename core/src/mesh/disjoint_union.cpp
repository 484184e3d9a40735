#include "crossdiv/mesh/disjoint_union.h"

#include <algorithm>

namespace crossdiv {

PolyMesh disjoint_union(const std::vector<PolyMesh>& parts) {
    PolyMesh out;
    if (parts.empty()) return out;
    const bool colors = std::all_of(parts.begin(), parts.end(), [](const PolyMesh& p) { return !p.colors.empty(); });
    const auto same_channels = [&](const PolyMesh& p) {
        if (p.face_varying.size() != parts[0].face_varying.size()) return false;
        for (size_t ch = 0; ch < p.face_varying.size(); ++ch)
            if (p.face_varying[ch].dimension != parts[0].face_varying[ch].dimension) return false;
        return true;
    };
    if (std::all_of(parts.begin(), parts.end(), same_channels)) {
        out.face_varying = parts[0].face_varying;
        for (FaceVaryingChannel& ch : out.face_varying) {
            ch.values.clear();
            ch.corner_values.clear();
        }
    }
    for (const PolyMesh& p : parts) {
        const int offset = out.num_vertices();
        out.positions.insert(out.positions.end(), p.positions.begin(), p.positions.end());
        if (colors) out.colors.insert(out.colors.end(), p.colors.begin(), p.colors.end());
        for (int v : p.face_vertices) out.face_vertices.push_back(v + offset);
        for (int f = 0; f < p.num_faces(); ++f) out.face_start.push_back(out.face_start.back() + p.face_size(f));
        for (size_t ch = 0; ch < out.face_varying.size(); ++ch) {
            FaceVaryingChannel& into = out.face_varying[ch];
            const int values = into.num_values();
            for (int v : p.face_varying[ch].corner_values) into.corner_values.push_back(v + values);
            into.values.insert(into.values.end(), p.face_varying[ch].values.begin(), p.face_varying[ch].values.end());
        }
    }
    return out;
}

}  // namespace crossdiv
