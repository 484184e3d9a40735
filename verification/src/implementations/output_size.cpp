#include "crossdiv/verification/implementations/output_size.h"

#include <limits>

#include "crossdiv/error.h"

namespace crossdiv::verification {

long long refined_face_count(const PolyMesh& mesh, Scheme scheme, int levels) {
    if (levels <= 0) return mesh.num_faces();
    constexpr long long kMax = std::numeric_limits<long long>::max();
    const long long corners = static_cast<long long>(mesh.face_vertices.size());
    long long faces = scheme == Scheme::CatmullClark || scheme == Scheme::Bilinear ? corners
                      : scheme == Scheme::DooSabin   ? 2 * corners
                      : scheme == Scheme::Sqrt3      ? 3LL * mesh.num_faces()
                                                     : 4LL * mesh.num_faces();
    const long long growth = scheme == Scheme::Sqrt3 ? 3 : 4;
    for (int l = 1; l < levels; ++l) faces = faces > kMax / growth ? kMax : faces * growth;
    return faces;
}

void require_refined_size(long long faces, long long limit, int levels, const std::string& name,
                          const std::string& limit_option) {
    if (faces <= limit) return;
    throw OverSizeLimit(name + ": " + std::to_string(levels) + " levels would produce " + std::to_string(faces) +
                     " faces, over the limit of " + std::to_string(limit) + " (" + limit_option +
                     "); use fewer levels or raise the limit");
}

void require_refined_size(const PolyMesh& mesh, Scheme scheme, int levels, long long limit, const std::string& name,
                          const std::string& limit_option) {
    require_refined_size(refined_face_count(mesh, scheme, levels), limit, levels, name, limit_option);
}

}  // namespace crossdiv::verification
