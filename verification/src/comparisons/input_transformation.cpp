#include "crossdiv/verification/comparisons/input_transformation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "crossdiv/error.h"
#include "crossdiv/verification/comparisons/shrink.h"

namespace crossdiv::verification {
namespace {

constexpr std::pair<InputTransformation, const char*> kNames[] = {
    {InputTransformation::RotateCorners, "rotate-corners"},
    {InputTransformation::RotateCornersRandom, "rotate-corners-random"},
    {InputTransformation::ReverseFaces, "reverse-faces"},
    {InputTransformation::RotateFaces, "rotate-faces"},
    {InputTransformation::ShuffleFaces, "shuffle-faces"},
    {InputTransformation::RelabelVertices, "relabel-vertices"},
    {InputTransformation::ReverseOrientation, "reverse-orientation"},
    {InputTransformation::Translate, "translate"},
    {InputTransformation::Scale, "scale"},
    {InputTransformation::SwapAxes, "swap-axes"},
    {InputTransformation::Mirror, "mirror"},
    {InputTransformation::Rotate, "rotate"},
    {InputTransformation::SplitComponents, "components"},
    {InputTransformation::LevelByLevel, "level-by-level"},
    {InputTransformation::Repeat, "repeat"},
};

/// Each face's corners rotated: face f starts at its corner shift(f) (mod its size); hole tags
/// stay, face-varying corners follow.
PolyMesh with_corners_rotated(const PolyMesh& mesh, const std::function<int(int)>& shift) {
    PolyMesh out = mesh;
    out.derived = {};
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int n = mesh.face_size(f), s = ((shift(f) % n) + n) % n, start = mesh.face_start[f];
        for (int k = 0; k < n; ++k) {
            out.face_vertices[static_cast<size_t>(start + k)] = mesh.face_vertices[static_cast<size_t>(start + (k + s) % n)];
            for (size_t ch = 0; ch < mesh.face_varying.size(); ++ch)
                out.face_varying[ch].corner_values[static_cast<size_t>(start + k)] =
                    mesh.face_varying[ch].corner_values[static_cast<size_t>(start + (k + s) % n)];
        }
    }
    return out;
}

/// Every face's corners in the other order (the first corner stays first).
PolyMesh with_orientation_reversed(const PolyMesh& mesh) {
    PolyMesh out = mesh;
    out.derived = {};
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int n = mesh.face_size(f), start = mesh.face_start[f];
        for (int k = 1; k < n; ++k) {
            out.face_vertices[static_cast<size_t>(start + k)] = mesh.face_vertices[static_cast<size_t>(start + n - k)];
            for (size_t ch = 0; ch < mesh.face_varying.size(); ++ch)
                out.face_varying[ch].corner_values[static_cast<size_t>(start + k)] =
                    mesh.face_varying[ch].corner_values[static_cast<size_t>(start + n - k)];
        }
    }
    return out;
}

/// The vertices renumbered: old vertex v becomes new_index[v]; crease and corner tags follow.
PolyMesh with_vertices_relabelled(const PolyMesh& mesh, const std::vector<int>& new_index) {
    PolyMesh out = mesh;
    out.derived = {};
    for (size_t v = 0; v < new_index.size(); ++v) {
        out.positions[static_cast<size_t>(new_index[v])] = mesh.positions[v];
        if (!mesh.colors.empty()) out.colors[static_cast<size_t>(new_index[v])] = mesh.colors[v];
    }
    for (int& v : out.face_vertices) v = new_index[static_cast<size_t>(v)];
    for (SharpEdge& e : out.creases.edges) {
        e.a = new_index[static_cast<size_t>(e.a)];
        e.b = new_index[static_cast<size_t>(e.b)];
    }
    for (SharpVertex& s : out.creases.vertices) s.v = new_index[static_cast<size_t>(s.v)];
    out.source.vertex_line.clear();
    return out;
}

std::vector<int> permutation(size_t n, std::mt19937_64& rng) {
    std::vector<int> p(n);
    std::iota(p.begin(), p.end(), 0);
    std::shuffle(p.begin(), p.end(), rng);
    return p;
}

}  // namespace

const char* to_string(InputTransformation t) {
    for (const auto& [value, name] : kNames)
        if (value == t) return name;
    return "?";
}

InputTransformation input_transformation_from_string(std::string_view name) {
    std::string known;
    for (const auto& [value, n] : kNames) {
        if (name == n) return value;
        known += (known.empty() ? "" : ", ") + std::string(n);
    }
    throw InputError("unknown transformation '" + std::string(name) + "' (known: " + known + ")");
}

std::vector<PolyMesh> connected_components(const PolyMesh& mesh) {
    // Union-find over the vertices, each face joining its corners.
    std::vector<int> parent(static_cast<size_t>(mesh.num_vertices()));
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&](int x) {
        while (parent[static_cast<size_t>(x)] != x) x = parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
        return x;
    };
    for (int f = 0; f < mesh.num_faces(); ++f)
        for (int k = 1; k < mesh.face_size(f); ++k) parent[static_cast<size_t>(root(mesh.face(f)[k]))] = root(mesh.face(f)[0]);
    // Components numbered by their first face; the faces of each in input order.
    std::vector<int> component_of_root(parent.size(), -1);
    std::vector<std::vector<int>> faces;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        int& c = component_of_root[static_cast<size_t>(root(mesh.face(f)[0]))];
        if (c < 0) {
            c = static_cast<int>(faces.size());
            faces.emplace_back();
        }
        faces[static_cast<size_t>(c)].push_back(f);
    }
    std::vector<int> unused;
    std::vector<char> used(parent.size(), 0);
    for (int v : mesh.face_vertices) used[static_cast<size_t>(v)] = 1;
    for (size_t v = 0; v < used.size(); ++v)
        if (!used[v]) unused.push_back(static_cast<int>(v));
    if (faces.empty()) return {mesh};
    std::vector<PolyMesh> parts;
    parts.reserve(faces.size());
    for (size_t c = 0; c < faces.size(); ++c) parts.push_back(submesh(mesh, faces[c], c == 0 ? unused : std::vector<int>{}));
    return parts;
}

