#include "crossdiv/verification/pages/page_arrays.h"

namespace crossdiv::verification {

std::string base64(const unsigned char* bytes, size_t n) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((n + 2) / 3 * 4);
    for (size_t i = 0; i < n; i += 3) {
        const unsigned b0 = bytes[i], b1 = i + 1 < n ? bytes[i + 1] : 0u, b2 = i + 2 < n ? bytes[i + 2] : 0u;
        const unsigned triple = (b0 << 16) | (b1 << 8) | b2;
        out += kAlphabet[(triple >> 18) & 63];
        out += kAlphabet[(triple >> 12) & 63];
        out += i + 1 < n ? kAlphabet[(triple >> 6) & 63] : '=';
        out += i + 2 < n ? kAlphabet[triple & 63] : '=';
    }
    return out;
}

std::string positions64(const PolyMesh& mesh) {
    std::vector<double> xyz;
    xyz.reserve(3 * mesh.positions.size());
    for (const Vec3& p : mesh.positions) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
    return base64(xyz);
}

std::string face_sizes32(const PolyMesh& mesh) {
    std::vector<int32_t> sizes(static_cast<size_t>(mesh.num_faces()));
    for (int f = 0; f < mesh.num_faces(); ++f) sizes[f] = mesh.face_size(f);
    return base64(sizes);
}

std::string triangles32(const PolyMesh& mesh) {
    std::vector<int32_t> corners;
    for (int f = 0; f < mesh.num_faces(); ++f) {
        const int* v = mesh.face(f);
        for (int k = 1; k + 1 < mesh.face_size(f); ++k) corners.insert(corners.end(), {v[0], v[k], v[k + 1]});
    }
    return base64(corners);
}

std::string edges32(const std::vector<std::array<int, 2>>& edges) {
    std::vector<int32_t> pairs;
    pairs.reserve(2 * edges.size());
    for (const auto& e : edges) pairs.insert(pairs.end(), {e[0], e[1]});
    return base64(pairs);
}

}  // namespace crossdiv::verification
