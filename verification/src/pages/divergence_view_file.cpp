#include "crossdiv/verification/pages/divergence_view_file.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/mesh/tri_mesh.h"
#include "crossdiv/verification/harness/json_text.h"
#include "crossdiv/verification/pages/page_arrays.h"

namespace crossdiv::verification {
namespace {

/// A pair per vertex: (v, -1) the vertex point of v, (a, b) the edge point of (a, b), (f, -2)
/// the face point of face f.
std::string origins32(const std::vector<VertexBirth>& births) {
    std::vector<int32_t> pairs;
    pairs.reserve(2 * births.size());
    for (const VertexBirth& o : births)
        pairs.insert(pairs.end(), {o.a, o.kind == VertexBirth::Kind::Edge ? o.b : o.kind == VertexBirth::Kind::Face ? -2 : -1});
    return base64(pairs);
}

/// The reference's position minus ours per vertex, in float32 (NaN stays NaN).
std::string offsets32(const std::vector<Vec3>& ref, const PolyMesh& ours) {
    std::vector<float> xyz;
    xyz.reserve(3 * ref.size());
    for (size_t v = 0; v < ref.size(); ++v)
        for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(ref[v][k] - ours.positions[v][k]));
    return base64(xyz);
}

}  // namespace

std::string divergence_view_script(const DivergenceView& view, int job, const std::string& subject) {
    using nlohmann::json;
    json levels = json::array();
    for (size_t l = 0; l < view.levels.size(); ++l) {
        const PolyMesh& m = view.levels[l];
        json level{{"positions", positions64(m)}, {"triangles", triangles32(m)}};
        if (!m.all_triangles()) level["sizes"] = face_sizes32(m);
        if (l >= 1 && l - 1 < view.births.size() && !view.births[l - 1].empty())
            level["origins"] = origins32(view.births[l - 1]);
        if (!m.face_varying.empty()) {
            const FaceVaryingChannel& ch = m.face_varying.front();
            level["uv"] = {{"name", ch.name},
                           {"dimension", ch.dimension},
                           {"values", base64(ch.values)},
                           {"corners", base64(ch.corner_values)}};
        }
        levels.push_back(std::move(level));
    }
    json references = json::object();
    for (const auto& [name, at_level] : view.references) {
        json per_level = json::array();
        for (size_t l = 0; l < view.levels.size(); ++l) {
            const bool mapped = l < at_level.size() && at_level[l].size() == view.levels[l].positions.size() &&
                                !at_level[l].empty();
            per_level.push_back(mapped ? json(offsets32(at_level[l], view.levels[l])) : json(nullptr));
        }
        references[name] = std::move(per_level);
    }
    json data{{"job", job}, {"subject", subject}, {"levels", levels}, {"references", references}};
    if (!view.reference_uvs.empty()) {
        json uvs = json::object();
        for (const auto& [name, values] : view.reference_uvs) uvs[name] = values.empty() ? json(nullptr) : json(base64(values));
        data["reference_uvs"] = std::move(uvs);
        data["uv_worst_corner"] = view.uv_worst_corner;
    }
    if (const auto& m = view.minimal) {
        data["minimal"] = {{"reference", m->reference},     {"symptom", m->symptom},
                           {"tests", m->tests},             {"faces", m->mesh.num_faces()},
                           {"positions", positions64(m->mesh)}, {"triangles", triangles32(m->mesh)},
                           {"reproduce", m->reproduce}};
        if (!m->mesh.all_triangles()) data["minimal"]["sizes"] = face_sizes32(m->mesh);
    }
    return "crossdivView(" + json_text(data) + ");\n";
}

void write_divergence_view(const DivergenceView& view, int job, const std::string& subject, const std::string& path) {
    write_text_file(path, divergence_view_script(view, job, subject));
}

}  // namespace crossdiv::verification
