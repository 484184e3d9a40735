#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numeric>

#include "crossdiv/adapters/assimp.h"
#include "crossdiv/error.h"
#include "crossdiv/io/mesh_io.h"

namespace crossdiv::adapters::assimp {

const std::vector<std::string>& extensions() {
    // Every format this Assimp reads, from its own list ("*.3ds;*.ac;..."), but the ones core
    // reads itself (OBJ with its tags, OFF, PLY: the file's vertex order and binary floats
    // kept exactly).
    static const std::vector<std::string> ext = [] {
        std::string list;
        Assimp::Importer().GetExtensionList(list);
        std::vector<std::string> out;
        for (size_t at = 0; at < list.size();) {
            size_t end = list.find(';', at);
            if (end == std::string::npos) end = list.size();
            std::string e = list.substr(at, end - at);
            at = end + 1;
            if (e.starts_with("*")) e.erase(0, 1);
            std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            const bool core_reads = std::any_of(mesh_extensions().begin(), mesh_extensions().end(),
                                                [&](std::string_view own) { return own == e; });
            if (e.size() > 1 && e[0] == '.' && !core_reads) out.push_back(e);
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());  // a format two importers list is one entry
        return out;
    }();
    return ext;
}

std::string version() {
    return "Assimp " + std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) + "." +
           std::to_string(aiGetVersionPatch());
}