PolyMesh with_face_order(const PolyMesh& mesh, const std::vector<int>& order) {
    PolyMesh out = mesh;
    out.face_start = {0};
    out.face_vertices.clear();
    out.derived = {};
    out.source.face_line.clear();
    for (FaceVaryingChannel& ch : out.face_varying) ch.corner_values.clear();
    std::vector<int> new_index(order.size());
    for (size_t i = 0; i < order.size(); ++i) new_index[static_cast<size_t>(order[i])] = static_cast<int>(i);
    for (int f : order) {
        out.face_vertices.insert(out.face_vertices.end(), mesh.face(f), mesh.face(f) + mesh.face_size(f));
        out.face_start.push_back(static_cast<int>(out.face_vertices.size()));
        for (size_t k = 0; k < mesh.face_varying.size(); ++k) {
            const std::vector<int>& from = mesh.face_varying[k].corner_values;
            out.face_varying[k].corner_values.insert(out.face_varying[k].corner_values.end(), from.begin() + mesh.face_start[f],
                                                     from.begin() + mesh.face_start[f + 1]);
        }
    }
    for (int& h : out.creases.holes) h = new_index[static_cast<size_t>(h)];
    std::sort(out.creases.holes.begin(), out.creases.holes.end());
    return out;
}

TransformedInput transform_input(const PolyMesh& mesh, InputTransformation t, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    TransformedInput out;
    const auto mapped = [&](const Eigen::Matrix3d& linear, const Vec3& offset) {
        out.linear = linear;
        out.offset = offset;
        out.mesh = mesh;
        for (Vec3& p : out.mesh.positions) p = linear * p + offset;
    };
    switch (t) {
        case InputTransformation::RotateCorners: out.mesh = with_corners_rotated(mesh, [](int) { return 1; }); break;
        case InputTransformation::RotateCornersRandom: {
            std::vector<int> shift(static_cast<size_t>(mesh.num_faces()));
            for (int& s : shift) s = static_cast<int>(rng() % 64);
            out.mesh = with_corners_rotated(mesh, [&](int f) { return shift[static_cast<size_t>(f)]; });
            break;
        }
        case InputTransformation::ReverseFaces: {
            std::vector<int> order(static_cast<size_t>(mesh.num_faces()));
            for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(order.size() - 1 - i);
            out.mesh = with_face_order(mesh, order);
            break;
        }
        case InputTransformation::RotateFaces: {
            const size_t n = static_cast<size_t>(mesh.num_faces());
            std::vector<int> order(n);
            for (size_t i = 0; i < n; ++i) order[i] = static_cast<int>((i + n / 2) % n);
            out.mesh = with_face_order(mesh, order);
            break;
        }
        case InputTransformation::ShuffleFaces:
            out.mesh = with_face_order(mesh, permutation(static_cast<size_t>(mesh.num_faces()), rng));
            break;
        case InputTransformation::RelabelVertices:
            out.mesh = with_vertices_relabelled(mesh, permutation(static_cast<size_t>(mesh.num_vertices()), rng));
            break;
        case InputTransformation::ReverseOrientation:
            out.mesh = with_orientation_reversed(mesh);
            out.reversed = true;
            break;
        case InputTransformation::Translate: {
            // A power of two at least the box's largest side: the offset's bits sit above the
            // coordinates' leading ones, so every input coordinate is rounded once at most.
            Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
            for (const Vec3& p : mesh.positions) {
                lo = lo.cwiseMin(p);
                hi = hi.cwiseMax(p);
            }
            const double side = mesh.positions.empty() ? 1.0 : std::max((hi - lo).maxCoeff(), 1e-300);
            mapped(Eigen::Matrix3d::Identity(), Vec3::Constant(std::exp2(std::ceil(std::log2(side)))));
            break;
        }
        case InputTransformation::Scale:
            mapped(2.0 * Eigen::Matrix3d::Identity(), Vec3::Zero());
            out.exact = true;
            break;
        case InputTransformation::SwapAxes: {
            Eigen::Matrix3d swap;
            swap << 0, 1, 0, 1, 0, 0, 0, 0, 1;
            mapped(swap, Vec3::Zero());
            out.exact = true;
            break;
        }
        case InputTransformation::Mirror:
            mapped(Eigen::Vector3d(-1, 1, 1).asDiagonal(), Vec3::Zero());
            out.exact = true;
            break;
        case InputTransformation::Rotate:
            mapped(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix(), Vec3::Zero());
            break;
        case InputTransformation::SplitComponents:
        case InputTransformation::LevelByLevel:
            out.mesh = mesh;
            break;
        case InputTransformation::Repeat:
            out.mesh = mesh;
            out.exact = true;
            break;
    }
    return out;
}

}  // namespace crossdiv::verification