PolyMesh read_mesh(const std::string& path) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_PreTransformVertices);
    if (!scene) throw InputError(path + ": Assimp could not read it: " + importer.GetErrorString());

    // Every face corner with its position and (first channel) texture coordinate, in file order.
    std::vector<std::array<double, 3>> corner_pos, corner_uv;
    std::vector<int> face_start{0};
    long skipped = 0;
    unsigned uv_components = 0;
    int mesh_without_uv = -1;  // the first mesh with polygons and no texture coordinates
    for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
        const aiMesh* mesh = scene->mMeshes[mi];
        const bool has_uv = mesh->HasTextureCoords(0);
        if (has_uv) uv_components = std::max(uv_components, mesh->mNumUVComponents[0]);
        else if (mesh_without_uv < 0 && mesh->mNumFaces > 0) mesh_without_uv = static_cast<int>(mi);
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices < 3) {
                ++skipped;
                continue;
            }
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                const aiVector3D& p = mesh->mVertices[face.mIndices[k]];
                corner_pos.push_back({p.x, p.y, p.z});
                const aiVector3D t = has_uv ? mesh->mTextureCoords[0][face.mIndices[k]] : aiVector3D(0, 0, 0);
                corner_uv.push_back({t.x, t.y, t.z});
            }
            face_start.push_back(static_cast<int>(corner_pos.size()));
        }
    }
    if (face_start.size() == 1)
        throw InputError(path + ": no polygon in the scene (" + std::to_string(scene->mNumMeshes) + " meshes, " +
                         std::to_string(skipped) + " point or line primitives)");

    // Weld corners with identical positions: sort corner indices by position (ties by corner
    // index), so each run is one vertex; number vertices by their first corner.
    const size_t nc = corner_pos.size();
    std::vector<int> order(nc);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return corner_pos[static_cast<size_t>(a)] != corner_pos[static_cast<size_t>(b)] ? corner_pos[static_cast<size_t>(a)] < corner_pos[static_cast<size_t>(b)] : a < b;
    });
    std::vector<int> run_of(nc), run_first;  // run index per corner; first corner per run
    for (size_t i = 0; i < nc; ++i) {
        const int c = order[i];
        if (i == 0 || corner_pos[static_cast<size_t>(c)] != corner_pos[static_cast<size_t>(order[i - 1])]) run_first.push_back(c);
        run_of[static_cast<size_t>(c)] = static_cast<int>(run_first.size()) - 1;
    }
    std::vector<int> runs_by_first(run_first.size());
    std::iota(runs_by_first.begin(), runs_by_first.end(), 0);
    std::sort(runs_by_first.begin(), runs_by_first.end(), [&](int a, int b) { return run_first[static_cast<size_t>(a)] < run_first[static_cast<size_t>(b)]; });
    std::vector<int> vertex_of_run(run_first.size());
    PolyMesh out;
    out.positions.reserve(run_first.size());
    for (size_t v = 0; v < runs_by_first.size(); ++v) {
        const int run = runs_by_first[v];
        vertex_of_run[static_cast<size_t>(run)] = static_cast<int>(v);
        const auto& p = corner_pos[static_cast<size_t>(run_first[static_cast<size_t>(run)])];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw InputError(path + ": vertex " + std::to_string(v) + " has a NaN or infinite coordinate");
        out.positions.emplace_back(p[0], p[1], p[2]);
    }
    out.face_start = std::move(face_start);
    out.face_vertices.resize(nc);
    for (size_t c = 0; c < nc; ++c) out.face_vertices[c] = vertex_of_run[static_cast<size_t>(run_of[c])];
    out.source.file = path;
    out.source.notes.push_back("read with " + version() + ": " + std::to_string(nc) + " face corners welded into " +
                               std::to_string(out.positions.size()) + " vertices by identical position");
    if (uv_components > 0 && mesh_without_uv >= 0) {
        out.source.notes.push_back("texture coordinates not read: mesh " + std::to_string(mesh_without_uv) +
                                   " of the scene has none (a channel is on every corner or on none)");
    } else if (uv_components > 0) {
        // The face-varying channel: corners of one vertex with bit-identical coordinates share a
        // value (Assimp keeps one per corner, so the file's own value indices are gone; equal
        // coordinates at a vertex are the same value, different ones a seam).
        FaceVaryingChannel uv;
        uv.dimension = uv_components >= 3 ? 3 : 2;
        std::vector<int> by_key(nc);
        std::iota(by_key.begin(), by_key.end(), 0);
        const auto key_less = [&](int a, int b) {
            const int va = out.face_vertices[static_cast<size_t>(a)], vb = out.face_vertices[static_cast<size_t>(b)];
            if (va != vb) return va < vb;
            return corner_uv[static_cast<size_t>(a)] != corner_uv[static_cast<size_t>(b)]
                       ? corner_uv[static_cast<size_t>(a)] < corner_uv[static_cast<size_t>(b)]
                       : a < b;
        };
        std::sort(by_key.begin(), by_key.end(), key_less);
        std::vector<int> value_of_corner(nc), first_corner_of_value;
        for (size_t i = 0; i < nc; ++i) {
            const int c = by_key[i], prev = i == 0 ? -1 : by_key[i - 1];
            const bool same = prev >= 0 && out.face_vertices[static_cast<size_t>(prev)] == out.face_vertices[static_cast<size_t>(c)] &&
                              corner_uv[static_cast<size_t>(prev)] == corner_uv[static_cast<size_t>(c)];
            if (!same) first_corner_of_value.push_back(c);
            value_of_corner[static_cast<size_t>(c)] = static_cast<int>(first_corner_of_value.size()) - 1;
        }
        // Values numbered by their first corner in file order, as vertices are.
        std::vector<int> values_by_first(first_corner_of_value.size());
        std::iota(values_by_first.begin(), values_by_first.end(), 0);
        std::sort(values_by_first.begin(), values_by_first.end(), [&](int a, int b) {
            return first_corner_of_value[static_cast<size_t>(a)] < first_corner_of_value[static_cast<size_t>(b)];
        });
        std::vector<int> number(first_corner_of_value.size());
        for (size_t i = 0; i < values_by_first.size(); ++i) {
            const int value = values_by_first[i];
            number[static_cast<size_t>(value)] = static_cast<int>(i);
            const auto& t = corner_uv[static_cast<size_t>(first_corner_of_value[static_cast<size_t>(value)])];
            for (int k = 0; k < uv.dimension; ++k) {
                if (!std::isfinite(t[static_cast<size_t>(k)]))
                    throw InputError(path + ": texture coordinate " + std::to_string(i) + " is NaN or infinite");
                uv.values.push_back(t[static_cast<size_t>(k)]);
            }
        }
        uv.corner_values.resize(nc);
        for (size_t c = 0; c < nc; ++c) uv.corner_values[c] = number[static_cast<size_t>(value_of_corner[c])];
        out.face_varying.push_back(std::move(uv));
    }
    if (skipped) out.source.notes.push_back(std::to_string(skipped) + " point or line primitives skipped");
    return out;
}

}  // namespace crossdiv::adapters::assimp
